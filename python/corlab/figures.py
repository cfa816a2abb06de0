"""Figures of the reproduction report: our versions of Ma et al. (2023) Figs. 2-13.

Every function takes the report directory (the output of ``corlab reproduce``) and the parsed
``fit.json``, writes one PNG into ``<dir>/figures`` and returns its file name, or ``None`` when
the data for it are missing (the report then says so). Axes carry SI units (mm, us and kN where
those read better). No experimental points are drawn (docs/reference models.md section 7). Every
model line and reference value comes from fit.json (the C++ ``corlab reproduce``: "verification",
"figure_lines", "fits", "paper"); this module holds no formula or published constant: it plots.
"""
# SPDX-License-Identifier: BSD-3-Clause
from __future__ import annotations

import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from .vtu import field_snapshots, read_vtu  # noqa: E402


# Colours and markers of figures with one series per case (Figs. 6 and 9, yield onset): tab10, then
# ten other hues far from tab10 and from each other (not tab20's light shades, which read as
# pairs); and a marker of its own for each of the first 15 cases (Fig. 6's), so that a case is told
# apart by its colour and by its marker alike, in print and for colour-blind readers.
_CASE_MARKERS = ("o", "s", "^", "D", "v", "P", "X", "*", "<", ">", "h", "p", "d", "H", "8")
_SECOND_COLOURS = ("#000000", "#000080", "#800000", "#ff00ff", "#808000", "#0000ff", "#8b008b",
                   "#00a86b", "#2f4f4f", "#6495ed")


def case_style(i):
    """(colour, marker) of case i: 20 colours and 15 markers in turn, so every colour differs for
    i < 20, every marker for i < 15 and every (colour, marker) for i < 60."""
    cycle, k = divmod(i % 20, 10)
    palette = matplotlib.colormaps["tab10"].colors if cycle == 0 else _SECOND_COLOURS
    return matplotlib.colors.to_hex(palette[k]), _CASE_MARKERS[i % len(_CASE_MARKERS)]


def read_csv(path):
    """Rows of a CSV file as dicts (numbers stay text); [] if the file does not exist."""
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def read_columns(path):
    """A numeric CSV (history.csv) as {column: [float]}."""
    rows = read_csv(path)
    if not rows:
        return {}
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def num(x):
    try:
        v = float(x)
    except (TypeError, ValueError):
        return math.nan
    return v


def _save(fig, out_dir, name):
    os.makedirs(os.path.join(out_dir, "figures"), exist_ok=True)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "figures", name), dpi=110)
    plt.close(fig)
    return name


def history_runs(out_dir, study):
    """[(settings dict, history columns, summary dict)] of a history study."""
    import json

    runs = []
    for row in read_csv(os.path.join(out_dir, study, "cases.csv")):
        run_dir = os.path.join(out_dir, study, "runs", row["case_id"])
        summary = os.path.join(run_dir, "summary.json")
        if not os.path.exists(summary):
            continue
        with open(summary) as f:
            s = json.load(f)
        runs.append((row, read_columns(os.path.join(run_dir, "history.csv")), s))
    return runs


def fig2_mesh(out_dir, fit):
    runs = history_runs(out_dir, "verification_mesh")
    if not runs:
        return None
    runs.sort(key=lambda r: -num(r[0].get("mesh.h_min")))
    fig, ax = plt.subplots(1, 3, figsize=(13, 3.8))
    for row, h, s in runs:
        t = [x * 1e6 for x in h["time_s"]]
        label = f"h_min = {num(row['mesh.h_min']) * 1e3:g} mm (e = {s['e']:.4f})"
        ax[0].plot(t, [(d + s["config"]["impact"]["gap"]) * 1e3 for d in h["indentation_m"]],
                   label=label)
        ax[1].plot(t, h["sphere_velocity_m_per_s"], label=label)
        ax[2].plot(t, [f / 1e3 for f in h["contact_force_N"]], label=label)
    ax[0].set_ylabel("sphere displacement [mm]")
    ax[1].set_ylabel("sphere velocity (+ towards substrate) [m/s]")
    ax[2].set_ylabel("normal contact force [kN]")
    for a in ax:
        a.set_xlabel("time [us]")
        a.grid(alpha=0.3)
    ax[2].legend(fontsize=7)
    fig.suptitle("Fig. 2: mesh sizes at 5 m/s (Table 1 materials)")
    return _save(fig, out_dir, "fig02_mesh.png")


