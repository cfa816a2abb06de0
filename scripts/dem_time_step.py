#!/usr/bin/env python3
"""Measures the steps per contact each DEM code needs so that its e stays within the promised
time-step error (1e-3) of its law's e: runs the drop tests of tests/verification/dem (the cases of
dem_check_common.py, every code) at contact time at v_max / N for N = 25, 50, 100, ... with the
contact starting at several points of a step (--phases) and prints the worst |e_code - e_law| per
code and law. The table in src/dem/time_step.cpp holds the smallest N of the doubling series
whose worst error is within 1e-3 at N and at N/2 (the stated step and twice it hold the
promise), with the errors measured there.
usage: scripts/dem_time_step.py --corlab build/bin/corlab [--lmp lmp] [--liggghts liggghts]
       [--yade yade] [--work DIR] [--steps 25,50,100,200,400] [--phases 0,0.25,0.5,0.75]
       [--codes lammps,liggghts,yade] [--cases glass_copper,alumina_aluminium]
"""
# SPDX-License-Identifier: BSD-3-Clause
import argparse
import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "verification", "dem"))
from dem_check_common import case_rows  # noqa: E402
import dem_lammps_check  # noqa: E402
import dem_liggghts_check  # noqa: E402
import dem_yade_check  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--corlab", required=True)
    ap.add_argument("--lmp", default="lmp")
    ap.add_argument("--liggghts", default="liggghts")
    ap.add_argument("--yade", default="yade")
    ap.add_argument("--work", default=None)
    ap.add_argument("--steps", default="25,50,100,200,400")
    ap.add_argument("--phases", default="0,0.25,0.5,0.75")
    ap.add_argument("--codes", default="lammps,liggghts,yade")
    ap.add_argument("--cases", default=None, help="EV cases to run (default: all)")
    a = ap.parse_args()
    cases = a.cases.split(",") if a.cases else None
    work = a.work or tempfile.mkdtemp(prefix="corlab_dem_dt_")
    codes = (("lammps", dem_lammps_check.simulator(a.lmp),
              (("lammps.in", "lammps"), ("lammps_nopython.in", "lammps_nopython"))),
             ("liggghts", dem_liggghts_check.simulator(a.liggghts), (("liggghts.in", "liggghts"),)),
             ("yade", dem_yade_check.simulator(a.yade), (("yade_fragment.py", "yade"),)))
    worst = {}
    for n in [int(s) for s in a.steps.split(",")]:
        for code, simulate, fragments in codes:
            if code not in a.codes.split(","):
                continue
            for phase in [float(p) for p in a.phases.split(",")]:
                out = os.path.join(work, "%s_%d_%g" % (code, n, phase))
                os.makedirs(out, exist_ok=True)
                _, _, by_law = case_rows(a.corlab, out, code, simulate, fragments, lambda k: k,
                                         steps_per_contact=n, phase=phase, cases=cases)
                for law, err in by_law.items():
                    worst.setdefault(law, {})[n] = max(worst.get(law, {}).get(n, 0.0), err)
                    print("N = %5d phase %.2f  %-45s worst |e_code - e_law| = %.2e"
                          % (n, phase, law, err), flush=True)
    print("\nsmallest N with worst |e_code - e_law| <= 1e-3 at N and at N/2:")
    for law, errs in worst.items():
        ok = [n for n in sorted(errs) if errs[n] <= 1e-3 and errs.get(n // 2, 1.0) <= 1e-3]
        found = ("N = %d (%.2e; N/2: %.2e)" % (ok[0], errs[ok[0]], errs[ok[0] // 2])
                 if ok else "none (%s)" % errs)
        print("  %-45s %s" % (law, found))


if __name__ == "__main__":
    main()
