"""HTML report of ``corlab reproduce``: ``python3 -m corlab.report DIR``.

Reads ``DIR/fit.json`` (written by ``corlab reproduce``) and the run files under DIR, draws our
versions of Ma et al. (2023) Figs. 2-13 (``corlab.figures``) and writes ``DIR/report.html``:
fitted coefficients with 95 % confidence intervals next to the paper's, the error of the paper's
model against our solver per case, run counts and times, the command and versions, and a
discussion of the differences computed from the numbers (nothing in it is typed in by hand).

Every number it prints comes from fit.json, computed by the C++ ``corlab reproduce`` (the Hertz
reference of the verification runs, the model errors, our coefficients against the paper's, the
paper's published values, the runs on disk); this module holds no formula and no published
constant: it only reads, formats and plots.
"""
# SPDX-License-Identifier: BSD-3-Clause
from __future__ import annotations

import json
import math
import os
import platform
import sys

from . import figures
from .html_table import esc, fmt, pct, table, with_contents
from .report_dataset import dataset_section
from .report_oblique import oblique_section
from .report_summary import glance

COARSE_OMITS = [
    "Contact mesh: h_min = 1 mm with h <= a_max/4 (paper and paper preset: 0.25 mm, h <= "
    "a_max/12); the runs of Figs. 3-5 use 0.5 mm; Fig. 2 uses 1.5, 1 and 0.5 mm (the paper preset: "
    "1, 0.5, 0.35, 0.25 and 0.18 mm). The coarse mesh shifts e by a few percent (see the mesh "
    "table).",
    "Table 2: all 15 cases, but velocities {1, 2, 5, 10, 20, 50} m/s only (paper: 0.1-70 m/s; "
    "full preset: 11 velocities 0.1-70 m/s).",
    "Yield velocity: all 60 (rho, E*, sigma_y) cases, but only two velocities {2, 10} m/s per "
    "case (paper preset: {1, 3, 10, 30} m/s).",
    "Yield onset: two cases (rho 7850, E* 63.8 GPa, sigma_y 300 and 600 MPa) "
    "(paper preset: 7 cases).",
    "Table 3 pairs: velocities {0.5, 1, 2, 4, 6, 20} m/s (paper preset: 12 velocities 0.2-70 m/s).",
    "Table 4 cases: velocities {1, 2, 5, 10, 20} m/s (paper preset: 1-50 m/s).",
]


def covers(c):
    """'yes'/'no' whether the paper's value lies in our interval."""
    try:
        lo, hi, p = float(c["ci_lower"]), float(c["ci_upper"]), float(c["paper"])
    except (TypeError, ValueError, KeyError):
        return "-"
    if any(math.isnan(v) for v in (lo, hi, p)):
        return "-"
    return "yes" if lo <= p <= hi else "<b>no</b>"


def coef_row(label, c, form):
    if not c:
        return [esc(label), "-", "-", "-", "-", "-", esc(form)]
    return [esc(label), fmt(c.get("value"), 5), fmt(c.get("standard_error"), 3),
            f"[{fmt(c.get('ci_lower'), 5)}, {fmt(c.get('ci_upper'), 5)}]", fmt(c.get("paper"), 5),
            covers(c), esc(form)]


