#!/usr/bin/env python3
"""Figures and tables of the DEM hand-off (docs/theory/dem_contact_laws.md, docs/user/dem.md).

  exactness: delivered e of each published chi(e) formula over e in [0.05, 0.99] (closed form
             of the exact relation, checked against ODE in the tests) -> markdown table + figure
  bounce:    a ball (alumina, R = 5 mm) dropped on an aluminium plate in LAMMPS, with a constant e
             and with corlab's e(v) (thornton1997 via damping viscoelastic) -> rebound heights
Regenerate (from the repository root, after `make build`):
  PYTHONPATH=build/python python3 scripts/dem_figures.py exactness --out docs/img
  PYTHONPATH=build/python python3 scripts/dem_figures.py bounce --corlab build/bin/corlab \
      --lmp lmp --liggghts liggghts --out docs/img
"""
# SPDX-License-Identifier: BSD-3-Clause
import argparse
import json
import math
import os
import subprocess
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import corlab  # noqa: E402

MAX_REBOUNDS = 12
LABELS = {"hunt_crossley": "Hunt-Crossley 1975",
          "lankarani_nikravesh": "Lankarani-Nikravesh 1990",
          "flores": "Flores et al. 2011", "gonthier": "Gonthier et al. 2004",
          "hu_guo": "Hu-Guo 2015", "carvalho_martins": "Carvalho-Martins 2019"}


def delivered_e(name, e):
    """e delivered by the published chi(e) formula `name` at target e."""
    return float(corlab.dem.exact_restitution(corlab.dem.published_chi(name, e)))


def exactness(out):
    e = np.linspace(0.05, 0.99, 189)
    rows = ["| formula | delivered e at 0.1 / 0.3 / 0.5 / 0.7 / 0.9 "
            "| max abs error of e over [0.05, 0.99] (at e) |",
            "|---|---|---|"]
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for name in corlab.dem.chi_formulas():
        delivered = np.array([delivered_e(name, x) for x in e])
        err = delivered - e
        i = int(np.argmax(np.abs(err)))
        at = [delivered_e(name, x) for x in (0.1, 0.3, 0.5, 0.7, 0.9)]
        rows.append("| %s | %s | %.3f (e = %.2f) |"
                    % (LABELS[name], " / ".join("%.3f" % a for a in at), abs(err[i]), e[i]))
        ax.plot(e, err, label=LABELS[name])
    ax.axhline(0.0, color="k", lw=0.8)
    ax.set_xlabel("target e")
    ax.set_ylabel("delivered e - target e")
    ax.set_title("F = K d^n (1 + chi d'/v_in): published chi(e) vs exact")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    path = os.path.join(out, "dem_chi_exactness.png")
    fig.savefig(path, dpi=130)
    print("\n".join(rows))
    print("wrote", path)


def lammps_bounce(lmp, fragment, radius, density, h0, t_end, dt, work, tag):
    lines = ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f",
             "comm_modify vel yes",
             "region box block -0.05 0.05 -0.05 0.05 -0.001 %g" % (h0 + 0.05), "create_box 1 box",
             "create_atoms 1 single 0 0 %.12g" % (h0 + radius),
             "set atom 1 diameter %.12g density %.12g" % (2 * radius, density),
             "include %s" % fragment, "fix g all gravity 9.81 vector 0 0 -1",
             "fix nve all nve/sphere",
             "timestep %g" % dt, "variable t equal time", "variable z equal z[1]-%.12g" % radius,
             "variable vz equal vz[1]",
             "fix p all print 200 \"${t} ${z} ${vz}\" file %s screen no"
             % os.path.join(work, tag + ".txt"),
             "thermo 0", "run %d" % int(t_end / dt)]
    path = os.path.join(work, "in." + tag)
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    subprocess.run([lmp, "-in", path, "-log", "none", "-screen", "none"], check=True)
    data = np.loadtxt(os.path.join(work, tag + ".txt"), comments="#")
    return data[:, 0], data[:, 1], data[:, 2]


def liggghts_bounce(liggghts, fragment, radius, density, h0, t_end, dt, work, tag):
    lines = ["atom_style granular", "atom_modify map array", "boundary f f f", "newton off",
             "communicate single vel yes", "units si", "hard_particles yes",
             "region reg block -0.05 0.05 -0.05 0.05 -0.00001 %g units box" % (h0 + 0.05),
             "create_box 2 reg", "neighbor 0.001 bin", "neigh_modify delay 0",
             "include %s" % fragment,
             "create_atoms 1 single 0 0 %.12g units box" % (h0 + radius),
             "set atom 1 diameter %.12g density %.12g" % (2 * radius, density),
             "fix g all gravity 9.81 vector 0 0 -1", "fix nve all nve/sphere", "timestep %g" % dt,
             "variable t equal time", "variable z equal z[1]-%.12g" % radius,
             "variable vz equal vz[1]",
             "fix p all print 200 \"${t} ${z} ${vz}\" file %s screen no"
             % os.path.join(work, tag + ".txt"),
             "thermo 1000000", "run %d" % int(t_end / dt)]
    path = os.path.join(work, "in." + tag)
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    subprocess.run([liggghts, "-in", path, "-log", "none", "-echo", "none"], check=True,
                   capture_output=True, cwd=work)
    data = np.loadtxt(os.path.join(work, tag + ".txt"), comments="#")
    return data[:, 0], data[:, 1], data[:, 2]


