#!/usr/bin/env python3
"""Real-code check of `corlab dem` exports in YADE 2023.02a (Debian's `yade`, never mocked).

Constant e: Hertz-Mindlin with en (exact for Hertz) within 1 %. e(v) of thornton1997 through
the fragment's per-contact hook (a PyRunner setting the Ip2 functor's en from each new contact's
approach speed): within 1 % of the target e(v) itself at 3 speeds spanning a decade.
usage: dem_yade_check.py CORLAB_BIN YADE_BIN WORK_DIR [--report FILE]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dem_check_common import (  # noqa: E402
    STEPS_PER_CONTACT, check_cases, contact_time, finish, parse_e, run)


def yade_script(fragment, pair, radius, v, geometry):
    tc = contact_time(pair, v)
    dt = tc / STEPS_PER_CONTACT
    gap = 20 * v * dt
    steps = int((gap / v + 1.6 * tc) / dt)
    hook = "corlab_set_en" in open(fragment).read()
    lines = ["exec(open(%r).read())" % fragment, "R = %.17g" % radius]
    if geometry == "wall":
        lines += ["O.bodies.append(box((0, 0, -R), (8 * R, 8 * R, R), fixed=True, "
                  "material=corlab_wall_mat))",
                  "a = O.bodies.append(sphere((0, 0, R + %.17g), R, material=corlab_mat1))"
                  % gap,
                  "O.bodies[a].state.vel = Vector3(0, 0, %.17g)" % (-v)]
        measure = "O.bodies[a].state.vel[2] / %.17g" % v
    else:
        lines += ["a = O.bodies.append(sphere((%.17g, 0, 0), R, material=corlab_mat1))"
                  % (-(radius + gap / 2)),
                  "b = O.bodies.append(sphere((%.17g, 0, 0), R, material=corlab_mat1))"
                  % (radius + gap / 2),
                  "O.bodies[a].state.vel = Vector3(%.17g, 0, 0)" % (v / 2),
                  "O.bodies[b].state.vel = Vector3(%.17g, 0, 0)" % (-v / 2)]
        measure = "(O.bodies[b].state.vel[0] - O.bodies[a].state.vel[0]) / %.17g" % v
    lines += ["O.engines = [ForceResetter(), "
              "InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Box_Aabb()]),"]
    if hook:
        lines += ["    PyRunner(command='corlab_set_en()', iterPeriod=1),"]
    lines += ["    InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Box_Sphere_ScGeom()], "
              "[corlab_ip2],",
              "                    [Law2_ScGeom_MindlinPhys_Mindlin()]),",
              "    NewtonIntegrator(damping=0.0, gravity=(0, 0, 0))]",
              "O.dt = %.17g" % dt, "O.run(%d, True)" % steps, "print('CORLAB_E', %s)" % measure]
    return "\n".join(lines) + "\n"


def main():
    corlab, yade, work = sys.argv[1:4]
    report = sys.argv[sys.argv.index("--report") + 1] if "--report" in sys.argv else None
    os.makedirs(work, exist_ok=True)

    def simulate(out, pair, density, v, geometry):
        path = os.path.join(out, "yade_%s_%g.py" % (geometry, v))
        with open(path, "w") as f:
            f.write(yade_script(os.path.join(out, "yade_fragment.py"), pair, 0.005, v, geometry))
        return parse_e(run([yade, "-n", "-x", path], cwd=out).stdout)

    rows, failures = check_cases(simulate, corlab, work, "viscoelastic_damping_N_s_per_m1.5",
                                 exact=True)
    return finish("dem_yade_check", rows, failures, report)


if __name__ == "__main__":
    sys.exit(main())
