#!/usr/bin/env python3
"""A real pour in YADE (Debian's `yade`, never mocked) from a `corlab dem` export (issue 41).

The pour of dem_pour_common.py: yade_fragment.py exec'd unedited (its five walls are utils.wall
bodies), the spheres of each type added at run time by a PyRunner (type 1 at the first step,
type 2 a few steps later, at random non-overlapping places of its insertion region, vx towards
the side wall), gravity, the fragment's functors. A second PyRunner writes every sample interval
each sphere's id, type, x, vx, z and number of sphere contacts, and the totals. Checks: those of
dem_pour_common.check. Then the same pour from an e(v) export (corlab's FE e(v) of alumina on
aluminium for every pair, --v-max 2) with the fragment's corlab_hook: each first side-wall
contact's e within the stated bound of e(v_in), and corlab_missed (contacts the hook did not set
before they touched) zero.
usage: dem_pour_yade_check.py CORLAB_BIN YADE_BIN WORK_DIR [--report FILE]
"""
# SPDX-License-Identifier: BSD-3-Clause
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dem_check_common import FE_TABLE, export, run  # noqa: E402
from dem_pour_common import (  # noqa: E402
    G, PER_TYPE, TYPES, VX, WALLS, check, insertion_box, pour_export, steps, work_file)

SCRIPT = """
import random
exec(open(%(fragment)r).read())
TYPES = %(types)r  # (radius [m], insertion box) per type
corlab_mats = [corlab_mat1, corlab_mat2]
out = open('pour_samples.txt', 'w')

def insert(k):
    r, (x0, x1, y0, y1, z0, z1) = TYPES[k]
    rng = random.Random(1234 + k)
    placed = [(b.state.pos, b.shape.radius) for b in O.bodies if isinstance(b.shape, Sphere)]
    added, tries = 0, 0
    while added < %(per_type)d and tries < 200000:
        tries += 1
        p = Vector3(rng.uniform(x0 + r, x1 - r), rng.uniform(y0 + r, y1 - r),
                    rng.uniform(z0 + r, z1 - r))
        if any((p - q).norm() < r + s for q, s in placed):
            continue
        b = O.bodies.append(sphere(p, r, material=corlab_mats[k]))
        O.bodies[b].state.vel = Vector3(%(vx).17g, 0, 0)
        placed.append((p, r))
        added += 1

def pour():
    if O.iter == 1:
        insert(0)
    elif O.iter == 1 + %(every)d:
        insert(1)

def sample():
    spheres = [b for b in O.bodies if isinstance(b.shape, Sphere)]
    if not spheres:
        return
    ke, vmax = 0.0, 0.0
    for b in spheres:
        s = b.state
        contacts = sum(1 for i in O.interactions.withBody(b.id)  # touching (the hook keeps more)
                       if i.isReal and i.geom.penetrationDepth > 0
                       and isinstance(O.bodies[i.id1 if i.id2 == b.id else i.id2].shape, Sphere))
        out.write('S %%d %%d %%d %%.10g %%.10g %%.10g %%d\\n' %% (
            O.iter, b.id, corlab_type_of_material[b.material.id], s.pos[0], s.vel[0], s.pos[2],
            contacts))
        ke += 0.5 * s.mass * s.vel.squaredNorm()
        vmax = max(vmax, s.vel.norm())
    xs = [b.state.pos for b in spheres]
    out.write('T %%d %%d %%.10g %%.10g %%.10g %%.10g %%.10g %%.10g %%.10g\\n' %% (
        O.iter, len(spheres), ke, vmax, min(p[0] for p in xs), max(p[0] for p in xs),
        min(p[1] for p in xs), max(p[1] for p in xs), min(p[2] for p in xs)))

O.engines = [ForceResetter(), InsertionSortCollider(corlab_bound),
             PyRunner(command='pour()', iterPeriod=1),
             InteractionLoop(corlab_ig2, [corlab_ip2], [corlab_law2])]
if 'corlab_hook' in globals():  # an e(v) export
    O.engines = O.engines + [corlab_hook]
O.engines = O.engines + [NewtonIntegrator(damping=0.0, gravity=(0, 0, -%(g).17g)),
                         PyRunner(command='sample()', iterPeriod=%(every)d)]
O.run(%(steps)d, True)
out.write('M %%d\\n' %% globals().get('corlab_missed', 0))
out.close()
print('CORLAB_DONE')
"""
TOTALS = ("step", "atoms", "ke", "vmax", "xlo", "xhi", "ylo", "yhi", "zlo")


def read_samples(path):
    """(totals, samples, missed) of pour_samples.txt: samples[k] = {id: (type, x, vx, z,
    contacts)}, missed the hook's corlab_missed (contacts it did not set before they touched)."""
    totals, samples, by_step, missed = [], [], {}, None
    with open(path) as f:
        for line in f:
            w = line.split()
            if w[0] == "M":
                missed = int(w[1])
            elif w[0] == "T":
                totals.append(dict(zip(TOTALS, map(float, w[1:]))))
            elif w[0] == "S":
                snap = by_step.get(w[1])
                if snap is None:
                    snap = by_step[w[1]] = {}
                    samples.append(snap)
                snap[int(w[2])] = (int(w[3]), float(w[4]), float(w[5]), float(w[6]), int(w[7]))
    return totals, samples, missed


def pour(yade, work, data):
    """Runs the pour of export `data` (in `work`); (totals, samples, missed)."""
    _, n, every = steps(data, "yade")
    types = [(t["radius_m"], insertion_box(k)) for k, t in enumerate(data["types"])]
    path = work_file(work, "pour.py")
    with open(path, "w") as f:
        f.write(SCRIPT % {"fragment": os.path.join(work, "yade_fragment.py"), "types": types,
                          "per_type": PER_TYPE, "vx": VX, "every": every, "g": G, "steps": n})
    run([yade, "-n", "-x", path], cwd=work)
    return read_samples(os.path.join(work, "pour_samples.txt"))


def main():
    corlab, yade, work = sys.argv[1:4]
    report = sys.argv[sys.argv.index("--report") + 1] if "--report" in sys.argv else None
    data = pour_export(corlab, work)
    totals, samples, _ = pour(yade, work, data)
    failures = check("dem_pour_yade_check", "yade", data, totals, samples, report)
    # The same pour with an e(v) export (corlab's FE e(v) of alumina on aluminium for every
    # pair): the hook's e of each first side-wall contact, and no contact it did not set.
    ev_work = os.path.join(work, "ev")
    ev = export(corlab, ev_work, ["--table", FE_TABLE, "--v-min", "0.3", "--v-max", "2",
                                  "--friction", "0.3"]
                + sum((["--wall", w] for w in WALLS), []) + sum((["--type", t] for t in TYPES), []))
    totals, samples, missed = pour(yade, ev_work, ev)
    ev_report = report and report.replace(".txt", "_ev.txt")
    failures += check("dem_pour_yade_check (e(v))", "yade", ev, totals, samples, ev_report)
    print("contacts the hook did not set before they touched (corlab_missed): %s (== 0) %s"
          % (missed, "ok" if missed == 0 else "FAIL"))
    failures += missed != 0
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
