#!/usr/bin/env python3
"""Walls at any orientation in LAMMPS, LIGGGHTS and YADE (Debian's, never mocked; issue 41).

One export with an oblique plane (normal (1, 0, 1)/sqrt(2) through the origin, its own material;
LAMMPS region plane, LIGGGHTS the STL mesh the export writes, YADE two facets) and a cylinder
(axis z, radius 30 mm, another material; LAMMPS region cylinder, LIGGGHTS zcylinder, YADE
facetCylinder), constant e 0.5. In each code one particle hits each wall head-on at 1 m/s, no
gravity, the contact starting mid-step, at the fragment's own step: e (the normal speed after
over before) must be within the export's stated max |de| + its time-step error of 0.5 (for a
constant e the damping sets e whatever the stiffness, so the cylinder's curvature does not move
it). YADE's cylinder is printed, not checked: its facets (48 sides, 3.9 mm wide here) are
narrower than the particle, which meets two at once and gets each one's damping (e 0.395).
YADE's e(v) hook on facets: the oblique-plane drop once more from an e(v) export, e within the
stated bound of e(1 m/s).
usage: dem_walls_check.py CORLAB_BIN LMP_BIN LIGGGHTS_BIN YADE_BIN WORK_DIR
"""
# SPDX-License-Identifier: BSD-3-Clause
import math
import os
import sys

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dem_check_common import FE_TABLE, export, parse_e, run  # noqa: E402

R = 0.004  # m
RHO = 1000.0  # kg/m^3
V = 1.0  # m/s
RC = 0.03  # m, the cylinder's radius
TARGET = 0.5
S = 1.0 / math.sqrt(2.0)
ARGS = ["--type", "a=E=5e6,nu=0.3,rho=%g:%g" % (RHO, R), "--wall-only", "--restitution", "0.5",
        "--wall", "tilted=E=2e7,nu=0.3,rho=2000@plane:0,0,0,1,0,1,0.05",
        "--wall", "drum=E=3e7,nu=0.3,rho=2000@cylinder:z,0,0,%g,-0.05,0.05" % RC, "--v-max", "2"]


def cases(dt):
    """(name, start [m], velocity [m/s], unit normal of the wall into the particle)."""
    gap = 20.5 * V * dt
    d = R + gap
    # the plane hit 20 mm along y from its point: inside one of YADE's two facets (their shared
    # diagonal runs through the point)
    return (("oblique plane", (S * d, 0.02, S * d), (-S * V, 0.0, -S * V), (S, 0.0, S)),
            ("cylinder", (RC - d, 0.0, 0.0), (V, 0.0, 0.0), (-1.0, 0.0, 0.0)))


def steps(data, dt):
    tc = min(p["contact_time_at_v_min_s"] for p in data["pairs"])
    return int((20.5 * V * dt / V + 2.0 * tc) / dt)


def lammps_like(fragment, data, code, start, vel, normal):
    dt = data["time_step_s"][code]
    e = "(vx[1]*%.17g+vz[1]*%.17g)/%.17g" % (normal[0], normal[2], V)
    lines = ["units si", "atom_modify map array", "boundary f f f"]
    if code == "lammps":
        lines = ["atom_style sphere"] + lines + ["comm_modify vel yes"]
    else:
        lines = ["atom_style granular"] + lines + ["newton off", "communicate single vel yes"]
    lines += ["region box block -0.06 0.06 -0.06 0.06 -0.06 0.06 units box",
              "create_box %d box" % (1 if code == "lammps" else 3),
              "create_atoms 1 single %.17g %.17g %.17g units box" % start,
              "set atom 1 diameter %.17g density %.17g" % (2 * R, RHO), "include %s" % fragment,
              "velocity all set %.17g %.17g %.17g units box" % vel,
              "fix nve all nve/sphere", "thermo 0", "run %d" % steps(data, dt),
              "variable e equal %s" % e, 'print "CORLAB_E ${e}"']
    return "\n".join(lines) + "\n"