def coefficient_table(fits, paper):
    law = fits.get("restitution_law", {})
    fixed = (f"n = {figures.num(paper.get('n')):g}, m = {figures.num(paper.get('m')):g} "
             "fixed")
    yv = fits.get("yield_velocity_fe", {})
    rows = []
    if "error" not in law:
        rows.append(coef_row("s (slope of ln k1)", law.get("slope"), "(i) Table 2, eq. 9"))
        rows.append(coef_row("alpha", law.get("alpha"), "(ii) eq. 11"))
        rows.append(coef_row("beta", law.get("beta"), "(ii) eq. 11"))
    y = yv if yv and "error" not in yv else None
    if y:
        label = "v_y from FE crossings"
        rows.append(coef_row(f"n [{label}]", y.get("n"), "(iii) eq. 15"))
        rows.append(coef_row(f"m [{label}]", y.get("m"), "(iv) eq. 17"))
        rows.append(coef_row(f"c [Pa] [{label}]", y.get("c"), "(iv) eq. 17"))
        k_row = coef_row(f"K [{label}] one step", y.get("K"), "eq. 18 constant")
        vs = fits.get("versus_paper", {})
        if not vs.get("K_comparable"):  # K carries units Pa^(1-n-m): not comparable
            k_row[5] = f"not comparable (unit Pa^{figures.num(vs.get('K_unit_exponent')):.3f})"
        rows.append(k_row)
        rows.append(coef_row(f"K [{label}] with {fixed}",
                             y.get("K_fixed_exponents"), "eq. 18 constant"))
        rows.append([esc(f"K [{label}] two step c sigma0^-n E0^-m"), fmt(y.get("K_two_step"), 5),
                     "-", "-", fmt(paper.get("K"), 5), "-", "eq. 18 constant"])
    for key, label in (("yield_velocity_eq12", "our eq. 12"),
                       ("yield_velocity_paper_eq12", "paper's eq. 12")):
        y = fits.get(key, {})
        if not y or "error" in y:
            continue
        note = "derived exactly from alpha, beta, s (n = beta/s, m = 1 - beta/s): no interval"
        for name, c in (("n", y.get("n")), ("m", y.get("m")), ("c [Pa]", y.get("c")),
                        ("K one step", y.get("K")),
                        (f"K with {fixed}", y.get("K_fixed_exponents"))):
            if c:
                rows.append([esc(f"{name} [v_y back-calculated from {label}]"),
                             fmt(c.get("value"), 5), "-", "-", fmt(c.get("paper"), 5), "-",
                             esc(note)])
    return table(["coefficient", "ours", "std. error", "95 % CI", "paper", "paper in CI?", "form"],
                 rows)


def goodness_rows(fits):
    rows = []
    law = fits.get("restitution_law", {})
    for key, label in (("goodness_form_i", "(i) e = a_i + s ln k1 (Table 2 plastic points)"),
                       ("goodness_form_ii", "(ii) a_i = alpha + beta ln k2"),
                       ("goodness_combined", "eq. 12 with our alpha, beta, s")):
        g = law.get(key)
        if g:
            rows.append([esc(label), fmt(g["r_squared"], 5), pct(g["max_relative_error"]),
                         pct(g["rms_relative_error"])])
    for fk, name in (("yield_velocity_fe", "FE crossings"),):
        y = fits.get(fk, {})
        for key, label in (("goodness_form_iii", f"(iii) rho v_y^2 = b sigma_bar^n ({name})"),
                           ("goodness_form_iv", f"(iv) b = c E_bar^m ({name})"),
                           ("goodness_v_y", f"v_y = sqrt(K sigma^n E*^m / rho) ({name})")):
            g = y.get(key) if isinstance(y, dict) else None
            if g:
                rows.append([esc(label), fmt(g["r_squared"], 5), pct(g["max_relative_error"]),
                             pct(g["rms_relative_error"])])
    return table(["fit", "R^2", "max rel. error", "RMS rel. error"], rows)


def scaled(x, factor):
    """x * factor, NaN when x is missing (fmt and pct then print "-")."""
    return figures.num(x) * factor


def model_error_table(fits, key="e_paper"):
    """The per-case table of fit.json's "model_error" of one model, and its "overall" entry."""
    err = fits.get("model_error", {}).get(key, {})
    rows = []
    for g in err.get("groups", []):
        rows.append([esc(g["study"]), esc(g["group"]), str(g["runs"]),
                     pct(g["mean_relative_error"]), pct(g["rms_relative_error"]),
                     f"{pct(g['largest_relative_error'])} at "
                     f"{fmt(g['largest_at_velocity'], 3)} m/s"])
    return table(["study", "case (group)", "runs", "mean rel. error", "RMS rel. error",
                  "largest rel. error"], rows), err.get("overall", {})


