#!/usr/bin/env python3
"""Real-code check of `corlab dem` exports in LIGGGHTS 3.8 (Debian's `liggghts`, never mocked).

Same cases as dem_lammps_check.py: constant e (model hertz, coefficientRestitution) within 1 %,
and e(v) of thornton1997 through model thornton_ning with the fitted coefficientYieldRatio:
within 1 % of the fitted law's e (ODE of LIGGGHTS's own law) and within the fit's stated error
+ 1 % of the target.
usage: dem_liggghts_check.py CORLAB_BIN LIGGGHTS_BIN WORK_DIR [--report FILE]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dem_check_common import (  # noqa: E402
    STEPS_PER_CONTACT, check_cases, contact_time, finish, parse_e, run)


def liggghts_input(fragment, pair, radius, density, v, geometry):
    tc = contact_time(pair, v)
    dt = tc / STEPS_PER_CONTACT
    gap = 20 * v * dt
    steps = int((gap / v + 1.6 * tc) / dt)
    text = open(fragment).read()
    ntypes = 2 if "corlab_wall" in text else 1
    lines = ["atom_style granular", "atom_modify map array", "boundary f f f", "newton off",
             "communicate single vel yes", "units si", "hard_particles yes",
             "region reg block -%g %g -%g %g -%g %g units box"
             % ((8 * radius,) * 4 + (0.001 * radius, 8 * radius)),
             "create_box %d reg" % ntypes, "neighbor %g bin" % (0.2 * radius),
             "neigh_modify delay 0", "include %s" % fragment]
    if geometry == "wall":
        lines += ["create_atoms 1 single 0 0 %.12g units box" % (radius + gap)]
    else:
        if ntypes == 2:
            lines += ["unfix corlab_wall"]
        lines += ["create_atoms 1 single %.12g 0 %.12g units box"
                  % (-(radius + gap / 2), 4 * radius),
                  "create_atoms 1 single %.12g 0 %.12g units box"
                  % (radius + gap / 2, 4 * radius)]
    lines += ["set atom * diameter %.12g density %.12g" % (2 * radius, density)]
    if geometry == "wall":
        lines += ["velocity all set 0 0 %.12g units box" % (-v)]
    else:
        lines += ["set atom 1 vx %.12g" % (v / 2), "set atom 2 vx %.12g" % (-v / 2)]
    lines += ["fix corlab_nve all nve/sphere", "timestep %.12g" % dt, "run %d" % steps]
    if geometry == "wall":
        lines += ["variable e equal vz[1]/%.17g" % v]
    else:
        lines += ["variable e equal (vx[2]-vx[1])/%.17g" % v]
    return "\n".join(lines + ['print "CORLAB_E ${e}"']) + "\n"


def main():
    corlab, liggghts, work = sys.argv[1:4]
    report = sys.argv[sys.argv.index("--report") + 1] if "--report" in sys.argv else None
    os.makedirs(work, exist_ok=True)

    def simulate(out, pair, density, v, geometry):
        path = os.path.join(out, "in.%s_%g" % (geometry, v))
        with open(path, "w") as f:
            f.write(liggghts_input(os.path.join(out, "liggghts.in"), pair, 0.005, density, v,
                                   geometry))
        return parse_e(run([liggghts, "-in", path, "-log", "none", "-echo", "none"],
                           cwd=out).stdout)

    rows, failures = check_cases(simulate, corlab, work, "liggghts_thornton_ning_pressure_Pa")
    return finish("dem_liggghts_check", rows, failures, report)


if __name__ == "__main__":
    sys.exit(main())
