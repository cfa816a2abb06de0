#!/usr/bin/env python3
"""Real-code check of `corlab dem` exports in YADE 2023.02a (Debian's `yade`, never mocked).

Same cases and bounds as dem_lammps_check.py (dem_check_common.py), with yade_fragment.py at its
recommended step (O.dt): Hertz-Mindlin with en per material pair, e(v) through the fragment's
hook (a PyRunner giving each contact, before it touches, the damping of e(v_n) at its normal
approach speed); plus one
oblique frictionless impact (glass on copper, v_n = 2, v_t = 1.5 m/s) whose normal e must be
e(v_n), not e(|v|).
usage: dem_yade_check.py CORLAB_BIN YADE_BIN WORK_DIR [--report FILE]
"""
# SPDX-License-Identifier: BSD-3-Clause
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dem_check_common import (  # noqa: E402
    EV_CASES, Drop, case_rows, export, finish, parse_e, run)


def yade_script(fragment, drop):
    v = drop.v
    hook = "corlab_hook = " in open(fragment).read()
    lines = ["exec(open(%r).read())" % fragment]
    if drop.geometry == "wall":
        lines += ["R = %.17g" % drop.radii[0],  # the floor z = 0: the fragment's utils.wall
                  "a = O.bodies.append(sphere((0, 0, R + %.17g), R, material=corlab_mat%d))"
                  % (drop.gap, drop.types[0]),
                  "O.bodies[a].state.vel = Vector3(%.17g, 0, %.17g)" % (drop.vt, -v)]
        measure = "O.bodies[a].state.vel[2] / %.17g" % v
    else:
        (r1, r2), (t1, t2) = drop.radii, drop.types
        lines += ["for w in corlab_walls:", "    O.bodies.erase(w)",  # head-on, no wall
                  "a = O.bodies.append(sphere((%.17g, 0, 0), %.17g, material=corlab_mat%d))"
                  % (-(r1 + drop.gap / 2), r1, t1),
                  "b = O.bodies.append(sphere((%.17g, 0, 0), %.17g, material=corlab_mat%d))"
                  % (r2 + drop.gap / 2, r2, t2),
                  "O.bodies[a].state.vel = Vector3(%.17g, 0, 0)" % drop.velocities[0],
                  "O.bodies[b].state.vel = Vector3(%.17g, 0, 0)" % drop.velocities[1]]
        measure = "(O.bodies[b].state.vel[0] - O.bodies[a].state.vel[0]) / %.17g" % v
    lines += ["O.engines = [ForceResetter(), InsertionSortCollider(corlab_bound),",
              "    InteractionLoop(corlab_ig2, [corlab_ip2], [corlab_law2]),"]
    if hook:
        lines += ["    corlab_hook,"]
    lines += ["    NewtonIntegrator(damping=0.0, gravity=(0, 0, 0))]",
              "O.dt = %.17g" % drop.dt, "O.run(%d, True)" % drop.steps,
              # with the hook: no e (nan, a failure) unless the contact was set before it touched
              "print('CORLAB_E', %s)" % (measure if not hook else
                                         "%s if corlab_missed == 0 else float('nan')" % measure)]
    return "\n".join(lines) + "\n"


def simulator(yade):
    def simulate(out, fragment, drop):
        path = os.path.join(out, "yade_%s_%g_%g_%g.py" % (drop.geometry, drop.v, drop.vt, drop.dt))
        with open(path, "w") as f:
            f.write(yade_script(os.path.join(out, fragment), drop))
        return parse_e(run([yade, "-n", "-x", path], cwd=out).stdout)
    return simulate


def oblique(corlab, work, simulate):
    """Glass on copper, frictionless, v_n = 2 and v_t = 1.5 m/s: e must be e(v_n)."""
    name, args, _ = EV_CASES[0]
    out = os.path.join(work, name + "_oblique")
    data = export(corlab, out, args)
    pair = {p["pair"]: p for p in data["pairs"]}["1-wall"]
    e_n = [row["e"] for row in pair["table"]]
    v_tab = [row["v"] for row in pair["table"]]
    import numpy
    target = float(numpy.interp(2.0, v_tab, e_n))
    full = float(numpy.interp(2.5, v_tab, e_n))
    e = simulate(out, "yade_fragment.py", Drop(data, pair, "wall", 2.0,
                                               data["time_step_s"]["yade"], vt=1.5))
    bound = pair["delivered"]["yade"]["max_abs_error"] + data["time_step_error"]
    ok = abs(e - target) <= bound
    return ("oblique glass-copper v_n=2 v_t=1.5: e=%.6f e(v_n)=%.6f (e(|v|)=%.6f) |de|=%.1e "
            "(<= %.1e) %s" % (e, target, full, abs(e - target), bound, "ok" if ok else "FAIL"),
            not ok)


def main():
    corlab, yade, work = sys.argv[1:4]
    report = sys.argv[sys.argv.index("--report") + 1] if "--report" in sys.argv else None
    os.makedirs(work, exist_ok=True)
    simulate = simulator(yade)
    rows, failures, _ = case_rows(corlab, work, "yade", simulate, (("yade_fragment.py", "yade"),),
                                  lambda key: key)
    row, failed = oblique(corlab, work, simulate)
    return finish("dem_yade_check", rows + [row], failures + failed, report)


if __name__ == "__main__":
    sys.exit(main())
