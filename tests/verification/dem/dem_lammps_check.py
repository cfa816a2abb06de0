#!/usr/bin/env python3
"""Real-code check of `corlab dem` exports in LAMMPS (Debian's `lmp`, never mocked).

Each case's export is wrapped in a minimal input (one sphere hitting the fix wall/gran plane
z = 0, or two spheres of the pair's types head-on; no gravity, so e is the contact's alone) and
run at the export's recommended time step, both lammps.in (e(v) through the python/invoke hook) and
lammps_nopython.in: e must be within the time-step error (1e-3) of the law the fragment runs, and
within the fragment's stated max |de| + 1e-3 of the target. Cases: dem_check_common.py.
usage: dem_lammps_check.py CORLAB_BIN LMP_BIN WORK_DIR [--report FILE]
"""
# SPDX-License-Identifier: BSD-3-Clause
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dem_check_common import case_rows, finish, parse_e, run  # noqa: E402


def lammps_input(fragment, drop):
    r, v, dt = drop.radius, drop.v, drop.dt
    lines = ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f",
             "comm_modify vel yes", "region box block -%g %g -%g %g -%g %g" % ((8 * r,) * 6),
             "create_box %d box" % drop.ntypes]
    if drop.geometry == "wall":
        lines += ["create_atoms %d single 0 0 %.12g" % (drop.types[0], drop.radii[0] + drop.gap)]
    else:
        x = (-(drop.radii[0] + drop.gap / 2), drop.radii[1] + drop.gap / 2)
        lines += ["create_atoms %d single %.12g 0 %.12g" % (t, xt, 4 * r)
                  for t, xt in zip(drop.types, x)]
    lines += ["set atom %d diameter %.12g density %.12g" % (k + 1, 2 * radius, density)
              for k, (radius, density) in enumerate(zip(drop.radii, drop.densities))]
    if drop.geometry == "wall":
        lines += ["velocity all set %.12g 0 %.12g" % (drop.vt, -v)]
    else:
        lines += ["set atom %d vx %.12g" % (k + 1, u) for k, u in enumerate(drop.velocities)]
    lines += ["include %s" % fragment]
    if drop.geometry == "pair":
        lines += ["unfix %s" % line.split()[1] for line in open(fragment)
                  if line.startswith("fix corlab_wall")]
    lines += ["fix corlab_nve all nve/sphere", "timestep %.12g" % dt, "thermo 0",
              "run %d" % drop.steps]
    if drop.geometry == "wall":
        lines += ["variable e equal vz[1]/%.17g" % v]
    else:
        lines += ["variable e equal (vx[2]-vx[1])/%.17g" % v]
    return "\n".join(lines + ['print "CORLAB_E ${e}"']) + "\n"


def simulator(lmp):
    def simulate(out, fragment, drop):
        path = os.path.join(out, "in.%s_%s_%g_%g" % (fragment, drop.geometry, drop.v, drop.dt))
        with open(path, "w") as f:
            f.write(lammps_input(os.path.join(out, fragment), drop))
        return parse_e(run([lmp, "-in", path, "-log", "none", "-echo", "none"]).stdout)
    return simulate


def main():
    corlab, lmp, work = sys.argv[1:4]
    report = sys.argv[sys.argv.index("--report") + 1] if "--report" in sys.argv else None
    os.makedirs(work, exist_ok=True)
    fragments = (("lammps.in", "lammps"), ("lammps_nopython.in", "lammps_nopython"))
    rows, failures, _ = case_rows(corlab, work, "lammps", simulator(lmp), fragments,
                                  lambda key: key)
    return finish("dem_lammps_check", rows, failures, report)


if __name__ == "__main__":
    sys.exit(main())
