#!/usr/bin/env python3
"""Prints the cost of the e(v) hooks against a constant e in a 400-particle pour (issue 41): per
step (hook / constant) and per simulated second at each fragment's own step (LAMMPS: and per step
with both at the hook's step), in LAMMPS (lammps.in: fix python/invoke; lammps_compiled.in: fix
corlab/ev run by corlab-lammps, code lammps_compiled) and YADE (the PyRunner corlab_hook setting
each contact's damping before it touches). Nothing is asserted.

Two exports of the same particles (two soft types, 200 each, with the five walls of the pour
check): `--table` corlab's FE e(v) of alumina on aluminium (every pair: the hook's e(v)) and
`--restitution 0.6`. Each code puts the 400 particles on a lattice from the floor up, just
apart (a bed, the end of a pour: LAMMPS create_atoms, YADE spheres added), runs 1000 steps
and then STEPS steps more, timed alone in CPU time (LAMMPS's Loop time x its % CPU use, YADE's
process time around O.run): on a shared machine wall-clock ratios swing by 3x.
usage: scripts/dem_hook_benchmark.py --corlab build/bin/corlab [--lmp lmp] [--yade yade]
       [--corlab-lammps build/bin/corlab-lammps] [--steps 4000]
       [--codes lammps,lammps_compiled,yade] [--work DIR]
"""
# SPDX-License-Identifier: BSD-3-Clause
import argparse
import os
import re
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "verification", "dem"))
from dem_check_common import FE_TABLE, export, run  # noqa: E402
from dem_pour_common import G, TYPES, W, WALLS  # noqa: E402

PER_TYPE = 200
SETTLE = 1000  # steps run before the timed ones
TARGETS = (("e(v) hook", ["--table", FE_TABLE, "--v-min", "0.3", "--v-max", "3"]),
           ("constant e", ["--restitution", "0.6", "--v-min", "0.3", "--v-max", "3"]))


def places(data):
    """(type, x, y, z) [m] of the 400 particles: a simple cubic lattice of spacing 2 r_max
    + 0.1 mm from the floor up (7 x 7 a layer), the types alternating: a bed from its start."""
    r_max = max(t["radius_m"] for t in data["types"])
    s = 2.0 * r_max + 1e-4
    sites = [(-W + r_max + a * s, -W + r_max + b * s, r_max + c * s)
             for c in range(9) for b in range(7) for a in range(7)]
    return [(1 + k % 2,) + p for k, p in enumerate(sites[:2 * PER_TYPE])]


def lammps_input(fragment, data, steps, dt=None):
    """The bed in LAMMPS with `fragment`, at its own step or at `dt` [s]."""
    lines = ["units si", "atom_style sphere", "boundary f f f", "comm_modify vel yes",
             "region box block -%g %g -%g %g -0.01 0.3" % (W, W, W, W),
             "create_box %d box" % len(data["types"]), "include %s" % fragment]
    lines += ["timestep %.9g" % dt] if dt else []
    lines += ["fix grav all gravity %g vector 0 0 -1" % G, "fix nve all nve/sphere"]
    lines += ["create_atoms %d single %.9g %.9g %.9g units box" % p for p in places(data)]
    for k, t in enumerate(data["types"]):
        lines += ["set type %d diameter %.9g density %.9g"
                  % (k + 1, 2 * t["radius_m"], t["density_kg_per_m3"]),
                  "group corlab_type%d type %d" % (k + 1, k + 1)]
    lines += ["thermo 1000", "run %d" % SETTLE, "run %d" % steps]
    return "\n".join(lines) + "\n"


YADE = """
import time
exec(open(%(fragment)r).read())
mats = [corlab_mat1, corlab_mat2]
for t, x, y, z in %(places)r:
    O.bodies.append(sphere((x, y, z), %(radii)r[t - 1], material=mats[t - 1]))
engines = [ForceResetter(), InsertionSortCollider(corlab_bound),
           InteractionLoop(corlab_ig2, [corlab_ip2], [corlab_law2])]
if 'corlab_hook' in globals():
    engines.append(corlab_hook)
O.engines = engines + [NewtonIntegrator(damping=0.0, gravity=(0, 0, -%(g)g))]
O.run(%(settle)d, True)
t0 = time.process_time()
O.run(%(steps)d, True)
print('CORLAB_TIME', time.process_time() - t0)
"""