def verification_section(fit):
    """The tables of fit.json's "verification": the 5 m/s runs against Hertz (elastic) and the
    paper's energies (elastic-plastic), and the mesh study."""
    parts = []
    paper = fit.get("paper", {})
    ver = fit.get("verification", {})
    rows = []
    for r in ver.get("hertz", []):
        h = r.get("hertz", {})
        if r.get("elastic"):
            rows.append(["elastic substrate", fmt(r["e"], 4), "1 (Hertz)",
                         f"{fmt(scaled(r['F_max'], 1e-3), 5)} kN vs Hertz "
                         f"{fmt(scaled(h.get('max_force'), 1e-3), 5)} kN "
                         f"({pct(r['F_max_vs_hertz'])})",
                         f"{fmt(scaled(r['delta_max'], 1e3), 5)} mm vs Hertz "
                         f"{fmt(scaled(h.get('max_overlap'), 1e3), 5)} mm "
                         f"({pct(r['delta_max_vs_hertz'])})",
                         f"{fmt(scaled(r['t_contact'], 1e6), 5)} us vs Hertz "
                         f"{fmt(scaled(h.get('contact_time'), 1e6), 5)} us "
                         f"({pct(r['t_contact_vs_hertz'])})"])
        else:
            loss = fmt(paper.get("energy_loss_5ms_J"), 4)
            rows.append(["sigma_y = 500 MPa", fmt(r["e"], 4),
                         f"{figures.num(r['e_from_paper_energy_loss']):.3f} (from the paper's "
                         f"{loss} J loss)",
                         f"sphere energy loss {fmt(r['energy_sphere_loss'], 4)} J (paper {loss} J)",
                         f"hysteresis area {fmt(r['hysteresis_area'], 4)} J (paper "
                         f"{fmt(paper.get('hysteresis_area_5ms_J'), 4)} J); "
                         f"difference {pct(r['hysteresis_vs_energy_loss'])} "
                         f"(paper {pct(paper.get('hysteresis_difference'))})",
                         f"hourglass {pct(r['hourglass_fraction'], 3)} of the "
                         f"initial energy (paper {pct(paper.get('hourglass_fraction'), 4)}); "
                         f"energy balance error {fmt(r['energy_balance_error'], 2)}"])
    if rows:
        parts.append(table(["run at 5 m/s", "e (ours)", "e (reference)", "", "", ""], rows))
    mesh = ver.get("mesh", [])
    if mesh:
        parts.append(table(
            ["h_min [mm]", "elements", "steps", "e", "e - e(finest)", "F_max [kN]", "wall [s]"],
            [[fmt(scaled(r["h_min"], 1e3), 3), str(r["elements"]), str(r["steps"]),
              fmt(r["e"], 5), fmt(r["e_minus_finest"], 3), fmt(scaled(r["F_max"], 1e-3), 5),
              fmt(r["wall_s"], 3)] for r in mesh]))
    return "\n".join(parts)


def onset_table(fits):
    rows = []
    for o in fits.get("yield_onset", []):
        ratio = o.get("v_y_paper_over_onset")
        rows.append([esc(o["group"]), fmt(o["v_elastic"], 4), fmt(o["v_plastic"], 4),
                     fmt(o["v_onset"], 4), fmt(o["v_hertz_onset"], 4), fmt(o["v_y_paper_eq18"], 4),
                     fmt(o.get("v_y_ours"), 4), fmt(ratio, 3), str(len(o["probes"]))])
    return table(["case", "highest elastic v [m/s]", "lowest plastic v [m/s]", "onset (geo. mean)",
                  "Hertz p0 = 1.6 sigma_y", "Ma eq. 18 v_y", "our eq. 18 v_y",
                  "Ma v_y / onset", "runs"], rows)


def runs_table(fit):
    rows = []
    for name, s in fit.get("studies", {}).items():
        rows.append([esc(name), esc(s.get("description", "")), str(s.get("total", "-")),
                     str(s.get("already_done", "-")), str(s.get("ran", "-")),
                     str(s.get("failed", "-")), fmt(s.get("wall_s"), 4),
                     str(s.get("runs_on_disk", "-")), fmt(s.get("solver_s_on_disk"), 4)])
    t = fit.get("studies_total", {})
    rows.append(["<b>all</b>", "", "", "", f"<b>{t.get('ran', '-')}</b>", "",
                 f"<b>{fmt(t.get('wall_s'), 4)}</b>", f"<b>{t.get('runs_on_disk', '-')}</b>",
                 f"<b>{fmt(t.get('solver_s_on_disk'), 4)}</b>"])
    return table(["study", "description", "runs in spec", "done earlier", "ran now", "failed",
                  "wall now [s]", "finished runs on disk", "their solver time [s] (sum)"], rows)


