#!/usr/bin/env bash
# Issue 12 reproducers through the built CLI: every bad input gives exit 2 and exactly one
# "corlab: error: invalid <field> ..." line on stderr (nothing crashes, hangs or prints NaN);
# the parser library's own errors too; predict warns outside a model's calibration; progress off a
# terminal has no carriage returns.
# Usage: input_cli_test.sh CORLAB_BIN WORKDIR   (registered in tests/CMakeLists.txt)
# SPDX-License-Identifier: BSD-3-Clause
set -uo pipefail
corlab=$1 work=$2
rm -rf "$work" && mkdir -p "$work"
# shellcheck source=../support/cli_refused.sh
. "$(dirname "$0")/../support/cli_refused.sh"
# refused FIELD ARGS...: this script's fields are patterns ("impact.gap = 1e+20" and the like):
# exit 2, one "corlab: error: ...FIELD" line on stderr, nothing on stdout, within 20 s.
refused() { refused_re "$@"; }
sim() { refused "$1" simulate "${@:2}" --out "$work/sim" --quiet; }

sim "impact.gap = 1e+20" --set impact.gap=1e20 --set mesh.h_min=1.5e-3 --set mesh.contact_elements=0
sim "impact.gap = 1000000000000000" --set impact.gap=1e15
sim "impact.gap = 10000000000" --set impact.gap=1e10
sim "impact.gap = 1000000000000" --set impact.gap=1e12
sim "sphere.E = 2.1e+17" --set sphere.E=2.1e17
sim "substrate.E = 2.1e+17" --set substrate.E=2.1e17
sim "substrate.rho = 1e+308" --set substrate.rho=1e308
sim "substrate.rho = 0.001" --set substrate.rho=1e-3
sim "sphere.rho = 1e+308" --set sphere.rho=1e308
sim "solver.hourglass = 1e+308" --set solver.hourglass=1e308
sim "solver.hourglass = 10" --set solver.hourglass=10
sim "solver.bulk_viscosity_quadratic = 1e+308" --set solver.bulk_viscosity_quadratic=1e308
sim "impact.velocity = 1e+308" --set impact.velocity=1e308
sim "impact.velocity = 1000" --set impact.velocity=1000
sim "impact.velocity = 5000" --set impact.velocity=5000
sim "impact.velocity = 500" --set impact.velocity=500 --set substrate.sigma_y=100e6
sim "solver.penalty_scale = 1" --set solver.penalty_scale=1.0 --set solver.safety_factor=1.0
sim "solver.penalty_scale = 0.001" --set solver.penalty_scale=1e-3
sim "impact.velocity = 5" --set substrate.E=1e6 --set substrate.sigma_y=1e4
sim "substrate.radius = 0.002" --set substrate.radius=2e-3
sim "solver.t_max = 1e-06" --set solver.t_max=1e-6
sim "sphere.radius = '0b101'" --set sphere.radius=0b101
sim "sphere.sigma_y = 50" --set sphere.sigma_y=50
sim "substrate.sigma_y = ''" --set substrate.sigma_y=
sim "impact.velocity = '\[5.0\]'" --set impact.velocity=[5.0]
sim "--set impact.velocity = '3'" --set impact.velocity=2 --set impact.velocity=3
sim "sphere.E = '2e9'" --set sphere.material=E=1e9,E=2e9,nu=0.3,rho=1000
sim "solver.max_steps = 20000000" --set substrate.nu=0.4999999
sim "mesh.h_min = 0.00025: the mesh it gives is refused" --set sphere.radius=2.5e-3 \
  --set substrate.radius=2.5e-3 --set substrate.depth=2.5e-3 --set mesh.contact_elements=0
