#!/usr/bin/env bash
# Issue 31 reproducers through the built CLI: special and oversized files, quadratic and unbounded
# work, silent defaults and missing results. Each gives a one-line error with exit 2, a status or a
# documented warning; none exit 3, a signal, a hang or a silent default. The Python side:
# python/tests/test_bounded_input.py; the report step's signals: test_reproduce_signals.py.
# Usage: reliability_cli_test.sh CORLAB_BIN WORKDIR   (registered in tests/CMakeLists.txt)
# SPDX-License-Identifier: BSD-3-Clause
set -uo pipefail
corlab=$1 work=$2
src=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

# limited CMD...: at most 2 GB of address space and 20 s (the issue's probes grew to 5 GB).
limited() { (ulimit -v 2000000 && timeout 20 "$@"); }

# refused PATTERN ARGS...: exit 2, one stderr line matching PATTERN, nothing on stdout.
refused() {
  local pattern=$1; shift
  limited "$corlab" "$@" > "$work/out" 2> "$work/err"
  local rc=$?
  [ $rc -eq 2 ] || fail "$* -> exit $rc, expected 2: $(head -c 400 "$work/err")"
  [ "$(wc -l < "$work/err")" -eq 1 ] || fail "$* -> not one line: $(head -c 400 "$work/err")"
  grep -q -- "^corlab: error: .*$pattern" "$work/err" ||
    fail "$* -> does not match '$pattern': $(head -c 400 "$work/err")"
  [ ! -s "$work/out" ] || fail "$* -> wrote to stdout"
}
special="must be a regular file or a pipe (it is a character device)"

# 1. Special files are refused at once, not read until memory runs out.
refused "spec = '/dev/zero': $special" sweep /dev/zero --out "$work/X"
refused "spec = '/dev/urandom': $special" sweep /dev/urandom --out "$work/X"
refused "results file = '/dev/zero': $special" fit /dev/zero
refused "results file = '/dev/zero': $special" dem --type alumina_ma2023:0.005 \
  --wall aluminium_ma2023 --wall-only --table /dev/zero --out "$work/X"
refused "mesh.file = '/dev/zero': must be a regular file" mesh --set mesh.file=/dev/zero \
  --out "$work/X"
[ ! -e "$work/X" ] || fail "a refused input left an output directory"

# 2. A malformed config is an error, never the default case (it ran e = 0.5886).
refused "config file = '/dev/zero': $special" simulate --config /dev/zero --out "$work/X"
refused "config file = '/dev/urandom': $special" simulate --config /dev/urandom --out "$work/X"
refused "config file = '/dev/zero': $special" mesh --config /dev/zero --out "$work/X"
refused "config file = '$work': must be a regular file or a pipe (it is a directory)" \
  simulate --config "$work" --out "$work/X"
: > "$work/empty.toml"
refused "config file = '$work/empty.toml': must be a TOML file that sets at least one key" \
  simulate --config "$work/empty.toml" --out "$work/X"
printf '[impact]\nvelocity = 5.0\n\xff\n' > "$work/latin1.toml"
refused "config file = '$work/latin1.toml': must be UTF-8 text (line 3: byte 0xff" \
  simulate --config "$work/latin1.toml" --out "$work/X"
head -c 1048577 /dev/zero | tr '\0' '#' > "$work/big.toml"
refused "config file = '$work/big.toml': must be at most 1 MiB long" \
  simulate --config "$work/big.toml" --out "$work/X"
# ... but a pipe or process substitution is read (it was "could not be opened").
limited "$corlab" mesh --config <(printf '[impact]\nvelocity = 2.0\n') --out "$work/piped" \
  > "$work/out" 2> "$work/err" || fail "--config <(...) refused: $(cat "$work/err")"

# 3. A long grid is sized before it is read or expanded; max_runs has a ceiling.
{ printf '[study]\nname = "g"\n[grid]\n"impact.velocity" = ['
  seq -s, 1 1000000
  printf ']\n'; } > "$work/long_grid.toml"
