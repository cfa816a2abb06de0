#!/usr/bin/env python3
"""A real pour in LIGGGHTS (Debian's `liggghts`, never mocked) from a `corlab dem` export
(issue 41).

The pour of dem_pour_common.py: `fix insert/pack` of each type (insert_every once, vx towards the
side wall) into the box the fragment's five primitive walls close, liggghts.in included unedited
after create_box with the particle types and one atom type per wall material. Checks: those of
dem_pour_common.check on the thermo output and a dump (id type x vx z and compute contact/atom)
every sample interval.
usage: dem_pour_liggghts_check.py CORLAB_BIN LIGGGHTS_BIN WORK_DIR [--report FILE]
"""
# SPDX-License-Identifier: BSD-3-Clause
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dem_check_common import run  # noqa: E402
from dem_pour_common import (  # noqa: E402
    G, PER_TYPE, VX, W, check, dump_samples, insertion_box, monitor_and_run, pour_export, steps,
    thermo_rows, work_file)

PRIMES = (15485863, 32452843, 49979687, 67867967, 86028121, 104395301)  # LIGGGHTS's seeds


def pour_input(fragment, data):
    dt, n, every = steps(data, "liggghts")
    ntypes = len(data["types"]) + len({p["label"].split("-")[-1] for p in data["pairs"]
                                       if p["type_j"] == 0})
    lines = ["atom_style granular", "atom_modify map array", "boundary f f f", "newton off",
             "communicate single vel yes", "units si",
             "region box block -%g %g -%g %g -0.01 0.25 units box" % (W, W, W, W),
             "create_box %d box" % ntypes, "include %s" % fragment,
             "fix grav all gravity %g vector 0 0 -1" % G]
    for k, t in enumerate(data["types"]):
        seeds = PRIMES[3 * k:3 * k + 3]
        lines += ["fix pts%d all particletemplate/sphere %d atom_type %d density constant %.9g "
                  "radius constant %.9g" % (k + 1, seeds[0], k + 1, t["density_kg_per_m3"],
                                            t["radius_m"]),
                  "fix pdd%d all particledistribution/discrete %d 1 pts%d 1.0"
                  % (k + 1, seeds[1], k + 1),
                  "region corlab_in%d block %g %g %g %g %g %g units box"
                  % ((k + 1,) + insertion_box(k)),
                  "fix ins%d all insert/pack seed %d distributiontemplate pdd%d "
                  "vel constant %g 0 0 insert_every once overlapcheck yes all_in yes "
                  "particles_in_region %d region corlab_in%d"
                  % (k + 1, seeds[2], k + 1, VX, PER_TYPE, k + 1)]
    lines += ["fix nve all nve/sphere"] + monitor_and_run(every, n)
    return "\n".join(lines) + "\n", dt


def main():
    corlab, liggghts, work = sys.argv[1:4]
    report = sys.argv[sys.argv.index("--report") + 1] if "--report" in sys.argv else None
    data = pour_export(corlab, work)
    text, _ = pour_input(os.path.join(work, "liggghts.in"), data)
    path = work_file(work, "in.pour")
    with open(path, "w") as f:
        f.write(text)
    out = run([liggghts, "-in", path, "-log", "none", "-echo", "none"], cwd=work).stdout
    failures = check("dem_pour_liggghts_check", "liggghts", data, thermo_rows(out),
                     dump_samples(os.path.join(work, "dump.pour")), report)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
