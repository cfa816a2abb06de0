#!/usr/bin/env python3
"""Real-code check of `corlab dem` exports in LAMMPS (Debian's `lmp`, never mocked).

For each case `corlab dem` writes the LAMMPS fragment; this script wraps it in a minimal input
(one sphere hitting the fix wall/gran plane z = 0, or two equal spheres head-on), runs `lmp`,
and measures e = rebound speed / impact speed from LAMMPS's own output (no gravity, so the
measured e is the contact's alone).
  constant e in {0.3, 0.5, 0.7, 0.9} at 0.1, 1, 10 m/s: |e_lammps - e| <= 1 % of e.
  e(v) of thornton1997 (alumina on aluminium wall; aluminium spheres) at 3 speeds spanning a
  decade: e_lammps within 1 % of the fitted viscoelastic law's e (ODE) and so within the fit's
  stated error (max |de| in dem_export.json) + 1 % of the target.
usage: dem_lammps_check.py CORLAB_BIN LMP_BIN WORK_DIR [--report FILE]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dem_check_common import (  # noqa: E402
    STEPS_PER_CONTACT, check_cases, contact_time, finish, parse_e, run)


def lammps_input(fragment, pair, radius, density, v, geometry):
    tc = contact_time(pair, v)
    dt = tc / STEPS_PER_CONTACT
    gap = 20 * v * dt
    steps = int((gap / v + 1.6 * tc) / dt)
    lines = ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f",
             "comm_modify vel yes", "neighbor %g bin" % (0.2 * radius),
             "region box block -%g %g -%g %g -%g %g" % ((8 * radius,) * 6), "create_box 1 box"]
    if geometry == "wall":
        lines += ["create_atoms 1 single 0 0 %.12g" % (radius + gap)]
    else:
        lines += ["create_atoms 1 single %.12g 0 %.12g" % (-(radius + gap / 2), 4 * radius),
                  "create_atoms 1 single %.12g 0 %.12g" % (radius + gap / 2, 4 * radius)]
    lines += ["set atom * diameter %.12g density %.12g" % (2 * radius, density)]
    if geometry == "wall":
        lines += ["velocity all set 0 0 %.12g" % (-v)]
    else:
        lines += ["set atom 1 vx %.12g" % (v / 2), "set atom 2 vx %.12g" % (-v / 2)]
    lines += ["include %s" % fragment]
    if geometry == "pair" and "corlab_wall1" in open(fragment).read():
        lines += ["unfix corlab_wall1"]
    lines += ["fix corlab_nve all nve/sphere", "timestep %.12g" % dt, "thermo 0", "run %d" % steps]
    if geometry == "wall":
        lines += ["variable e equal vz[1]/%.17g" % v]
    else:
        lines += ["variable e equal (vx[2]-vx[1])/%.17g" % v]
    return "\n".join(lines + ['print "CORLAB_E ${e}"']) + "\n"


def main():
    corlab, lmp, work = sys.argv[1:4]
    report = sys.argv[sys.argv.index("--report") + 1] if "--report" in sys.argv else None
    os.makedirs(work, exist_ok=True)

    def simulate(out, pair, density, v, geometry):
        path = os.path.join(out, "in.%s_%g" % (geometry, v))
        with open(path, "w") as f:
            f.write(lammps_input(os.path.join(out, "lammps.in"), pair, 0.005, density, v, geometry))
        return parse_e(run([lmp, "-in", path, "-log", "none", "-echo", "none"]).stdout)

    rows, failures = check_cases(simulate, corlab, work, "viscoelastic_damping_N_s_per_m1.5")
    return finish("dem_lammps_check", rows, failures, report)


if __name__ == "__main__":
    sys.exit(main())