def per_step(code, binary, out, data, steps, dt=None):
    """Seconds per step of `steps` steps of the pour in `code` (LAMMPS: at `dt` [s] if given)."""
    if code.startswith("lammps"):
        path = os.path.join(out, "in.bench")
        with open(path, "w") as f:
            f.write(lammps_input(os.path.join(out, code + ".in"), data, steps, dt))
        text = run([binary, "-in", path, "-log", "none", "-echo", "none"], cwd=out).stdout
        loops = re.findall(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with "
                           r"(\d+) atoms", text)
        seconds, n, atoms = loops[-1]
        if int(atoms) != 2 * PER_TYPE:
            raise RuntimeError("%s atoms poured, not %d" % (atoms, 2 * PER_TYPE))
        cpu = float(re.findall(r"([0-9.]+)% CPU use", text)[-1]) / 100.0
        return float(seconds) * cpu / int(n)
    path = os.path.join(out, "bench.py")
    with open(path, "w") as f:
        f.write(YADE % {"fragment": os.path.join(out, "yade_fragment.py"), "places": places(data),
                        "radii": [t["radius_m"] for t in data["types"]], "g": G, "steps": steps,
                        "settle": SETTLE})
    text = run([binary, "-n", "-x", path], cwd=out).stdout
    return float(re.findall(r"CORLAB_TIME ([0-9.eE+-]+)", text)[-1]) / steps


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--corlab", required=True)
    ap.add_argument("--lmp", default="lmp")
    ap.add_argument("--yade", default="yade")
    ap.add_argument("--corlab-lammps", default="corlab-lammps")
    ap.add_argument("--steps", type=int, default=4000)
    ap.add_argument("--codes", default="lammps,yade")
    ap.add_argument("--work", default=None)
    a = ap.parse_args()
    work = a.work or tempfile.mkdtemp(prefix="corlab_dem_bench_")
    # a path (not a name on PATH) made absolute: the codes run in the export's folder
    binaries = {code: os.path.abspath(b) if os.sep in b else b for code, b in
                (("lammps", a.lmp), ("lammps_compiled", a.corlab_lammps), ("yade", a.yade))}
    for code in a.codes.split(","):
        cost, exports = {}, {}
        for name, args in TARGETS:
            out = os.path.join(work, "%s_%s" % (code, "hook" if "hook" in name else "constant"))
            walls = sum((["--wall", w] for w in WALLS), [])
            types = sum((["--type", t] for t in TYPES), [])
            data = export(a.corlab, out, args + walls + types)
            exports[name] = (out, data)
            dt = data["time_step_s"]["lammps" if code.startswith("lammps") else code]
            cost[name] = (per_step(code, binaries[code], out, data, a.steps), dt)
            print("%-15s %-11s %.3e s/step, step %.3e s: %.3g s per simulated second"
                  % (code, name, cost[name][0], dt, cost[name][0] / dt), flush=True)
        (hook, dt_hook), (const, dt_const) = cost["e(v) hook"], cost["constant e"]
        print("%-15s hook / constant e: %.2f per step, %.2f per simulated second"
              % (code, hook / const, (hook / dt_hook) / (const / dt_const)), flush=True)
        if code.startswith("lammps"):
            # Each at its own step the runs cover different times of the bed's fall (the
            # constant e's 27x smaller step: fewer contacts); at the hook's step both cover
            # the same, and the ratio is the hook's own cost.
            same = per_step(code, binaries[code], *exports["constant e"], a.steps, dt_hook)
            print("%-15s constant e at the hook's step %.3e s: %.3e s/step; hook / constant e "
                  "there: %.2f per step" % (code, dt_hook, same, hook / same), flush=True)


if __name__ == "__main__":
    main()
