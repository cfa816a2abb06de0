#!/usr/bin/env bash
# Issue 39 item 3: a plain oblique command runs at the 3-D model's default resolution
# (hex_resolution.hpp). The plain Kharaz command (alumina on glass, 40 deg, mu 0.092) gets a mesh
# at a/4 (checked on `corlab mesh`: the run itself takes minutes); a cheaper plain pair (the
# rigid flat) runs end to end and says in summary.json that the model chose its mesh; a case
# with no feasible default names the key and value to set; a set key is still obeyed.
# Usage: default_3d_mesh_cli_test.sh CORLAB_BIN WORKDIR   (registered in tests/CMakeLists.txt)
# SPDX-License-Identifier: BSD-3-Clause
set -uo pipefail
corlab=$1 work=$2
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

kharaz=(--set sphere.material=E=380e9,nu=0.23,rho=4000 --set sphere.radius=2.5e-3
        --set substrate.material=E=70e9,nu=0.25,rho=2500 --set impact.velocity=3.9
        --set solver.model=3d --set impact.angle=40 --set contact.friction=0.092)

# contact_elements ARGS...: a / h of `corlab mesh` (the zone radius is refine_factor 1.5 a).
contact_elements() {
  "$corlab" mesh "$@" --out "$work/mesh" > "$work/mesh.out" 2> "$work/mesh.err" \
    || fail "corlab mesh $* -> $(cat "$work/mesh.err")"
  awk '/^3-D model:/ { printf "%.2f\n", $8 / 1.5 / $4 }' "$work/mesh.out"
}

n=$(contact_elements "${kharaz[@]}")
[ "$n" = "4.00" ] || fail "plain Kharaz command: a/h = $n, expected the default 4"
# The default block (issue 39): 0.14 c_p t_c = 11 mm with the viscous-spring boundary, 97,153
# elements where the 70 mm block had 224,098; graded by the model's growth 1.25 (item 4):
# 40,039.
total=$(awk '/^total/ { print $3 }' "$work/mesh.out")
[ "$total" -lt 45000 ] || fail "plain Kharaz command: $total elements, expected the default block and grading's < 45000"
grep -q "growth 1.25 " "$work/mesh.out" || fail "plain Kharaz command: not the model's growth 1.25: $(grep '^3-D model' "$work/mesh.out")"
n=$(contact_elements "${kharaz[@]}" --set mesh.contact_elements=3)
[ "$n" = "3.00" ] || fail "mesh.contact_elements = 3: a/h = $n, expected 3"

# No default fits: a 0.5 m block would need h >= 0.25 mm, coarser than a/3 of the 0.19 mm contact.
timeout 20 "$corlab" simulate "${kharaz[@]}" --set substrate.radius=0.5 --set substrate.depth=0.5 \
  --out "$work/none" --quiet > "$work/out" 2> "$work/err"
rc=$?
[ $rc -eq 2 ] || fail "no feasible default -> exit $rc, expected 2: $(cat "$work/err")"
[ "$(wc -l < "$work/err")" -eq 1 ] || fail "no feasible default: not one line: $(cat "$work/err")"
grep -q "^corlab: error: invalid mesh.contact_elements = default: .*set substrate.radius and substrate.depth <= 0.123 m" \
  "$work/err" || fail "no feasible default does not name the keys to set: $(cat "$work/err")"
# ... and where a coarser contact_elements fits, that key and value.
timeout 20 "$corlab" simulate "${kharaz[@]}" --set substrate.radius=0.16 --set substrate.depth=0.16 \
  --out "$work/none" --quiet > "$work/out" 2> "$work/err"
[ $? -eq 2 ] || fail "a 0.16 m block -> not exit 2: $(cat "$work/err")"
grep -q "set mesh.contact_elements = 2.3 " "$work/err" \
  || fail "a 0.16 m block does not name mesh.contact_elements = 2.3: $(cat "$work/err")"

# A cheaper plain pair end to end: the paper's sphere at 40 deg on the rigid flat.
timeout 250 "$corlab" simulate --set solver.model=3d --set impact.angle=40 --set contact.friction=0.1 \
  --set substrate.shape=rigid --out "$work/rigid" --quiet > "$work/out" 2> "$work/err" \
  || fail "plain rigid-flat oblique run failed: $(cat "$work/err")"
summary="$work/rigid/summary.json"
grep -q '"mesh_choice": "model"' "$summary" || fail "summary.json: mesh_choice is not model"
grep -q '"mesh_reason": "model default: h = .* 4 elements across the predicted contact radius' \
  "$summary" || fail "summary.json: no mesh_reason with a/4: $(grep mesh_reason "$summary")"
grep -q '"elements": 25856' "$summary" || fail "summary.json: elements $(grep '"elements"' "$summary")"
grep -q '"status": "separated"' "$summary" || fail "plain rigid-flat run did not separate"
echo "default 3-D mesh: all checks passed"