def versus(name, c, digits=4):
    """'name = x [lo, hi] against the paper's p (+d %, inside/outside our 95 % CI)' from an entry
    of fit.json's "versus_paper"."""
    v, lo, hi, paper = (figures.num(c.get(k)) for k in ("value", "ci_lower", "ci_upper", "paper"))
    if math.isnan(v):
        return f"{name}: no value"
    where = "inside" if c.get("paper_in_ci") else "outside"
    return (f"{name} = {fmt(v, digits)} [{fmt(lo, digits)}, {fmt(hi, digits)}] against the "
            f"paper's {paper:g} ({pct(c.get('relative_difference'), 1)}; "
            f"the paper's value is {where} our 95 % CI)")


def error_bar_item(fits):
    """The study's discretisation-error bars (the scatter estimator per run), one sentence."""
    d = fits.get("discretisation_error", {}).get("all")
    if not d:
        return None
    m = d["max_case"]
    return (f"Every FE restitution coefficient carries a discretisation-error bar from companion "
            f"runs on meshes √2, 2 and 2√2 times as coarse everywhere (corlab's scatter estimator, "
            f"docs/theory/error_bars.md: on two seeded samples of 48 cases it held the value at "
            f"h/2 in 46 and 48; error bars in Figs. 6 and 11-13): over {d['count']} runs the "
            "median "
            f"is {fmt(d['median'], 2)} and the largest {fmt(d['max'], 2)} "
            f"({pct(d['max_relative'], 1)} of e = {fmt(m['e'], 4)}, {esc(m['study'])} "
            f"{esc(m['group'])} at {fmt(m['velocity'], 3)} m/s). The confidence intervals of the "
            "fits below are statistical only and do not include it.")


# The refit question's outside evidence (issue 28): runs made for this project with another code,
# quoted as reported; no corlab command reproduces them.
INDEPENDENT_CODE = (
    "An independent code agrees with corlab better than either agrees with the paper's fit: "
    "CalculiX (3-D implicit, a wedge model at the same 0.25 mm contact resolution), run for this "
    "project outside this repository at five points of the paper's corner (steel on steel, "
    "sigma_y 500 MPa at 1, 5, 10 and 30 m/s; 300 MPa at 5 m/s), gives e within 0.1-2.1 % of "
    "corlab's, corlab below it and the difference growing with speed, and both codes lie "
    "1.8-4.1 % above the paper's eq. 19 at those points.")


