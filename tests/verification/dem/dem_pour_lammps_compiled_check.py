#!/usr/bin/env python3
"""The pour of dem_pour_lammps_check.py with e(v) at native speed (issue 41): every pair and wall
of the export follows corlab's FE e(v) of alumina on aluminium (--table), lammps_compiled.in is
included unedited and run by corlab-lammps (Debian's LAMMPS with corlab's compiled fix
corlab/ev). The checks of dem_pour_common.check, with the energy bound (kinetic + gravitational
energy never above its start) for the speed bound, which an e near 1 may pass; the e of each
first side-wall contact against the target e(v_in) within the stated max |de| + the time-step
error.
usage: dem_pour_lammps_compiled_check.py CORLAB_BIN CORLAB_LAMMPS_BIN WORK_DIR [--report FILE]
"""
# SPDX-License-Identifier: BSD-3-Clause
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dem_check_common import FE_TABLE, run  # noqa: E402
from dem_pour_common import check, dump_samples, pour_export, thermo_rows, work_file  # noqa: E402
from dem_pour_lammps_check import pour_input  # noqa: E402

TARGET = ["--table", FE_TABLE, "--v-min", "0.1", "--v-max", "2"]


def main():
    corlab, binary, work = sys.argv[1:4]
    report = sys.argv[sys.argv.index("--report") + 1] if "--report" in sys.argv else None
    data = pour_export(corlab, work, target=TARGET)
    text, _ = pour_input(os.path.join(work, "lammps_compiled.in"), data)
    path = work_file(work, "in.pour")
    with open(path, "w") as f:
        f.write(text)
    out = run([binary, "-in", path, "-log", "none", "-echo", "none"], cwd=work).stdout
    failures = check("dem_pour_lammps_compiled_check", "lammps", data, thermo_rows(out),
                     dump_samples(os.path.join(work, "dump.pour")), report, energy=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
