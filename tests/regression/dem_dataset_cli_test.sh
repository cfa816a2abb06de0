#!/usr/bin/env bash
# Issue 42 reproducers of `corlab dem` and `corlab dataset design` through the built CLI: each ends
# in exit 2 with one "corlab: error: invalid <field> ..." line (never exit 3, a long run or a
# silently misplaced value), and a spec path holding a line break and a [grid] stays a comment.
# Usage: dem_dataset_cli_test.sh CORLAB_BIN WORKDIR   (registered in tests/CMakeLists.txt)
# SPDX-License-Identifier: BSD-3-Clause
set -uo pipefail
corlab=$1 work=$2
rm -rf "$work" && mkdir -p "$work"
# shellcheck source=../support/cli_refused.sh
. "$(dirname "$0")/../support/cli_refused.sh"

A="A=E=70e9,nu=0.3,rho=2700,sy=1e8"
B="B=E=200e9,nu=0.3,rho=7800"
dem() { refused "$1" dem "${@:2}"; }

# --out that cannot be a directory: exit 3 (filesystem_error) before
touch "$work/a_file"
for out in "$work/a_file" /dev/null /proc/x; do
  dem "invalid --out = '$out': must be a directory that can be made" --type "$A:0.001" \
    --restitution 0.5 --out "$out"
done
# table rows: -1 was exit 3 (vector larger than max_size), 0 an empty table with exit 0, 1 a NaN,
# 1e6 minutes of work
for n in -1 0 1 10001 1000000; do
  dem "invalid table-points = $n: must be in [2, 10000]" --type "$A:0.001" --restitution 0.5 \
    --table-points "$n" --out "$work/dem"
done
# labels that read as type ids, a wall label equal to a type's, wall/wall, a pair named twice
dem "invalid type label = '2'" --type "2=E=70e9,nu=0.3,rho=2700:0.001" \
  --type "1=E=70e9,nu=0.3,rho=2700:0.002" --restitution 0.5 --pair 1/1=0.3 --out "$work/dem"
dem "invalid wall label = 'al'" --type "al=E=70e9,nu=0.3,rho=2700:0.001" \
  --wall "al=E=200e9,nu=0.3,rho=7800" --restitution 0.5 --pair al/al=0.5 --out "$work/dem"
dem "invalid pair = 'wall/wall'" --type "$A:0.001" --wall "$B" --restitution 0.5 \
  --pair wall/wall=0.3 --out "$work/dem"
dem "invalid pair = 'A/A=0.4': must be a pair that no other --pair" --type "$A:0.001" \
  --restitution 0.5 --pair A/A=0.3 --pair A/A=0.4 --out "$work/dem"
# messages that named the wrong field: effective_mass for a tiny radius, restitution for a model
# above 1
dem "invalid type 1 (A) radius = 1e-300: must be in [1e-09, 1000] [m]" --type "$A:1e-300" \
  --restitution 0.5 --out "$work/dem"
dem "wu2003 (aluminium_ma2023 on aluminium_ma2023) gives it at v = 0.316228 m/s" \
  --type aluminium_ma2023:0.005 --wall aluminium_ma2023 --wall-only --model wu2003 \
  --out "$work/dem"
[ ! -e "$work/dem" ] || fail "a refused export left $work/dem"

# dataset design --points: -1 and 2^64-1 were exit 3 (bad_alloc); the cap is the sweep's run cap
for n in -1 0 18446744073709551615 1000001; do
  refused "invalid --points" dataset design --points "$n"
done
refused "--points" dataset design --points 1e12

# A spec path with a line break and a [grid]: the sweep runs the design's 2 cases, not 6.
spec="$work/x
[grid]
\"impact.velocity\" = [1.0, 2.0, 3.0]
#.toml"
"$corlab" dataset design --points 2 --out "$spec" 2> /dev/null || fail "design --out with a newline"
grep -q '^\[grid\]' "$spec" && fail "the path's [grid] is a line of the spec"
"$corlab" sweep "$spec" --dry-run > "$work/cases" 2> "$work/err" || fail "sweep: $(cat "$work/err")"
grep -q ": 2 cases (dry run" "$work/err" || fail "the injected grid runs: $(cat "$work/err")"
echo "dem_dataset_cli_test: OK"