start=$(date +%s)
refused "expands to 1000000 runs, more than \[study\] max_runs = 10000" \
  sweep "$work/long_grid.toml" --out "$work/X" --dry-run
[ $(( $(date +%s) - start )) -le 10 ] || fail "a 10^6-value grid took over 10 s to refuse"
printf '[study]\nname = "g"\nmax_runs = 9765625\n' > "$work/max_runs.toml"
refused "study.max_runs: must be an integer in \[1, 1000000\]" \
  sweep "$work/max_runs.toml" --out "$work/X" --dry-run

# 4. predict: the point cap named; a velocity whose k1 overflows refused.
predict=(predict --model ma2023 --sphere steel_ma2023 --substrate steel_ma2023)
refused "velocity = '0.1:10:100000000': must be at most 1000000 points" "${predict[@]}" \
  --velocity 0.1:10:100000000 --format json
refused "velocity = 1e-300: must be large enough for a finite k1" "${predict[@]}" --velocity 1e-300

# 5. dem --restitution below 2e-3 (an overdamped calibration step) works down to 1e-12.
for e in 1e-3 1e-12; do
  limited "$corlab" dem --type alumina_ma2023:0.005 --wall steel_ma2023 --restitution $e \
    --out "$work/dem$e" > "$work/out" 2> "$work/err" || fail "dem --restitution $e: $(cat "$work/err")"
  grep -q "damping tsuji" "$work/dem$e/lammps.in" || fail "dem --restitution $e: no lammps.in"
done

# 6. A non-UTF-8 byte in a results table is refused by `fit` with and without --json.
printf 'case_id,status,e,velocity\nc1,fa\xffiled,0.5,1\n' > "$work/latin1.csv"
refused "results file = '$work/latin1.csv': must be UTF-8 text (line 2" fit "$work/latin1.csv"
refused "results file = '$work/latin1.csv': must be UTF-8 text (line 2" fit "$work/latin1.csv" --json

# 7. An inline material gives E, nu and rho (nu became 0; a missing E read "= 0: must be > 0").
refused "sphere.material = 'E=200e9,rho=7800': must be a database name or an inline material with \
E, nu and rho (it lacks nu" simulate --set sphere.material=E=200e9,rho=7800 --out "$work/X"
refused "sphere = 'E=370e9,rho=3958': .*(it lacks nu" predict --model ma2023 \
  --sphere E=370e9,rho=3958 --substrate steel_ma2023 --velocity 1
refused "substrate = 'nu=0.3,sy=1e8': .*(it lacks E, rho" predict --model ma2023 \
  --sphere steel_ma2023 --substrate nu=0.3,sy=1e8 --velocity 1

# 8. --error-estimate without its error bar says why (it was silent), in summary.json too.
tiny=(--set sphere.radius=2.5e-3 --set substrate.radius=2.5e-3 --set substrate.depth=2.5e-3
      --set mesh.h_min=0.125e-3 --set mesh.h_max=1e-3 --set mesh.contact_elements=0)
limited "$corlab" simulate "${tiny[@]}" --error-estimate --quiet \
  --out "$work/ee" > "$work/out" 2> "$work/err" || fail "error estimate run: $(cat "$work/err")"
grep -q "^corlab simulate: warning: no error bar: no companion mesh at 1.41h: " "$work/err" ||
  fail "no reason for the missing error bar: $(cat "$work/err")"
grep -q '"e_error_reason": "no companion mesh at 1.41h: ' "$work/ee/summary.json" ||
  fail "summary.json has no e_error_reason"
if limited "$corlab" simulate --set mesh.file="$src/data/meshes/example_impact.msh" --error-estimate \
    --quiet --out "$work/ef" > "$work/out" 2> "$work/err"; then
  grep -q "^corlab simulate: warning: no error bar: mesh.file is set: the estimate coarsens only \
the built-in mesh$" "$work/err" || fail "no reason for mesh.file: $(cat "$work/err")"
else  # a build without Gmsh refuses the mesh file itself
  grep -q "gmsh" "$work/err" || fail "mesh.file run: $(cat "$work/err")"