printf '[impact]\nvelocity = [5.0]\n' > "$work/array.toml"
sim "impact.velocity = 'an array'" --config "$work/array.toml"
printf '[impact]\nvelocity = 5.0\nvelocity = 6.0\n' > "$work/dup.toml"
sim "dup.toml" --config "$work/dup.toml"
printf '[sphere]\nradius = 0b101\n' > "$work/radius.toml"
sim "sphere.radius = 5" --config "$work/radius.toml"
# The hot loops' instruction set (simd_level.hpp): an unknown $CORLAB_SIMD is refused before any
# output, by each command that runs the solver.
CORLAB_SIMD=avx9 refused "CORLAB_SIMD = 'avx9'" simulate --out "$work/simd" --quiet
[ ! -e "$work/simd" ] || fail "a bad CORLAB_SIMD left an output directory"
CORLAB_SIMD=avx9 refused "CORLAB_SIMD" sweep "$(dirname "$0")/../data/sweeps/tiny.toml" --out "$work/sw"
CORLAB_SIMD=avx9 refused "CORLAB_SIMD" reproduce --preset coarse --out "$work/rp" --no-report

# The parser library's own errors: one line, exit 2.
refused "not expected: --bogus" simulate --bogus --out "$work/sim"
refused "--out is required" simulate
refused "subcommand" frobnicate
refused "--velocity" predict --model ma2023 --sphere steel_ma2023 --substrate steel_ma2023
# The dataset commands and the sweep's case selection.
refused "--points = 0" dataset design --points 0
refused "spec = .*nowhere/spec.toml" dataset export "$work/nowhere"
refused "--only = '3-x'" sweep "$(dirname "$0")/../data/sweeps/tiny.toml" --out "$work/sw" --only 3-x
refused "--only = '99'" sweep "$(dirname "$0")/../data/sweeps/tiny.toml" --out "$work/sw" --only 99

# A valid run is still accepted; its progress off a terminal is plain lines (no '\r').
"$corlab" simulate --set sphere.radius=2.5e-3 --set substrate.radius=2.5e-3 \
  --set substrate.depth=2.5e-3 --set mesh.h_min=0.125e-3 --set mesh.h_max=1e-3 \
  --set mesh.contact_elements=0 --out "$work/ok" > "$work/ok.out" 2> "$work/ok.err" ||
  fail "valid run failed: $(cat "$work/ok.err")"
grep -q "corlab simulate: 100.0 %" "$work/ok.err" || fail "no final progress line"
if grep -q $'\r' "$work/ok.err"; then fail "carriage return in progress written to a file"; fi

# A run cut by t_max during contact: exit 4, its status printed and in summary.json, no e.
"$corlab" simulate --set sphere.radius=2.5e-3 --set substrate.radius=2.5e-3 \
  --set substrate.depth=2.5e-3 --set mesh.h_min=0.125e-3 --set mesh.h_max=1e-3 \
  --set mesh.contact_elements=0 --set solver.t_max=2.5e-5 --quiet --out "$work/cut" \
  > "$work/cut.out" 2> "$work/cut.err"
rc=$?
[ $rc -eq 4 ] || fail "run cut by t_max -> exit $rc, expected 4: $(cat "$work/cut.err")"
grep -q "^status = not_separated" "$work/cut.out" || fail "no status line: $(cat "$work/cut.out")"
grep -q '"status": "not_separated"' "$work/cut/summary.json" || fail "summary.json has no status"
grep -q '"e": null' "$work/cut/summary.json" || fail "summary.json reports an e for a cut run"

# predict outside a model's calibration: a warning on stderr, the numbers on stdout, exit 0.
"$corlab" predict --model ma2023 --sphere steel_ma2023 --substrate steel_ma2023 --velocity 1e6 \
  > "$work/p.out" 2> "$work/p.err" || fail "predict failed"
grep -q "warning: model 'ma2023': velocity 1e+06 m/s is beyond 1000 m/s" "$work/p.err" || fail "no speed warning"
grep -q "warning: model 'ma2023' extrapolates" "$work/p.err" || fail "no calibration warning"
"$corlab" predict --model ma2023 --sphere steel_ma2023 --substrate steel_ma2023 --velocity 5 \
  > "$work/p.out" 2> "$work/p.err" || fail "predict failed"
[ ! -s "$work/p.err" ] || fail "warning inside the calibration: $(cat "$work/p.err")"
echo "PASS"