YADE = """exec(open(%(fragment)r).read())
a = O.bodies.append(sphere(%(start)r, %(r).17g, material=corlab_mat1))
O.bodies[a].state.vel = Vector3%(vel)r
O.engines = [ForceResetter(), InsertionSortCollider(corlab_bound),
             InteractionLoop(corlab_ig2, [corlab_ip2], [corlab_law2])]
if 'corlab_hook' in globals():  # an e(v) export
    O.engines = O.engines + [corlab_hook]
O.engines = O.engines + [NewtonIntegrator(damping=0.0, gravity=(0, 0, 0))]
O.run(%(steps)d, True)
print('CORLAB_E', O.bodies[a].state.vel.dot(Vector3%(normal)r) / %(v).17g)
"""


def yade_ev(corlab, yade, work):
    """YADE's hook on facets: the oblique-plane drop from an e(v) export (corlab's FE e(v) of
    alumina on aluminium for both walls): e within the stated bound of e(V)."""
    out = os.path.join(work, "export_ev")
    args = [a for a in ARGS if a not in ("--restitution", "0.5")]
    data = export(corlab, out, args + ["--table", FE_TABLE, "--v-min", "0.3"])
    dt = data["time_step_s"]["yade"]
    pair = next(p for p in data["pairs"] if "tilted" in p["label"])
    rows = pair["table"]
    target = float(numpy.interp(V, [r["v"] for r in rows], [r["e"] for r in rows]))
    bound = pair["delivered"]["yade"]["max_abs_error"] + data["time_step_error"]
    name, start, vel, normal = cases(dt)[0]
    path = os.path.join(out, "yade_oblique_ev.py")
    with open(path, "w") as f:
        f.write(YADE % {"fragment": os.path.join(out, "yade_fragment.py"), "start": start,
                        "r": R, "vel": vel, "steps": steps(data, dt), "normal": normal, "v": V})
    e = parse_e(run([yade, "-n", "-x", path], cwd=out).stdout)
    ok = abs(e - target) <= bound
    print("%-8s %-14s e = %.6f |e - e(%g) = %.4f| = %.1e (<= %.1e) %s"
          % ("yade", name + " e(v)", e, V, target, abs(e - target), bound, "ok" if ok else "FAIL"))
    return not ok


def main():
    corlab, lmp, liggghts, yade, work = sys.argv[1:6]
    out = os.path.join(work, "export")
    data = export(corlab, out, ARGS)
    failures = yade_ev(corlab, yade, work)
    for code, binary in (("lammps", lmp), ("liggghts", liggghts), ("yade", yade)):
        dt = data["time_step_s"][code]
        stated = max(p["delivered"][code]["max_abs_error"] for p in data["pairs"])
        bound = stated + data["time_step_error"]
        for name, start, vel, normal in cases(dt):
            path = os.path.join(out, "%s_%s" % (code, name.replace(" ", "_")))
            if code == "yade":
                text = YADE % {"fragment": os.path.join(out, "yade_fragment.py"), "start": start,
                               "r": R, "vel": vel, "steps": steps(data, dt), "normal": normal,
                               "v": V}
                cmd = [binary, "-n", "-x", path + ".py"]
                path += ".py"
            else:
                fragment = os.path.join(out, "%s.in" % code)
                text = lammps_like(fragment, data, code, start, vel, normal)
                cmd = [binary, "-in", path, "-log", "none", "-echo", "none"]
            with open(path, "w") as f:
                f.write(text)
            e = parse_e(run(cmd, cwd=out).stdout)  # LIGGGHTS reads the mesh from here
            ok = abs(e - TARGET) <= bound
            known = code == "yade" and name == "cylinder"
            failures += not ok and not known
            print("%-8s %-14s e = %.6f |e - %.1f| = %.1e (<= %.1e) %s"
                  % (code, name, e, TARGET, abs(e - TARGET), bound,
                     "(not checked: two facets)" if known else "ok" if ok else "FAIL"))
    print("dem_walls_check: %d failure(s)" % failures)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
