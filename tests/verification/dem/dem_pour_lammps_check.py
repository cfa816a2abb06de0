#!/usr/bin/env python3
"""A real pour in LAMMPS (Debian's `lmp`, never mocked) from a `corlab dem` export (issue 41).

Two particle types (60 each, radii 4 and 5 mm, soft so that the export's step is large) are poured
with `fix pour` (one per type, into the fragment's group corlab_typeN, as its comments say) from
z <= 0.2 m onto the fix wall/gran floor z = 0 of a laterally periodic box, and run for 0.4 s of
simulated time at the fragment's own time step; lammps.in is included unedited. Checks: LAMMPS's
neighbour list cutoff at least 2 r_max (the farthest contact; without the fragment's cutoff this
LAMMPS takes 2 x 4 mm + skin, and stiff particles meeting at deep overlap blow up); then, on the
thermo output every 2000 steps, all 120 atoms inserted and none lost; the largest speed below
1.1 x the free-fall speed from the top of the insertion region (a collision may pass some energy
between particles; a blow-up reaches tens of m/s); no atom centre below half the smallest radius
(none through the floor); the final kinetic energy below 1% of its peak (the bed settles).
usage: dem_pour_lammps_check.py CORLAB_BIN LMP_BIN WORK_DIR
"""
# SPDX-License-Identifier: BSD-3-Clause
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dem_check_common import export, run  # noqa: E402

TYPES = ("soft_a=E=5e6,nu=0.3,rho=1000:0.004", "soft_b=E=1e7,nu=0.3,rho=2000:0.005")
WALL = "soft_wall=E=2e7,nu=0.3,rho=2000"
PER_TYPE = 60
HALF_WIDTH = 0.04  # m, the box is [-0.04, 0.04]^2 laterally
Z_TOP = 0.2  # m, top of the insertion regions
SIM_TIME = 0.4  # s
G = 9.81  # m/s^2
COLUMNS = ("step", "atoms", "ke", "vmax", "zmin")


def pour_input(fragment, data):
    w = HALF_WIDTH
    lines = ["units si", "atom_style sphere", "boundary p p f", "comm_modify vel yes",
             "region box block -%g %g -%g %g -0.01 0.25" % (w, w, w, w),
             "create_box %d box" % len(data["types"]), "include %s" % fragment,
             "fix grav all gravity %g vector 0 0 -1" % G, "fix nve all nve/sphere"]
    for k, t in enumerate(data["types"]):
        x0 = -w if k == 0 else 0.0  # type 1 in x < 0, type 2 in x > 0
        lines += ["region corlab_in%d block %g %g %g %g 0.05 %g units box"
                  % (k + 1, x0 + 0.006, x0 + w - 0.006, 0.006 - w, w - 0.006, Z_TOP),
                  "fix pour%d corlab_type%d pour %d %d %d region corlab_in%d diam one %.9g "
                  "dens %.9g %.9g vel 0 0 0 0 0"
                  % (k + 1, k + 1, PER_TYPE, k + 1, 1234 + k, k + 1, 2 * t["radius_m"],
                     t["density_kg_per_m3"], t["density_kg_per_m3"])]
    steps = int(math.ceil(SIM_TIME / data["time_step_s"]["lammps"]))
    lines += ["compute ke all ke", "variable speed atom sqrt(vx*vx+vy*vy+vz*vz)",
              "compute vmax all reduce max v_speed", "compute zmin all reduce min z",
              "thermo_style custom step atoms c_ke c_vmax c_zmin",
              "thermo_modify lost ignore norm no", "thermo 2000", "run %d" % steps]
    return "\n".join(lines) + "\n"


def thermo_rows(out):
    rows, on = [], False
    for line in out.splitlines():
        words = line.split()
        if words[:2] == ["Step", "Atoms"]:
            on = True
        elif on and len(words) == len(COLUMNS):
            try:
                rows.append(dict(zip(COLUMNS, map(float, words))))
            except ValueError:
                on = False
        elif on and words[:1] == ["Loop"]:
            on = False
    return rows


def main():
    corlab, lmp, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    args = ["--wall", WALL, "--restitution", "0.5", "--friction", "0.3", "--v-max", "2"]
    for t in TYPES:
        args += ["--type", t]
    data = export(corlab, work, args)
    path = os.path.join(work, "in.pour")
    with open(path, "w") as f:
        f.write(pour_input(os.path.join(work, "lammps.in"), data))
    out = run([lmp, "-in", path, "-log", "none", "-echo", "none"], cwd=work).stdout
    rows = thermo_rows(out)
    cutoff = min((float(line.split("=")[1]) for line in out.splitlines()
                  if "master list distance cutoff" in line), default=0.0)
    rows = [r for r in rows if r["atoms"] > 0]  # before the first insertion: no atoms
    if not rows:
        print("dem_pour_lammps_check: no thermo output")
        return 1
    r_min = min(t["radius_m"] for t in data["types"])
    v_bound = 1.1 * math.sqrt(2.0 * G * Z_TOP)
    peak_ke = max(r["ke"] for r in rows)
    r_max = max(t["radius_m"] for t in data["types"])
    checks = (
        ("neighbour list cutoff [m]", cutoff, ">= %.4g" % (2 * r_max), cutoff >= 2 * r_max),
        ("atoms at the end", rows[-1]["atoms"], "== %d" % (2 * PER_TYPE),
         rows[-1]["atoms"] == 2 * PER_TYPE),
        ("max speed [m/s]", max(r["vmax"] for r in rows), "< %.4g" % v_bound,
         max(r["vmax"] for r in rows) < v_bound),
        ("lowest centre z [m]", min(r["zmin"] for r in rows), ">= %.4g" % (0.5 * r_min),
         min(r["zmin"] for r in rows) >= 0.5 * r_min),
        ("final / peak kinetic energy", rows[-1]["ke"] / peak_ke, "< 0.01",
         rows[-1]["ke"] < 0.01 * peak_ke),
    )
    failures = 0
    for name, value, rule, ok in checks:
        failures += not ok
        print("%-30s %-12.6g %-10s %s" % (name, value, rule, "ok" if ok else "FAIL"))
    print("dem_pour_lammps_check: %d failure(s)" % failures)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