def discussion(fit):
    fits = fit.get("fits", {})
    law = fits.get("restitution_law", {})
    vs = fits.get("versus_paper", {})
    paper = fit.get("paper", {})
    items = []
    if law and "error" not in law:
        s = vs.get("slope", {})
        items.append(
            f"Slope of ln k1: ours s = {fmt(s.get('value'), 4)} (95 % CI "
            f"[{fmt(s.get('ci_lower'), 4)}, {fmt(s.get('ci_upper'), 4)}]) against the paper's "
            f"{figures.num(s.get('paper')):g}, a difference of "
            f"{pct(s.get('relative_difference'), 1)}; the paper's value is "
            f"{'inside' if s.get('paper_in_ci') else 'outside'} our interval. It rests on "
            f"{law['points_used']} plastic points in {len(law['cases'])} cases "
            f"({law['points_excluded']} points excluded as elastic or failed).")
        a = law["alpha"]
        if a.get("value") is not None and not math.isnan(figures.num(a.get("value"))):
            items.append(
                "Intercept law a = alpha + beta ln k2: ours "
                f"{versus('alpha', vs.get('alpha', {}))}; "
                f"{versus('beta', vs.get('beta', {}))}. "
                "Alpha and beta are strongly correlated (alpha is the extrapolation of the line to "
                "ln k2 = 0, far outside the data at ln k2 ~ -6 to -4), so compare the predicted e "
                "rather than alpha alone.")
    bars = error_bar_item(fits)
    if bars:
        items.append(bars)
    mesh = fit.get("verification", {}).get("mesh", [])
    if len(mesh) >= 2:
        items.append(
            "Mesh sensitivity at 5 m/s (Fig. 2): e = " +
            ", ".join(f"{figures.num(r['e']):.4f} at h_min = {scaled(r['h_min'], 1e3):g} mm"
                      for r in mesh) +
            "; the FE values carry a discretisation error of this order, which the confidence "
            "intervals do not include.")
    _, overall = model_error_table(fits, "e_paper")
    if overall.get("runs"):
        items.append(
            f"The paper's model (eq. 19 with its published constants) against our solver over "
            f"{overall['runs']} runs: RMS relative error {pct(overall['rms_relative_error'])}, "
            f"largest {pct(overall['largest_relative_error'])}. The paper states its fit stays "
            f"within {pct(paper.get('fit_error_bound'), 0)} of its own FE results (Fig. 7).")
    _, ours = model_error_table(fits, "e_ours")
    if ours.get("runs"):
        items.append(f"Eq. 19 with our refitted constants over the same runs: RMS "
                     f"{pct(ours['rms_relative_error'])}, largest "
                     f"{pct(ours['largest_relative_error'])}.")
    if overall.get("runs"):
        items.append(INDEPENDENT_CODE)
    y = fits.get("yield_velocity_fe", {})
    if y and "error" not in y:
        kf = y.get("K_fixed_exponents", {})
        n_p, m_p = figures.num(paper.get("n")), figures.num(paper.get("m"))
        k_p = figures.num(paper.get("K"))
        items.append(
            f"Yield-velocity law from our FE crossings: {versus('n', vs.get('n', {}))}; "
            f"{versus('m', vs.get('m', {}))}; c = {fmt(y['c']['value'], 4)} Pa "
            f"(paper {figures.num(paper.get('c')):g} Pa). With the exponents fixed at the paper's "
            f"{n_p:g} and {m_p:g} the constant "
            f"is K = {fmt(kf.get('value'), 4)} [{fmt(kf.get('ci_lower'), 4)}, "
            f"{fmt(kf.get('ci_upper'), 4)}] against {k_p:g}, i.e. our crossing velocities are "
            f"{fmt(vs.get('crossing_velocity_ratio'), 3)} x the paper's eq. 18. The free one-step "
            f"K ({fmt(y['K']['value'], 4)}) is not comparable: with n + m != 1 it carries the unit "
            "Pa^(1-n-m) and is an extrapolation to sigma_y = E* = 1 Pa.")
    pe = fits.get("yield_velocity_paper_eq12", {})
    if pe and "error" not in pe:
        kf = pe.get("K_fixed_exponents", {}).get("value")
        items.append(
            "Self-check of the procedure: back-calculating v_y from the paper's own eq. 12 over "
            f"the same (rho, E*, sigma_y) grid and fitting (iii)-(iv) gives exactly n = "
            f"{fmt(pe['n']['value'], 4)} (= {figures.num(paper.get('beta')):g}/"
            f"{figures.num(paper.get('slope')):g}), m = {fmt(pe['m']['value'], 4)}, K = "
            f"{fmt(pe['K']['value'], 4)}; with the exponents rounded to "
            f"{figures.num(paper.get('n')):g} and {figures.num(paper.get('m')):g} the constant "
            f"becomes {fmt(kf, 4)} against the published {figures.num(paper.get('K')):g}. Eq. 18 "
            "is thus a re-expression of "
            "the eq. 12 crossing (a fit of a fit), not an independent measurement of yield.")
    ye = fits.get("yield_velocity_eq12", {})
    if ye and "error" not in ye:
        items.append(
            "The same back-calculation from our refitted eq. 12 gives "
            f"n = {fmt(ye['n']['value'], 4)},"
            f" m = {fmt(ye['m']['value'], 4)}, K = {fmt(ye['K']['value'], 4)} (K with fixed "
            f"exponents {fmt(ye.get('K_fixed_exponents', {}).get('value'), 4)}); n = beta/s is "
            "sensitive to small changes of beta and s.")
    onset = [o for o in fits.get("yield_onset", []) if o.get("v_onset")]
    for o in onset:
        if o["v_onset"] and not math.isnan(figures.num(o["v_onset"])):
            items.append(
                f"Yield onset straight from the solver ({esc(o['group'])}): first plastic strain "
                f"between {fmt(o['v_elastic'], 3)} and {fmt(o['v_plastic'], 3)} m/s; Hertz theory "
                f"(p0 = 1.6 sigma_y) predicts {fmt(o['v_hertz_onset'], 3)} m/s, while the paper's "
                f"eq. 18 gives v_y = {fmt(o['v_y_paper_eq18'], 3)} m/s. The paper's v_y is the "
                "e = 1 crossing of its log law, not the onset of yield.")
    items.append(
        "Experimental points: the paper compares with Kharaz & Gorham (2000), but no published "
        "numbers of those experiments are available to corlab (docs/reference models.md section "
        "7). None are drawn or used; no point was invented, estimated or digitised. Figs. 11-12 "
        "compare the analytic models with our FE results only.")
    items.append(
        "The Wu et al. (2003) curve uses an UNVERIFIED candidate form (models.md section 3); "
        "treat it as indicative only. Thornton uses p_y = 1.6 sigma_y; which p_y the paper used "
        "is not stated.")
    return "<ul>" + "".join(f"<li>{i}</li>" for i in items) + "</ul>"


