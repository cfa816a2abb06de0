#!/usr/bin/env python3
"""Real-code check of lammps_compiled.in (issue 41): the e(v) damping of fix corlab/ev, compiled
into corlab-lammps (Debian's LAMMPS as a library), in the drop tests of dem_lammps_check.py at
the export's stated step and at twice it: e within the time-step error (1e-3) of the law (the
same law as lammps.in's Python hook) and within the stated max |de| + 1e-3 of the target.
usage: dem_lammps_compiled_check.py CORLAB_BIN CORLAB_LAMMPS_BIN WORK_DIR [--report FILE]
"""
# SPDX-License-Identifier: BSD-3-Clause
import copy
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dem_check_common import case_rows, finish  # noqa: E402
from dem_lammps_check import simulator  # noqa: E402


def scaled(simulate, factor):
    """`simulate` at `factor` times the drop's step: the gap scales with it (the contact starts
    at the same phase of a step); the steps run stay enough (fewer are needed)."""
    def run_scaled(out, fragment, drop):
        d = copy.copy(drop)
        d.dt, d.gap = drop.dt * factor, drop.gap * factor
        return simulate(out, fragment, d)
    return run_scaled


def main():
    corlab, binary, work = sys.argv[1:4]
    report = sys.argv[sys.argv.index("--report") + 1] if "--report" in sys.argv else None
    rows, failures = [], 0
    for factor in (1, 2):
        out = os.path.join(work, "step_x%d" % factor)
        os.makedirs(out, exist_ok=True)
        more, bad, _ = case_rows(corlab, out, "lammps", scaled(simulator(binary), factor),
                                 (("lammps_compiled.in", "lammps"),), lambda key: key)
        rows += ["step x%d %s" % (factor, row) for row in more]
        failures += bad
    return finish("dem_lammps_compiled_check", rows, failures, report)


if __name__ == "__main__":
    sys.exit(main())
