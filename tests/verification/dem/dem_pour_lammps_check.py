#!/usr/bin/env python3
"""A real pour in LAMMPS (Debian's `lmp`, never mocked) from a `corlab dem` export (issue 41).

The pour of dem_pour_common.py: `fix pour` of each type (into the fragment's group corlab_typeN, as
its comments say) with vx towards the side wall, lammps.in included unedited, its five walls
(region + fix wall/gran/region) closing the box. Checks: LAMMPS's neighbour list cutoff at least
2 r_max (the farthest contact; without the fragment's cutoff this LAMMPS takes 2 x 4 mm + skin,
and stiff particles meeting at deep overlap blow up), then those of dem_pour_common.check on the
thermo output and a dump (id type x vx z and compute contact/atom) every sample interval.
usage: dem_pour_lammps_check.py CORLAB_BIN LMP_BIN WORK_DIR [--report FILE]
"""
# SPDX-License-Identifier: BSD-3-Clause
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dem_check_common import run  # noqa: E402
from dem_pour_common import (  # noqa: E402
    G, PER_TYPE, VX, W, check, dump_samples, insertion_box, monitor_and_run, pour_export, steps,
    thermo_rows, work_file)


def pour_input(fragment, data):
    dt, n, every = steps(data, "lammps")
    lines = ["units si", "atom_style sphere", "boundary f f f", "comm_modify vel yes",
             "region box block -%g %g -%g %g -0.01 0.25" % (W, W, W, W),
             "create_box %d box" % len(data["types"]), "include %s" % fragment,
             "fix grav all gravity %g vector 0 0 -1" % G, "fix nve all nve/sphere"]
    for k, t in enumerate(data["types"]):
        lines += ["region corlab_in%d block %g %g %g %g %g %g units box"
                  % ((k + 1,) + insertion_box(k)),
                  "fix pour%d corlab_type%d pour %d %d %d region corlab_in%d diam one %.9g "
                  "dens %.9g %.9g vel %g %g 0 0 0"
                  % (k + 1, k + 1, PER_TYPE, k + 1, 1234 + k, k + 1, 2 * t["radius_m"],
                     t["density_kg_per_m3"], t["density_kg_per_m3"], VX, VX)]
    lines += monitor_and_run(every, n)
    return "\n".join(lines) + "\n", dt


def main():
    corlab, lmp, work = sys.argv[1:4]
    report = sys.argv[sys.argv.index("--report") + 1] if "--report" in sys.argv else None
    data = pour_export(corlab, work)
    text, _ = pour_input(os.path.join(work, "lammps.in"), data)
    path = work_file(work, "in.pour")
    with open(path, "w") as f:
        f.write(text)
    out = run([lmp, "-in", path, "-log", "none", "-echo", "none"], cwd=work).stdout
    cutoff = min((float(line.split("=")[1]) for line in out.splitlines()
                  if "master list distance cutoff" in line), default=0.0)
    r_max = max(t["radius_m"] for t in data["types"])
    ok = cutoff >= 2 * r_max
    print("%-32s %-12.6g %-10s %s" % ("neighbour list cutoff [m]", cutoff, ">= %.4g" % (2 * r_max),
                                      "ok" if ok else "FAIL"))
    failures = check("dem_pour_lammps_check", "lammps", data, thermo_rows(out),
                     dump_samples(os.path.join(work, "dump.pour")), report)
    return 1 if failures or not ok else 0


if __name__ == "__main__":
    sys.exit(main())