def apexes(t, z, vz):
    """Heights of the rebound apexes (vz changes sign from + to -)."""
    idx = np.where((vz[:-1] > 0) & (vz[1:] <= 0))[0]
    return z[idx][z[idx] > 1e-6][:MAX_REBOUNDS]


def bounce(corlab_bin, lmp, liggghts, out):
    radius, h0 = 0.005, 0.2
    v0 = math.sqrt(2 * 9.81 * h0)
    work = tempfile.mkdtemp(prefix="corlab_bounce_")
    subprocess.run([corlab_bin, "dem", "--type", "alumina_ma2023:%g" % radius,
                    "--wall", "aluminium_ma2023", "--wall-only", "--model", "thornton1997",
                    "--v-min", "0.2", "--v-max", "%.3f" % v0,
                    "--out", os.path.join(work, "ev")], check=True, capture_output=True)
    with open(os.path.join(work, "ev", "dem_export.json")) as f:
        pair = json.load(f)["pairs"][0]
    density = pair["effective_mass_kg"] / (4.0 / 3.0 * math.pi * radius ** 3)
    e_first = float(corlab.predict("thornton1997", "alumina_ma2023", "aluminium_ma2023", v0))
    subprocess.run([corlab_bin, "dem", "--type", "alumina_ma2023:%g" % radius,
                    "--wall", "aluminium_ma2023", "--wall-only", "--restitution", "%.6f" % e_first,
                    "--out", os.path.join(work, "const")],
                   check=True, capture_output=True)
    frag_const = os.path.join(work, "const", "lammps.in")
    # wall-only fragments have no pair_style; a single ball needs none.
    t_end, dt = 1.2, 1e-7
    res = {}
    for tag, frag in (("const", frag_const), ("ev", os.path.join(work, "ev", "lammps.in"))):
        t, z, vz = lammps_bounce(lmp, frag, radius, density, h0, t_end, dt, work, tag)
        res[tag] = (t, z, apexes(t, z, vz))
    if liggghts:
        t, z, vz = liggghts_bounce(liggghts, os.path.join(work, "ev", "liggghts.in"), radius,
                                   density, h0, t_end, dt, work, "lig")
        res["lig"] = (t, z, apexes(t, z, vz))
    # corlab's own e(v) sequence: h_{n+1} = h_n e(v_n)^2, v_n = sqrt(2 g h_n)
    h, seq = h0, []
    for _ in range(MAX_REBOUNDS):
        v = math.sqrt(2 * 9.81 * h)
        h = h * float(corlab.predict("thornton1997", "alumina_ma2023", "aluminium_ma2023", v)) ** 2
        seq.append(h)
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.2))
    a1.plot(res["const"][0], res["const"][1] * 1e3, lw=0.8,
            label="LAMMPS, constant e = %.3f" % e_first)
    a1.plot(res["ev"][0], res["ev"][1] * 1e3, lw=0.8,
            label="LAMMPS, corlab e(v) (viscoelastic fit)")
    a1.set_xlabel("time [s]")
    a1.set_ylabel("ball bottom height [mm]")
    if "lig" in res:
        a1.plot(res["lig"][0], res["lig"][1] * 1e3, lw=0.8,
                label="LIGGGHTS, corlab e(v) (thornton_ning fit)")
    a1.legend(fontsize=8)
    for tag, lab, mk in (("const", "LAMMPS constant e", "o"),
                         ("ev", "LAMMPS corlab e(v) (viscoelastic)", "s"),
                         ("lig", "LIGGGHTS corlab e(v) (thornton_ning)", "^")):
        if tag not in res:
            continue
        a2.semilogy(np.arange(1, len(res[tag][2]) + 1), res[tag][2] * 1e3, mk, label=lab)
    a2.semilogy(np.arange(1, len(seq) + 1), np.array(seq) * 1e3, "k--",
                label="thornton1997 e(v) (exact sequence)")
    a2.set_xlabel("rebound number")
    a2.set_ylabel("apex height [mm]")
    a2.legend(fontsize=8)
    a2.grid(alpha=0.3, which="both")
    fig.suptitle("Alumina ball (R = 5 mm) dropped from %.0f mm on aluminium: "
                 "constant e vs corlab e(v)" % (h0 * 1e3))
    fig.tight_layout()
    path = os.path.join(out, "dem_bouncing_ball.png")
    fig.savefig(path, dpi=130)
    for tag in res:
        print(tag, "apex heights [mm]:", " ".join("%.2f" % (x * 1e3) for x in res[tag][2]))
    print("exact thornton1997 sequence [mm]:", " ".join("%.2f" % (x * 1e3) for x in seq))
    print("wrote", path)


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("what", choices=["exactness", "bounce"])
    p.add_argument("--out", default="docs/img")
    p.add_argument("--corlab", default="build/bin/corlab")
    p.add_argument("--lmp", default="lmp")
    p.add_argument("--liggghts", default="", help="also run the LIGGGHTS thornton_ning route")
    a = p.parse_args()
    if a.what == "exactness":
        exactness(a.out)
    else:
        bounce(a.corlab, a.lmp, a.liggghts, a.out)


if __name__ == "__main__":
    main()
