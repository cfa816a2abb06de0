#!/usr/bin/env python3
"""Real-code check of lammps_compiled.in (issue 41): the e(v) damping of fix corlab/ev, compiled
into corlab-lammps (Debian's LAMMPS as a library), in the drop tests of dem_lammps_check.py at
the export's stated step and at twice it: e within the time-step error (1e-3) of the law (the
same law as lammps.in's Python hook) and within the stated max |de| + 1e-3 of the target.
Then one head-on drop (glass on copper, 4 m/s) where the contact is seen through a ghost atom:
across a periodic boundary, with newton off, and (where mpirun is) on two MPI ranks split
between the particles: each e equal to the plain serial run's within 1e-9.
usage: dem_lammps_compiled_check.py CORLAB_BIN CORLAB_LAMMPS_BIN WORK_DIR [--report FILE]
"""
# SPDX-License-Identifier: BSD-3-Clause
import copy
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dem_check_common import EV_CASES, Drop, case_rows, export, finish, parse_e  # noqa: E402
from dem_lammps_check import lammps_input, simulator  # noqa: E402


def scaled(simulate, factor):
    """`simulate` at `factor` times the drop's step: the gap scales with it (the contact starts
    at the same phase of a step); the steps run stay enough (fewer are needed)."""
    def run_scaled(out, fragment, drop):
        d = copy.copy(drop)
        d.dt, d.gap = drop.dt * factor, drop.gap * factor
        return simulate(out, fragment, d)
    return run_scaled


def ghost_rows(corlab, binary, work):
    """(rows, failures) of the ghost-atom runs. The particles lie at x < 0 and x > 0: two ranks
    (processors 2 1 1) split the box [-8r, 8r] at x = 0 between them, and the periodic box
    [0, 16r] puts the first one's image at x < 16r, its contact across x = 0."""
    args = next(c[1] for c in EV_CASES if c[0] == "glass_copper_spheres")
    out = os.path.join(work, "ghosts")
    data = export(corlab, out, args)
    pair = next(p for p in data["pairs"] if p["pair"] == "1-2")
    drop = Drop(data, pair, "pair", 4.0, data["time_step_s"]["lammps"])
    plain = lammps_input(os.path.join(out, "lammps_compiled.in"), drop)
    r = 8 * drop.radius
    box = "region box block 0 %.12g -%.12g %.12g -%.12g %.12g" % (2 * r, r, r, r, r)
    periodic = "\n".join(
        "boundary p f f" if line == "boundary f f f" else box if line.startswith("region box")
        else line + " remap yes" if line.startswith("create_atoms") else line
        for line in plain.split("\n"))
    newton_off = plain.replace("comm_modify vel yes", "comm_modify vel yes\nnewton off")
    runs = [("periodic x (the contact through an image)", periodic, []),
            ("newton off", newton_off, []),
            ("periodic x, newton off",
             periodic.replace("comm_modify vel yes", "comm_modify vel yes\nnewton off"), [])]
    mpirun = shutil.which("mpirun")
    if mpirun:
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        for label, text in (("2 MPI ranks", plain), ("2 MPI ranks, periodic x", periodic)):
            text = text.replace("comm_modify vel yes", "processors 2 1 1\ncomm_modify vel yes")
            runs.append((label, text, [mpirun, "--oversubscribe", "-np", "2"]))
    else:
        env = None

    def e_of(text, prefix):
        path = os.path.join(out, "in.ghost")
        with open(path, "w") as f:
            f.write(text)
        return parse_e(subprocess.run(prefix + [binary, "-in", path, "-log", "none", "-echo",
                                                "none"], check=True, capture_output=True,
                                      text=True, env=env).stdout)

    want = e_of(plain, [])
    rows, failures = [], 0
    for label, text, prefix in runs:
        e = e_of(text, prefix)
        ok = abs(e - want) <= 1e-9
        failures += not ok
        rows.append("ghosts %-44s e=%.12f serial=%.12f %s"
                    % (label, e, want, "ok" if ok else "FAIL"))
    return rows, failures


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
    more, bad = ghost_rows(corlab, binary, work)
    rows += more
    failures += bad
    return finish("dem_lammps_compiled_check", rows, failures, report)


if __name__ == "__main__":
    sys.exit(main())