fi
# in a sweep: the reason column (the error bar columns were nan beside an empty error column)
printf '[study]\nname = "ee"\n[base]\n' > "$work/ee.toml"
for ((i = 0; i < ${#tiny[@]}; i += 2)); do
  printf '"%s" = %s\n' "${tiny[i+1]%%=*}" "${tiny[i+1]#*=}" >> "$work/ee.toml"
done
printf '[grid]\n"impact.velocity" = [2.0]\n' >> "$work/ee.toml"
limited "$corlab" sweep "$work/ee.toml" --out "$work/ee_sweep" --error-estimate --quiet \
  > "$work/out" 2> "$work/err" || fail "error-estimate sweep: $(cat "$work/err")"
head -1 "$work/ee_sweep/results.csv" | grep -q ",e_error_reason," || fail "no e_error_reason column"
grep -q ",no companion mesh at 1.41h: " "$work/ee_sweep/results.csv" || fail "no reason in the row"

# 10. The elastic particle pair of the README's old dem example is refused with the ways out.
refused "pair 1-1 (alumina_ma2023-alumina_ma2023) = .*--pair alumina_ma2023/alumina_ma2023=E.*--wall-only" \
  dem --type alumina_ma2023:0.005 --wall aluminium_ma2023 --model thornton1997 --out "$work/X"

# 11. Hardening >= E is refused on an elastic body too; a long unknown material name is cut and
# named by its key; output times after the run's end are warned about; an interrupted run prints
# no "100.0 %".
refused "sphere.hardening = 300000000000: must be < sphere.E = 2.1e.11 \[Pa\]$" \
  simulate --set sphere.hardening=300e9 --out "$work/X"
head -c 100000 /dev/zero | tr '\0' 'x' > "$work/name"
printf '[sphere]\nmaterial = "%s"\n' "$(cat "$work/name")" > "$work/long_name.toml"
refused "sphere.material = 'x\{160\}\.\.\. (100000 bytes)': must be one of" \
  simulate --config "$work/long_name.toml" --out "$work/X"
[ "$(wc -c < "$work/err")" -lt 1000 ] || fail "the long material name is echoed whole"
limited "$corlab" simulate "${tiny[@]}" --set output.times=2.5e-5,3e-5,1 --quiet \
  --out "$work/late" > "$work/out" 2> "$work/err" || fail "output.times run: $(cat "$work/err")"
grep -q "^corlab simulate: warning: output.times 1 s (1 of 3) after the run's end at .* s: no \
field file for it$" "$work/err" || fail "no warning for a late output time: $(cat "$work/err")"
[ "$(ls "$work/late"/fields_*.vtu | wc -l)" -eq 2 ] || fail "not 2 field files"
limited "$corlab" simulate "${tiny[@]}" --set output.times=1e-5,3e-5 --quiet \
  --out "$work/early" > "$work/out" 2> "$work/err" || fail "output.times run: $(cat "$work/err")"
grep -q "^corlab simulate: warning: output.times 1e-05 s (1 of 2) before the run's start at \
2e-05 s (gap / normal speed): the first step's field file stands for it$" "$work/err" ||
  fail "no warning for an early output time: $(cat "$work/err")"
"$corlab" simulate --set mesh.h_min=0.1e-3 --out "$work/sim" 2> "$work/sim.err" &
pid=$!
sleep 1
kill -TERM $pid
wait $pid
rc=$?
[ $rc -eq 143 ] || fail "simulate SIGTERM: exit $rc"
if grep -q "100.0 %" "$work/sim.err"; then fail "an interrupted run printed 100.0 %"; fi
echo "reliability_cli_test: ok"