def verification_run(fit, case_id):
    """The entry of fit.json's "verification"/"hertz" of one run ({} when there is none)."""
    for r in fit.get("verification", {}).get("hertz", []):
        if r.get("case_id") == case_id:
            return r
    return {}


def _paper(fit, key):
    return num(fit.get("paper", {}).get(key))


def fig3_hertz(out_dir, fit):
    runs = history_runs(out_dir, "verification_hertz")
    if not runs:
        return None
    fig, ax = plt.subplots(figsize=(6.2, 4.4))
    for row, h, s in runs:
        cfg = s["config"]
        elastic = cfg["substrate"]["material"]["sigma_y"] is None
        label = "FE, elastic substrate" if elastic else "FE, elastic-plastic (sigma_y = 500 MPa)"
        ax.plot([d * 1e3 for d in h["indentation_m"]], [f / 1e3 for f in h["contact_force_N"]],
                label=f"{label}, e = {s['e']:.4f}")
        curve = verification_run(fit, row["case_id"]).get("hertz_curve")
        if elastic and curve:
            ax.plot([d * 1e3 for d in curve["delta"]], [f / 1e3 for f in curve["force"]], "k--",
                    label="Hertz: F = 4/3 E* R^1/2 delta^3/2")
    ax.set_xlabel("indentation delta [mm]")
    ax.set_ylabel("contact force F [kN]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    ax.set_title("Fig. 3: contact force vs indentation at 5 m/s")
    return _save(fig, out_dir, "fig03_force_indentation.png")


def _phase(t, h):
    """Which part of the impact t [s] lies in, from the run's history (contact force > 0)."""
    times = [x for x, f in zip(h["time_s"], h["contact_force_N"]) if f > 0]
    if not times:
        return "no contact"
    t_on, t_off = times[0], times[-1]
    t_peak = h["time_s"][max(range(len(h["time_s"])), key=lambda i: h["indentation_m"][i])]
    if t < t_on:
        return "before contact"
    if t > t_off:
        return "after separation"
    if abs(t - t_peak) <= 0.1 * (t_off - t_on):
        return "~max. compression"
    return "loading" if t < t_peak else "unloading"


def fig4_fields(out_dir, fit):
    """Fig. 4: (a) von Mises stress of the elastic impact, (b) of the elastic-plastic impact and
    (c) equivalent plastic strain of the elastic-plastic impact, at each field snapshot of the
    verification_hertz runs (runs/<case>/fields_<t>.vtu), contact region, deformed mesh."""
    import numpy as np
    from matplotlib.collections import PolyCollection

    runs = {}
    for row, h, s in history_runs(out_dir, "verification_hertz"):
        snaps = field_snapshots(os.path.join(out_dir, "verification_hertz", "runs", row["case_id"]))
        if snaps and h:
            elastic = s["config"]["substrate"]["material"]["sigma_y"] is None
            # the zoom: r up to 3 a_max, a_max = (R delta_max)^1/2 of the FE run (fit.json)
            a_max = num(verification_run(fit, row["case_id"]).get("contact_radius_fe"))
            runs.setdefault("elastic" if elastic else "plastic", (h, s, snaps, a_max))
    rows = []
    if "elastic" in runs:
        rows.append(("(a) elastic substrate: von Mises stress [MPa]", runs["elastic"], "von_mises",
                     1e-6))
    if "plastic" in runs:
        sy = runs["plastic"][1]["config"]["substrate"]["material"]["sigma_y"]
        rows.append((f"(b) sigma_y = {sy / 1e6:g} MPa: von Mises stress [MPa]", runs["plastic"],
                     "von_mises", 1e-6))
        rows.append((f"(c) sigma_y = {sy / 1e6:g} MPa: equivalent plastic strain [-]",
                     runs["plastic"], "plastic_strain", 1.0))
    if not rows:
        return None
    ncol = max(len(r[1][2]) for r in rows)
    fig = plt.figure(figsize=(3.0 * ncol + 1.2, 3.4 * len(rows)), layout="constrained")
    subfigs = fig.subfigures(len(rows), 1, squeeze=False)[:, 0]
    for sub, (label, (h, s, snaps, a_max), field, scale) in zip(subfigs, rows):
        axes = sub.subplots(1, ncol, squeeze=False)[0]
        if not a_max > 0:
            a_max = 1e-3
        r_lim, z_lo, z_hi = 3.0 * a_max, -3.0 * a_max, 1.5 * a_max
        data = []
        for t, path in snaps:
            v = read_vtu(path)
            xy = v["points"][:, :2][v["quads"]]  # (M, 4, 2) [m]
            c = xy.mean(axis=1)
            keep = (c[:, 0] <= 1.3 * r_lim) & (c[:, 1] >= z_lo - 0.3 * a_max) & \
                (c[:, 1] <= z_hi + 0.3 * a_max)
            data.append((t, xy[keep] * 1e3, np.asarray(v["cells"][field])[keep] * scale))
        vmax = max((float(d.max()) for _, _, d in data if d.size), default=0.0) or 1.0
        unit = label.rsplit(" ", 1)[1]
        for j, ax in enumerate(axes):
            if j >= len(data):
                ax.axis("off")
                continue
            t, polys, vals = data[j]
            pc = PolyCollection(polys, array=vals, cmap="jet", edgecolors="face", linewidths=0.2)
            pc.set_clim(0.0, vmax)
            ax.add_collection(pc)
            ax.set_xlim(0.0, r_lim * 1e3)
            ax.set_ylim(z_lo * 1e3, z_hi * 1e3)
            ax.set_aspect("equal")
            ax.set_title(f"t = {t * 1e6:.0f} us, {_phase(t, h)}\n"
                         f"max in view {vals.max():.3g} {unit}", fontsize=8)
            ax.set_xlabel("r [mm]", fontsize=8)
            if j == 0:
                ax.set_ylabel("z [mm]", fontsize=8)
            ax.tick_params(labelsize=7)
        sub.colorbar(pc, ax=axes, shrink=0.9).set_label(label.split(": ")[1], fontsize=8)
        sub.suptitle(label, fontsize=9, x=0.01, ha="left", weight="bold")
    fig.suptitle("Fig. 4: fields at 5 m/s near the contact (deformed mesh, sphere above the "
                 "substrate surface z = 0)", fontsize=10)
    os.makedirs(os.path.join(out_dir, "figures"), exist_ok=True)
    fig.savefig(os.path.join(out_dir, "figures", "fig04_fields.png"), dpi=110)
    plt.close(fig)
    return "fig04_fields.png"


def fig5_energy(out_dir, fit):
    runs = [r for r in history_runs(out_dir, "verification_hertz")
            if r[2]["config"]["substrate"]["material"]["sigma_y"] is not None]
    if not runs:
        return None
    row, h, s = runs[0]
    t = [x * 1e6 for x in h["time_s"]]
    fig, ax = plt.subplots(figsize=(6.6, 4.4))
    keys = [("kinetic_energy_J", "kinetic"), ("strain_energy_J", "elastic strain"),
            ("plastic_dissipation_J", "plastic dissipation"),
            ("hourglass_energy_J", "hourglass"), ("viscous_dissipation_J", "bulk viscosity"),
            ("contact_energy_J", "contact penalty")]
    total = [0.0] * len(t)
    for k, label in keys:
        ax.plot(t, h[k], label=label)
        total = [a + b for a, b in zip(total, h[k])]
    ax.plot(t, total, "k--", label="total")
    ax.set_xlabel("time [us]")
    ax.set_ylabel("energy [J]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    ax.set_title("Fig. 5: energies at 5 m/s (sigma_y = 500 MPa)")
    return _save(fig, out_dir, "fig05_energy.png")


def _law(fit):
    law = fit.get("fits", {}).get("restitution_law", {})
    return None if "error" in law or not law else law


def _table2_points(out_dir, fit):
    """{group: [(ln k1, e, run)]} of the ok Table 2 runs, grouped like the fit."""
    groups = {}
    for c in fit.get("fits", {}).get("comparison", []):
        if c["study"] != "table2":
            continue
        groups.setdefault(c["group"], []).append((math.log(c["k1"]), c["e_fe"], c))
    return groups


def _lines(fit, fig):
    return fit.get("figure_lines", {}).get(fig) or {}


def fig6_e_vs_k1(out_dir, fit):
    law = _law(fit)
    groups = _table2_points(out_dir, fit)
    if not groups:
        return None
    fig, ax = plt.subplots(figsize=(7.5, 5))
    lines = _lines(fit, "fig6")
    s = (law or {}).get("slope", {}).get("value", math.nan)
    for i, (g, pts) in enumerate(sorted(groups.items())):
        pts.sort(key=lambda p: p[0])
        color, marker = case_style(i)
        ax.errorbar([p[0] for p in pts], [p[1] for p in pts], yerr=_yerr(p[2] for p in pts),
                    fmt=marker, color=color, ms=4, capsize=2, elinewidth=0.8,
                    label=g.replace("_E115.4GPa", ""))
        if g in lines:
            ax.plot(lines[g]["ln_k1"], lines[g]["e"], "-", color=color, lw=1)
    ax.set_xlabel("ln k1 = ln(E*/(rho v^2)) [-]")
    ax.set_ylabel("coefficient of restitution e [-]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=6, ncol=2)
    ax.set_title(f"Fig. 6: e vs ln k1 (bars: discretisation error; lines: e = a_i + s ln k1, "
                 f"s = {s:.4f}; paper {_paper(fit, 'slope'):g})", fontsize=9)
    return _save(fig, out_dir, "fig06_e_vs_lnk1.png")


def fig7_fit_error(out_dir, fit):
    law = _law(fit)
    points = _lines(fit, "fig7")
    if not law or not points.get("e_fe"):
        return None
    xs, ys = points["e_fe"], points["e_eq9"]
    bound = _paper(fit, "fit_error_bound")
    fig, ax = plt.subplots(figsize=(5.2, 5))
    ax.plot(xs, ys, "o", ms=4, label="plastic FE points")
    lo, hi = min(xs + ys) * 0.95, 1.0
    ax.plot([lo, hi], [lo, hi], "k-", lw=1, label="y = x")
    ax.plot([lo, hi], [lo * (1 + bound), hi * (1 + bound)], "k--", lw=0.8,
            label=f"+-{100 * bound:g} %")
    ax.plot([lo, hi], [lo * (1 - bound), hi * (1 - bound)], "k--", lw=0.8)
    ax.set_xlabel("e from the FE solver [-]")
    ax.set_ylabel("e from eq. 9 (our a_i, s) [-]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    ax.set_title("Fig. 7: fitting error of eq. 9")
    return _save(fig, out_dir, "fig07_fit_error.png")


def fig8_a_vs_k2(out_dir, fit):
    law = _law(fit)
    if not law or not law.get("cases"):
        return None
    fig, ax = plt.subplots(figsize=(6, 4.4))
    x = [math.log(c["k2"]) for c in law["cases"]]
    y = [c["a"]["value"] for c in law["cases"]]
    err = [c["a"]["ci_upper"] - c["a"]["value"] for c in law["cases"]]
    ax.errorbar(x, y, yerr=err, fmt="o", ms=4, capsize=2, label="a_i (95 % CI)")
    lines = _lines(fit, "fig8")
    xs = lines.get("ln_k2", [])
    if xs and not math.isnan(num(lines["ours"][0])):
        ax.plot(xs, lines["ours"], "-",
                label=f"ours: a = {law['alpha']['value']:.3f} + {law['beta']['value']:.4f} ln k2")
    if xs:
        ax.plot(xs, lines["paper"], "k--",
                label=f"paper: a = {_paper(fit, 'alpha'):g} + {_paper(fit, 'beta'):g} ln k2")
    ax.set_xlabel("ln k2 = ln(sigma_y/E*) [-]")
    ax.set_ylabel("intercept a [-]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    ax.set_title("Fig. 8: intercept a vs ln k2")
    return _save(fig, out_dir, "fig08_a_vs_lnk2.png")


def _yield_fit(fit, key="yield_velocity_fe"):
    y = fit.get("fits", {}).get(key)
    return None if not y or "error" in y else y


def fig9_rho_vy2(out_dir, fit):
    y = _yield_fit(fit)
    if not y:
        return None
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    groups = {}
    for s in y["samples"]:
        groups.setdefault(round(s["E_star"] / 1e9, 3), []).append(s)
    curves = {round(c["E_star"] / 1e9, 3): c for c in _lines(fit, "fig9")}
    n = y["n"]["value"]
    for i, (es, pts) in enumerate(sorted(groups.items())):
        color, marker = case_style(i)
        ax.plot([p["sigma_y"] / 1e6 for p in pts], [p["sphere_rho"] * p["v_y"] ** 2 for p in pts],
                marker, color=color, ms=4, label=f"E* = {es:g} GPa")
        if es in curves:
            c = curves[es]
            ax.plot([v / 1e6 for v in c["sigma_y"]], c["ours"], "-", color=color, lw=1)
            ax.plot([v / 1e6 for v in c["sigma_y"]], c["paper"], ":", color=color, lw=1)
    ax.set_yscale("log")
    ax.set_xlabel("substrate yield stress sigma_y [MPa]")
    ax.set_ylabel("rho v_y^2 [Pa]")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7)
    ax.set_title(f"Fig. 9: rho v_y^2 = b (sigma_y/{_paper(fit, 'sigma0') / 1e6:g} MPa)^n; ours "
                 f"n = {n:.3f} (solid), paper {_paper(fit, 'n'):g} (dotted)", fontsize=9)
    return _save(fig, out_dir, "fig09_rho_vy2.png")


def fig10_b_vs_E(out_dir, fit):
    y = _yield_fit(fit)
    if not y or not y["groups"]:
        return None
    fig, ax = plt.subplots(figsize=(6, 4.4))
    es = [g["E_star"] / 1e9 for g in y["groups"]]
    b = [g["b"]["value"] for g in y["groups"]]
    yerr = [[g["b"]["value"] - g["b"]["ci_lower"] for g in y["groups"]],
            [g["b"]["ci_upper"] - g["b"]["value"] for g in y["groups"]]]
    ax.errorbar(es, b, yerr=yerr, fmt="o", capsize=2, label="b per E* (95 % CI)")
    lines = _lines(fit, "fig10")
    grid = [e / 1e9 for e in lines.get("E_star", [])]
    c, m = num(y["c"]["value"]), num(y["m"]["value"])
    e0 = f"E*/{_paper(fit, 'E0') / 1e9:g} GPa"
    if grid and not math.isnan(c):
        ax.plot(grid, lines["ours"], "-", label=f"ours: b = {c:.4g} Pa ({e0})^{m:.3f}")
    if grid:
        ax.plot(grid, lines["paper"], "k--",
                label=f"paper: b = {_paper(fit, 'c'):g} Pa ({e0})^{_paper(fit, 'm'):g}")
    ax.set_yscale("log")
    ax.set_xlabel("effective modulus E* [GPa]")
    ax.set_ylabel("b [Pa]")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7)
    ax.set_title("Fig. 10: b vs E*")
    return _save(fig, out_dir, "fig10_b_vs_E.png")


MODEL_STYLE = {"ma2023": ("k-", "Ma et al. 2023 eq. 19"), "thornton1997": ("C0--", "Thornton 1997"),
               "wu2003": ("C1:", "Wu et al. 2003 (UNVERIFIED form)"), "jg1": ("C2-.", "J-G1"),
               "jg2": ("C3-.", "J-G2"), "ours": ("C4-", "eq. 19 with our constants")}


def _yerr(runs):
    """Error bars from each run's discretisation-error estimate (0 where there is none)."""
    errs = [num(c.get("e_error")) for c in runs]
    return [0.0 if math.isnan(x) else x for x in errs]


def _fe_points(fit, study):
    pts = {}
    for c in fit.get("fits", {}).get("comparison", []):
        if c["study"] == study:
            pts.setdefault(c["group"], []).append((c["velocity"], c["e_fe"], c))
    return pts


def fig_pairs(out_dir, fit, study, file_prefix, title_of):
    """One figure per material pair: FE points and the analytic model curves."""
    curves = fit.get("fits", {}).get("curves", {}).get(study, {})
    pts = _fe_points(fit, study)
    names = []
    for i, (group, cur) in enumerate(sorted(curves.items())):
        fig, ax = plt.subplots(figsize=(6.4, 4.6))
        v = cur["velocity"]
        for name, values in cur["models"].items():
            if isinstance(values, dict):
                continue
            style, label = MODEL_STYLE.get(name, ("-", name))
            ax.plot(v, values, style, lw=1.2, label=label)
        p = sorted(pts.get(group, []), key=lambda q: q[0])
        if p:
            ax.errorbar([q[0] for q in p], [q[1] for q in p], yerr=_yerr(q[2] for q in p),
                        fmt="ko", mfc="white", ms=6, capsize=2, elinewidth=0.8,
                        label="FE (corlab solver, +/- discretisation error)")
        ax.set_xscale("log")
        ax.set_xlabel("impact velocity v [m/s]")
        ax.set_ylabel("coefficient of restitution e [-]")
        ax.set_ylim(0, 1.25)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7)
        ax.set_title(title_of(i, cur), fontsize=9)
        names.append(_save(fig, out_dir, f"{file_prefix}_{i + 1}.png"))
    return names


def fig11_12_alumina(out_dir, fit):
    def title(i, cur):
        fig_no = 11 if "alumin" in cur["substrate"] else 12
        return (f"Fig. {fig_no}: {cur['sphere']} on {cur['substrate']} "
                "(no experimental points: none available)")
    return fig_pairs(out_dir, fit, "alumina", "fig11_12_alumina", title)


def fig13_table4(out_dir, fit):
    def title(i, cur):
        return f"Fig. 13: {cur['sphere']} on {cur['substrate']}"
    return fig_pairs(out_dir, fit, "table4", "fig13_table4", title)


def fig_onset(out_dir, fit):
    onset = fit.get("fits", {}).get("yield_onset", [])
    if not onset or not any(o["probes"] for o in onset):
        return None
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for i, o in enumerate(onset):
        probes = sorted((p for p in o["probes"] if p.get("kind", "probe") == "probe"),
                        key=lambda p: p["velocity"])
        color, marker = case_style(i)
        ax.plot([p["velocity"] for p in probes],
                [max(p["plastic_strain_max"], 1e-12) for p in probes], marker + "-", color=color,
                label=o["group"])
        for key, style in (("v_hertz_onset", ":"), ("v_y_paper_eq18", "--"), ("v_scaled", "-.")):
            if o.get(key):
                ax.axvline(o[key], color=color, ls=style, lw=1)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("impact velocity v [m/s]")
    ax.set_ylabel("largest plastic strain left [-] (1e-12 = none)")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7)
    ax.set_title("Yield onset: bracket runs (dash-dot: elastic-scaling estimate; dotted: Hertz "
                 "p0 = 1.6 sigma_y; dashed: Ma eq. 18)",
                 fontsize=8)
    return _save(fig, out_dir, "fig_onset.png")