def versions():
    import matplotlib
    import numpy

    out = {"python": platform.python_version(), "numpy": numpy.__version__,
           "matplotlib": matplotlib.__version__, "platform": platform.platform()}
    from . import _core  # always present: corlab/__init__.py imports it

    out["corlab (python module)"] = _core.__version__
    return out


CSS = """body{font-family:sans-serif;max-width:1200px;margin:2em auto;line-height:1.4}
table{border-collapse:collapse;margin:0.6em 0;font-size:0.9em}
td,th{border:1px solid #bbb;padding:3px 6px;text-align:left}th{background:#eee}
img{max-width:100%;border:1px solid #ddd;margin:4px 0}code{background:#f4f4f4;padding:1px 3px}
.warn{background:#fff3cd;padding:0.5em;border:1px solid #e0c060}
.toc{background:#f8f8f8;border:1px solid #ddd;padding:0.3em 1em;columns:2}
.glance{background:#eef5ff;border:1px solid #9bc;padding:0.4em 1em}.glance ul{margin:0.3em 0}"""


def make_report(out_dir):
    """Writes <out_dir>/report.html and the figures; returns the report path."""
    with open(os.path.join(out_dir, "fit.json")) as f:
        fit = json.load(f)
    fits = fit.get("fits", {})
    figs = {}
    for key, fn in (("fig2", figures.fig2_mesh), ("fig3", figures.fig3_hertz),
                    ("fig4", figures.fig4_fields), ("fig5", figures.fig5_energy),
                    ("fig6", figures.fig6_e_vs_k1),
                    ("fig7", figures.fig7_fit_error), ("fig8", figures.fig8_a_vs_k2),
                    ("fig9", figures.fig9_rho_vy2), ("fig10", figures.fig10_b_vs_E),
                    ("fig11_12", figures.fig11_12_alumina), ("fig13", figures.fig13_table4),
                    ("onset", figures.fig_onset)):
        try:
            figs[key] = fn(out_dir, fit)
        except Exception as err:  # a broken figure must not lose the rest of the report
            figs[key] = None
            print(f"corlab.report: figure {key} failed: {err}", file=sys.stderr)

    def img(key, caption):
        names = figs.get(key)
        if not names:
            return f"<p><i>{esc(caption)}: no data (study not run or no finished runs).</i></p>"
        if isinstance(names, str):
            names = [names]
        return "".join(f'<p><img src="figures/{esc(n)}" alt="{esc(caption)}"></p>' for n in names)

    err_paper, _ = model_error_table(fits, "e_paper")
    err_ours, _ = model_error_table(fits, "e_ours")
    preset = fit.get("preset", "?")
    omitted = ""
    if preset == "coarse":
        omitted = ('<div class="warn"><b>Coarse preset: a demo, NOT the reproduction.</b> What '
                   "it omits relative to the paper (the default paper preset, <code>--preset "
                   "paper</code>, runs the paper's mesh and grids):<ul>" +
                   "".join(f"<li>{esc(x)}</li>" for x in COARSE_OMITS) + "</ul></div>")
    ver = versions()
    body = f"""<!DOCTYPE html><html><head><meta charset="utf-8">
<title>corlab: reproduction of Ma et al. (2023)</title><style>{CSS}</style></head><body>
<h1>Reproduction of Ma et al. (2023), Chinese J. Theor. Appl. Mech. 55(4):982-990</h1>
<p>"Research on normal restitution coefficient based on dimensionless analyses",
doi 10.6052/0459-1879-22-583. Our FE solver is corlab's explicit axisymmetric code, not ABAQUS.
All numbers below are computed from the runs in this directory.</p>
{glance(fit)}
{omitted}
<h2>Summary</h2>{discussion(fit)}
<h2>Fitted coefficients (95 % confidence intervals, Student t)</h2>
<p>Linear least squares by SVD with standard errors from s^2 (X^T X)^-1; (iii)-(iv) in log
space. "paper in CI?" asks whether the published value lies inside our interval. The intervals
carry only the scatter of our points about each form, not the discretisation error of the
solver.</p>
{coefficient_table(fits, fit.get("paper", {}))}
<h3>Goodness of fit</h3>{goodness_rows(fits)}
<h2>Error of the paper's model against our solver, per case</h2>
<p>Relative error (e_model - e_FE)/e_FE of Ma eq. 19 with the published constants (corlab's
<code>ma2023</code> model), for every finished run with a plastic substrate.</p>
{err_paper}
<h3>Same, with our refitted constants</h3>{err_ours}
<h2>Verification (paper section 1)</h2>
{verification_section(fit)}
{img("fig2", "Fig. 2")}{img("fig3", "Fig. 3")}
<p>Fig. 4: fields of the two 5 m/s runs at the <code>output.times</code> of the
verification_hertz study (runs/&lt;case&gt;/fields_&lt;t&gt;.vtu, open them in ParaView),
in the deformed configuration near the contact (r up to 3 a_max, a_max = (R delta_max)^1/2);
element values, one colour scale per row.</p>
{img("fig4", "Fig. 4")}{img("fig5", "Fig. 5")}
<h2>Restitution law (paper section 2.1)</h2>
{img("fig6", "Fig. 6")}{img("fig7", "Fig. 7")}{img("fig8", "Fig. 8")}
<h2>Yield velocity (paper section 2.2)</h2>
<p>v_y of each case is the e = 1 crossing of its fitted line e = a_i + s ln k1 (the paper's
back-calculation); E* is realised with equal bodies, nu = 0.3, E = 2(1 - nu^2) E* = 1.82 E*.</p>
{img("fig9", "Fig. 9")}{img("fig10", "Fig. 10")}
<h3>Yield onset straight from the solver (not in the paper)</h3>
{onset_table(fits)}{img("onset", "yield onset")}
<h2>Model comparison (paper section 3, Tables 3-4)</h2>
<p><b>No experimental points</b>: no published numbers of Kharaz &amp; Gorham (2000) are
available to corlab; none are shown and none were digitised.</p>
{img("fig11_12", "Figs. 11-12")}{img("fig13", "Fig. 13")}
<h2>Beyond the paper: corlab's FE dataset and its model</h2>
{dataset_section(fit, out_dir)}
<h2>Beyond the paper: oblique impacts in 3-D (Kharaz et al. 2001)</h2>
{oblique_section(os.path.dirname(fit.get("dataset_dir") or ""), out_dir)}
<h2>Runs and time</h2>{runs_table(fit)}
<p>Fitting took {fmt(fit.get('fit_wall_s'), 3)} s. Runs in parallel: {esc(fit.get('jobs'))}
(hardware threads: {esc(fit.get('hardware_threads'))}).</p>
<h2>Command and versions</h2>
<p><code>{esc(fit.get('command', ''))}</code> (then <code>python3 -m corlab.report {esc(out_dir)}
</code>)</p>
{table(["item", "value"], [[esc(k), esc(v)] for k, v in [
    ("preset", preset), ("corlab", fit.get("corlab_version")), ("compiler", fit.get("compiler")),
    ("build", fit.get("build_type")), ("date (UTC)", fit.get("date_utc"))] + list(ver.items())])}
</body></html>"""
    path = os.path.join(out_dir, "report.html")
    with open(path + ".tmp", "w") as f:  # replaced whole: a signal never leaves half a report
        f.write(with_contents(body))
    os.replace(path + ".tmp", path)
    return path


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 1:
        print("usage: python3 -m corlab.report DIR  (DIR holds fit.json from corlab reproduce)",
              file=sys.stderr)
        return 2
    if not os.path.exists(os.path.join(argv[0], "fit.json")):
        print(f"corlab.report: error: no fit.json in {argv[0]}", file=sys.stderr)
        return 2
    print(make_report(argv[0]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
