#!/usr/bin/env bash
# Issue 42 reproducers through the built CLI (analytic models, work caps, sweeps): each ends in
# one "corlab: error:" line with exit 2, or a stated warning, within seconds; never NaN or inf.
# Usage: contract_cli_test.sh CORLAB_BIN WORKDIR   (registered in tests/CMakeLists.txt)
# SPDX-License-Identifier: BSD-3-Clause
set -uo pipefail
corlab=$1 work=$2
rm -rf "$work" && mkdir -p "$work"
# shellcheck source=../support/cli_refused.sh
. "$(dirname "$0")/../support/cli_refused.sh"
pair=(--sphere alumina_ma2023 --substrate aluminium_ma2023)

# predict: every listed speed is checked; speeds from the speed of light on and radii outside
# [1e-9, 1000] m are refused; no NaN or inf in any output.
refused "invalid velocity = 1e-300: must be large enough for a finite k1" \
  predict --model jg2 "${pair[@]}" --velocity 5,1e-300
for model in corlab2026 corlab2026p; do
  refused "invalid velocity = 1e+307: must be < 2.99792e+08 [m/s]" \
    predict --model "$model" "${pair[@]}" --velocity 1e307
done
refused "invalid radius = 1e-300: must be in [1e-09, 1000] [m]" \
  predict --model jg2 "${pair[@]}" --velocity 5 --radius 1e-300
refused "invalid radius = 1e+300" predict --model jg2 "${pair[@]}" --velocity 5 --radius 1e300
for ratio in 5 1e6 1e200; do
  timeout 20 "$corlab" predict --model all "${pair[@]}" --velocity 5 --radius-ratio "$ratio" \
    > "$work/out" 2> "$work/err" || fail "--radius-ratio $ratio -> exit $?: $(cat "$work/err")"
  ! grep -qiE "nan|inf" "$work/out" || fail "--radius-ratio $ratio -> NaN or inf: $(cat "$work/out")"
  grep -q "model 'corlab2026p' extrapolates: radius_ratio = R1/R2 = $ratio" "$work/err" ||
    grep -q "model 'corlab2026p' extrapolates: radius_ratio = R1/R2 = 1e+" "$work/err" ||
    fail "--radius-ratio $ratio -> no warning: $(cat "$work/err")"
done

# simulate: the work caps refuse before meshing (a 10 m second sphere meshed 2.8 M elements and
# ran past 20 min); h_max below h_min is refused in 3-D too; a second sphere's depth is unused.
sim() { refused "$1" simulate "${@:2}" --out "$work/sim" --quiet; }
sim "invalid solver.max_elements = 2e+06: must be >= the element count estimated before meshing" \
  --set substrate.shape=sphere --set substrate.radius=10
sim "or raise solver.max_element_steps to run it" --set solver.max_element_steps=1e6
sim "invalid mesh.h_max = 1e-05: must be >= mesh.h_min" --set solver.model=3d --set mesh.h_max=1e-5
sim "invalid solver.t_max" --set substrate.shape=sphere --set substrate.depth=1e-5 \
  --set solver.t_max=1e-9

# sweeps: keys valid together are accepted in one case or grid; runs that resolve to the same
# configuration are refused.
printf '[study]\nname = "t"\n[base]\n"mesh.h_min" = 1e-3\n"solver.model" = "3d"\n[grid]\n"impact.angle" = [30, 45]\n"contact.friction" = [0.2, 0.5]\n' > "$work/angle.toml"
"$corlab" sweep "$work/angle.toml" --out "$work/sw" --dry-run > "$work/out" 2> "$work/err" ||
  fail "angle with friction in a grid refused: $(cat "$work/err")"
printf '[study]\nname = "t"\n[[cases]]\n"impact.velocity" = 5\n[[cases]]\n"impact.velocity" = " 5"\n' > "$work/same.toml"
refused "resolve to the same configuration" sweep "$work/same.toml" --out "$work/sw" --dry-run
# A value a run does not have (e_t of a normal impact, k2 and sigma_y of an elastic flat, the
# error bars without --error-estimate) is an empty cell in results.csv and null in summary.json,
# never "nan"; the console says so in words.
printf '[study]\nname = "t"\n[base]\n"mesh.h_min" = 1.5e-3\n"mesh.contact_elements" = 0\n[[cases]]\n"solver.model" = "3d"\n"substrate.shape" = "rigid"\n[[cases]]\n"substrate.sigma_y" = "none"\n"impact.velocity" = 1\n' > "$work/none.toml"
timeout 300 "$corlab" sweep "$work/none.toml" --out "$work/none" --quiet > "$work/out" 2> "$work/err" ||
  fail "sweep of values a run lacks -> exit $?: $(cat "$work/err")"
[ "$(grep -c ',ok,' "$work/none/results.csv")" = 2 ] || fail "not two clean runs: $(cat "$work/none/results.csv")"
! grep -qiwE "nan|inf" "$work/none/results.csv" || fail "nan or inf in results.csv: $(cat "$work/none/results.csv")"
timeout 120 "$corlab" simulate --set solver.model=3d --set substrate.shape=rigid --set mesh.h_min=1.5e-3 \
  --set mesh.contact_elements=0 --out "$work/normal3d" --quiet > "$work/out" 2> "$work/err" ||
  fail "3-D normal impact -> exit $?: $(cat "$work/err")"
grep -q "e_t = none (normal impact)" "$work/out" || fail "3-D normal impact e_t: $(cat "$work/out")"
! grep -qiwE "nan|inf" "$work/out" "$work/normal3d/summary.json" ||
  fail "nan or inf in a 3-D normal impact's output: $(cat "$work/out")"
echo "contract_cli_test: all passed"
