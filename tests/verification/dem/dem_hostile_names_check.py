#!/usr/bin/env python3
"""Generated DEM scripts hold file names as data, never as code (issue 42), in the real codes.

FE tables are copied to files whose names would be commands in LAMMPS, LIGGGHTS or YADE (a line
break then `shell touch PWNED`, Python's `__import__("os").system(...)`, quotes, `$`, `&`, `#`,
`\"\"\"`, unicode). `corlab dem --table NAME --pair-table 1/wall=NAME2` and
`corlab.dem.export(table_source=NAME)` export them; each fragment then runs a drop test in Debian's
lmp, liggghts and yade (never mocked) from a scratch directory. Nothing but the intended commands
may run: no PWNED file appears, and every run gives the very e of the same export with plain names.
With --corlab-lammps BIN the CLI's lammps_compiled.in runs too (in corlab-lammps).
usage: dem_hostile_names_check.py CORLAB_BIN LMP_BIN LIGGGHTS_BIN YADE_BIN WORK_DIR
       [--corlab-lammps BIN]   (PYTHONPATH: the built corlab package)
"""
# SPDX-License-Identifier: BSD-3-Clause
import json
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dem_check_common import FE_TABLE, Drop, run  # noqa: E402
import dem_lammps_check  # noqa: E402
import dem_liggghts_check  # noqa: E402
import dem_yade_check  # noqa: E402

HOSTILE = (
    "x\nshell touch PWNED\n.csv",
    'z\n__import__("os").system("touch PWNED")\n#.csv',
    "q'); __import__('os').system('touch PWNED'); ('\"\"\"\nshell touch PWNED &",
    "v ${PWNED} $(touch PWNED) `touch PWNED` # r\u00e9sultats \u2028.csv",
)
# (file, simulator, its key in dem_export.json time_step_s)
FRAGMENTS = (("lammps.in", "lammps", "lammps"),
             ("lammps_nopython.in", "lammps_nopython", "lammps_nopython"),
             ("liggghts.in", "liggghts", "liggghts"), ("yade_fragment.py", "yade", "yade"))
COMPILED = (("lammps_compiled.in", "lammps_compiled", "lammps"),)
EXPORT = ["--type", "alumina_ma2023:0.005", "--wall", "aluminium_ma2023", "--v-min", "0.3",
          "--v-max", "3"]


def drop_e(simulators, out, fragments):
    """e of a 1 m/s drop of type 1 on the wall with each of `fragments` of the export in `out`."""
    with open(os.path.join(out, "dem_export.json")) as f:
        data = json.load(f)
    pair = next(p for p in data["pairs"] if p["pair"] == "1-wall")
    got = {}
    for name, key, step in fragments:
        try:
            got[name] = simulators[key](out, name, Drop(data, pair, "wall", 1.0,
                                                        data["time_step_s"][step]))
        except (subprocess.CalledProcessError, UnicodeDecodeError, RuntimeError) as failed:
            # a name broke the script: the code failed, printed no e, or printed bytes
            print("%s/%s: the run failed: %s" % (out, name, str(failed)[-300:]))
            got[name] = None
    return got


def cli_export(corlab, out, table, pair_table):
    run([corlab, "dem", *EXPORT, "--table", table, "--pair-table", "1/wall=" + pair_table,
         "--out", out])


def python_export(out, table_source):
    import corlab
    import corlab.dem
    t = corlab.read_results(FE_TABLE)
    files = corlab.dem.export([("alumina_ma2023", 0.005)], wall="aluminium_ma2023", v_min=0.3,
                              v_max=3.0, table=(t["velocity"], t["e"]), table_source=table_source)
    os.makedirs(out)
    for key, name in (("lammps", "lammps.in"), ("lammps_nopython", "lammps_nopython.in"),
                      ("liggghts", "liggghts.in"), ("yade", "yade_fragment.py"),
                      ("json", "dem_export.json")):
        with open(os.path.join(out, name), "w") as f:
            f.write(files[key])


def main():
    corlab, lmp, liggghts, yade, work = sys.argv[1:6]
    shutil.rmtree(work, ignore_errors=True)
    tables, scratch = os.path.join(work, "tables"), os.path.join(work, "cwd")
    os.makedirs(tables)
    os.makedirs(scratch)
    os.chdir(scratch)  # an injected `touch PWNED` of lmp or liggghts lands here
    simulators = {"lammps": dem_lammps_check.simulator(lmp),
                  "lammps_nopython": dem_lammps_check.simulator(lmp),
                  "liggghts": dem_liggghts_check.simulator(liggghts),
                  "yade": dem_yade_check.simulator(yade)}
    cli_fragments = FRAGMENTS
    if "--corlab-lammps" in sys.argv:
        binary = sys.argv[sys.argv.index("--corlab-lammps") + 1]
        simulators["lammps_compiled"] = dem_lammps_check.simulator(binary)
        cli_fragments += COMPILED
    names = []
    for name in HOSTILE:
        path = os.path.join(tables, name)
        shutil.copy(FE_TABLE, path)
        names.append(path)
    plain = os.path.join(work, "plain")
    cli_export(corlab, plain, FE_TABLE, FE_TABLE)
    expected = drop_e(simulators, plain, cli_fragments)
    python_plain = os.path.join(work, "python_plain")
    python_export(python_plain, "fe.csv")
    python_expected = drop_e(simulators, python_plain, FRAGMENTS)
    failures = 0
    outs = []
    for k in range(0, len(names), 2):
        out = os.path.join(work, "cli_%d" % k)
        cli_export(corlab, out, names[k], names[k + 1])
        outs.append((out, expected, cli_fragments))
    for k, name in enumerate(HOSTILE):
        out = os.path.join(work, "python_%d" % k)
        python_export(out, name)
        outs.append((out, python_expected, FRAGMENTS))
    for out, want, fragments in outs:
        got = drop_e(simulators, out, fragments)
        for name, *_ in fragments:
            ok = got[name] == want[name]
            failures += not ok
            print("%-24s %-20s e = %s (plain names: %.9f) %s"
                  % (os.path.basename(out), name, got[name], want[name], "ok" if ok else "FAIL"))
    for where in (scratch, work, *(out for out, *_ in outs)):
        if os.path.exists(os.path.join(where, "PWNED")):
            print("FAIL: %s/PWNED exists: a name ran as a command" % where)
            failures += 1
    print("dem_hostile_names_check: %d failure(s)" % failures)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
