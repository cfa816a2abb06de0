#!/usr/bin/env python3
"""Real-code check of `corlab dem` exports in LIGGGHTS 3.8 (Debian's `liggghts`, never mocked).

Same cases and bounds as dem_lammps_check.py (dem_check_common.py), with liggghts.in at its
recommended step: model hertz (constant e per type pair) or thornton_ning (fitted yield ratio per
type), whichever the export chose; e within 1e-3 of that law's e and within the stated max |de|
+ 1e-3 of the target.
usage: dem_liggghts_check.py CORLAB_BIN LIGGGHTS_BIN WORK_DIR [--report FILE]
"""
# SPDX-License-Identifier: BSD-3-Clause
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dem_check_common import case_rows, finish, parse_e, run  # noqa: E402


def liggghts_input(fragment, drop):
    r, v = drop.radius, drop.v
    text = open(fragment).read()
    # the particle types, then one per wall material, as the fragment's header says
    ntypes = int(re.search(r"create_box N\s*(?:#\s*)?with N = (\d+)", text).group(1))
    lines = ["atom_style granular", "atom_modify map array", "boundary f f f", "newton off",
             "communicate single vel yes", "units si", "hard_particles yes",
             "region reg block -%g %g -%g %g -%g %g units box"
             % ((8 * r,) * 4 + (0.001 * r, 8 * r)),
             "create_box %d reg" % ntypes, "include %s" % fragment]
    if drop.geometry == "wall":
        lines += ["create_atoms %d single 0 0 %.12g units box"
                  % (drop.types[0], drop.radii[0] + drop.gap)]
    else:
        lines += ["unfix %s" % line.split()[1] for line in text.splitlines()
                  if line.startswith("fix corlab_wall")]
        x = (-(drop.radii[0] + drop.gap / 2), drop.radii[1] + drop.gap / 2)
        lines += ["create_atoms %d single %.12g 0 %.12g units box" % (t, xt, 4 * r)
                  for t, xt in zip(drop.types, x)]
    lines += ["set atom %d diameter %.12g density %.12g" % (k + 1, 2 * radius, density)
              for k, (radius, density) in enumerate(zip(drop.radii, drop.densities))]
    if drop.geometry == "wall":
        lines += ["velocity all set %.12g 0 %.12g units box" % (drop.vt, -v)]
    else:
        lines += ["set atom %d vx %.12g" % (k + 1, u) for k, u in enumerate(drop.velocities)]
    lines += ["fix corlab_nve all nve/sphere", "timestep %.12g" % drop.dt, "run %d" % drop.steps]
    if drop.geometry == "wall":
        lines += ["variable e equal vz[1]/%.17g" % v]
    else:
        lines += ["variable e equal (vx[2]-vx[1])/%.17g" % v]
    return "\n".join(lines + ['print "CORLAB_E ${e}"']) + "\n"


def simulator(liggghts):
    def simulate(out, fragment, drop):
        path = os.path.join(out, "in.%s_%s_%g_%g" % (fragment, drop.geometry, drop.v, drop.dt))
        with open(path, "w") as f:
            f.write(liggghts_input(os.path.join(out, fragment), drop))
        return parse_e(run([liggghts, "-in", path, "-log", "none", "-echo", "none"],
                           cwd=out).stdout)
    return simulate


def main():
    corlab, liggghts, work = sys.argv[1:4]
    report = sys.argv[sys.argv.index("--report") + 1] if "--report" in sys.argv else None
    os.makedirs(work, exist_ok=True)
    rows, failures, _ = case_rows(corlab, work, "liggghts", simulator(liggghts),
                                  (("liggghts.in", "liggghts"),), lambda key: key)
    return finish("dem_liggghts_check", rows, failures, report)


if __name__ == "__main__":
    sys.exit(main())
