"""The report's oblique-impact section (issue 27): corlab's 3-D FE on Kharaz, Gorham & Salman's
(2001) alumina sphere on glass against the measured points and the three DEM codes, from the files
data/kharaz2001 ships (fe_oblique.csv, measured_points.csv, dem_oblique.csv; its README says how
each was made), and the elastic-plastic studies of data/oblique_studies. Nothing is computed
here: figures and a table of those files' numbers."""
# SPDX-License-Identifier: BSD-3-Clause
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from .figures import num  # noqa: E402  (an empty cell: no value, nan)
from .html_table import esc, fmt, table  # noqa: E402

#: (fe_oblique.csv column, measured_points.csv quantity, dem_oblique.csv column, axis label)
QUANTITIES = (("e_t", "e_t", "e_t", "e_t = v_t'/v_t [-]"),
              ("omega", "omega", "omega_rad_s", "rebound spin ω [rad/s]"))


def _rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def _series(rows, x, y, keep=lambda r: True):
    points = sorted((num(r[x]), num(r[y])) for r in rows if keep(r) and not math.isnan(num(r[y])))
    return [p[0] for p in points], [p[1] for p in points]


def oblique_figure(fe, measured, dem, path):
    """e_t and omega against the impact angle: FE with its error bars, both digitisations of the
    measurements, each DEM code."""
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, (fe_key, quantity, dem_key, label) in zip(axes, QUANTITIES):
        for source in sorted({r["source"] for r in measured}):
            ax.plot(*_series(measured, "impact_angle_deg", "value",
                             lambda r: r["source"] == source and r["quantity"] == quantity),
                    "o", mfc="none", label=f"measured ({source})")
        for code in sorted({r["code"] for r in dem}):
            ax.plot(*_series(dem, "angle_deg", dem_key, lambda r: r["code"] == code), "-",
                    lw=1, label=f"DEM: {code}")
        angles = [num(r["impact_angle_deg"]) for r in fe]
        ax.errorbar(angles, [num(r[fe_key]) for r in fe],
                    yerr=[num(r[fe_key + "_error"]) for r in fe], fmt="s-", color="k",
                    ms=4, capsize=2, label="corlab 3-D FE")
        ax.set_xlabel("impact angle from the normal [deg]")
        ax.set_ylabel(label)
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def study_figure(rows, title, path):
    """e_n, e_t and omega against the impact angle, one line per impact speed, with error bars."""
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.8))
    speeds = sorted({num(r["impact_velocity"]) for r in rows})
    for ax, key, label in zip(axes, ("e_n", "e_t", "omega"),
                              ("e_n [-]", "e_t [-]", "rebound spin ω [rad/s]")):
        for v in speeds:
            mine = sorted((num(r["impact_angle_deg"]), num(r[key]),
                           num(r[key + "_error" if key != "e_n" else "e_n_error"]))
                          for r in rows
                          if num(r["impact_velocity"]) == v and not math.isnan(num(r[key])))
            if mine:
                ax.errorbar(*zip(*mine), fmt="o-", ms=3, capsize=2, label=f"{v:g} m/s")
        ax.set_xlabel("impact angle from the normal [deg]")
        ax.set_ylabel(label)
    axes[0].legend(fontsize=8)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def studies_section(data_dir, out_dir):
    """HTML: a figure per table of data/oblique_studies (the elastic-plastic oblique studies)."""
    folder = os.path.join(data_dir, "oblique_studies")
    try:
        names = sorted(n for n in os.listdir(folder) if n.endswith(".csv"))
    except OSError:
        names = []
    if not names:
        return "<p><i>No elastic-plastic oblique tables found (data/oblique_studies).</i></p>"
    os.makedirs(os.path.join(out_dir, "figures"), exist_ok=True)
    parts = []
    for name in names:
        stem = name[:-4]
        try:
            study_figure(_rows(os.path.join(folder, name)), stem,
                         os.path.join(out_dir, "figures", f"oblique_{stem}.png"))
            parts.append(f'<p><img src="figures/oblique_{esc(stem)}.png" alt="{esc(stem)}"></p>')
        except Exception as err:  # a broken figure must not lose the rest of the report
            print(f"corlab.report: oblique figure {stem} failed: {err}", file=sys.stderr)
    return (f"<p>The elastic-plastic oblique studies of <code>{esc(folder)}</code> (its README: "
            "materials, friction, mesh and how each table was made).</p>" + "".join(parts))


def oblique_section(data_dir, out_dir):
    """HTML: the Kharaz comparison, or a note when data/kharaz2001 lacks the tables."""
    folder = os.path.join(data_dir, "kharaz2001")
    try:
        fe = _rows(os.path.join(folder, "fe_oblique.csv"))
        measured = _rows(os.path.join(folder, "measured_points.csv"))
        dem = _rows(os.path.join(folder, "dem_oblique.csv"))
    except OSError:
        return "<p><i>No oblique-impact tables found (data/kharaz2001).</i></p>"
    figure = ""
    try:
        os.makedirs(os.path.join(out_dir, "figures"), exist_ok=True)
        oblique_figure(fe, measured, dem, os.path.join(out_dir, "figures", "kharaz2001.png"))
        figure = ('<p><img src="figures/kharaz2001.png" alt="e_t and omega against the impact '
                  'angle: FE, measurements, DEM"></p>')
    except Exception as err:  # a broken figure must not lose the rest of the report
        print(f"corlab.report: oblique figure failed: {err}", file=sys.stderr)
    rows = [[fmt(num(r["impact_angle_deg"]), 3),
             f"{fmt(num(r['e_t']), 4)} ± {fmt(num(r['e_t_error']), 2)}",
             f"{fmt(num(r['omega']), 4)} ± {fmt(num(r['omega_error']), 2)}",
             fmt(num(r["rebound_angle_com"]), 4), fmt(num(r["e_n"]), 4)] for r in fe]
    head = ["angle [deg]", "e_t", "ω [rad/s]", "rebound angle [deg]", "e_n"]
    return f"""<p>corlab's 3-D model (docs/theory/solver3d.md) on the alumina sphere and glass
anvil of Kharaz, Gorham &amp; Salman (2001) at 3.9 m/s with their measured friction, beside the
measured points (two independent digitisations) and LAMMPS, LIGGGHTS and YADE run with corlab's
export (<code>{esc(folder)}</code>, its README). The FE's error bars come from its coarser
companion meshes. From 20&deg; up the FE follows the measurements; below 15&deg; it rebounds with
less tangential velocity than measured (docs/theory/solver3d.md discusses why).</p>
{figure}
{table(head, rows)}
<h3>Elastic-plastic oblique impacts</h3>
{studies_section(data_dir, out_dir)}"""
