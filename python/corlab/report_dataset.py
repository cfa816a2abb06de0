"""The report's "beyond the paper" section: corlab's FE datasets (data/fe_restitution and
data/fe_restitution_pairs), its models corlab2026 and corlab2026p and every registered model's
scores on them, and corlab2026 against Ma eq. 19 on the
Table 2 runs of the report's directory. The numbers come from model_fit.json, model_scores.json
and fit.json (written by the C++), the figure's from the C++ models and relative errors
(corlab._core): no formula or material constant lives here."""
# SPDX-License-Identifier: BSD-3-Clause
import json
import os
import sys

from . import _core, dataset
from .html_table import esc, fmt, pct, table


def _score_cells(s):
    return [str(s["n"]), pct(s["rms"], 1), pct(s["worst"], 1), pct(s["bias"], 1)]


def table2_versus_eq19(fit):
    """corlab2026 against Ma eq. 19 (ma2023) on the Table 2 runs, as fit.json has them
    ("corlab2026_versus_eq19", computed by the C++ for each run's own materials). Returns (rows
    of the summary table, cases where corlab2026 is at least as close, cases)."""
    t2 = fit.get("fits", {}).get("corlab2026_versus_eq19") or {}
    if not t2.get("cases"):
        return [], 0, 0
    rows = [[esc("corlab2026"), *_score_cells(t2["corlab2026"])],
            [esc("ma2023 (eq. 19)"), *_score_cells(t2["ma2023"])]]
    return rows, t2["corlab2026_at_least_as_close"], t2["cases"]


def _span(bounds):
    return f"{bounds[0]:g}-{bounds[1]:g}"


def _model_and_scores(folder):
    """(model_fit.json, model_scores.json) of a dataset folder, None if either is missing."""
    try:
        with open(os.path.join(folder, "model_fit.json")) as f:
            model = json.load(f)
        with open(os.path.join(folder, "model_scores.json")) as f:
            return model, json.load(f)
    except OSError:
        return None


def pairs_section(folder):
    """The particle-pair dataset (data/fe_restitution_pairs, beside the flat one): every model's
    scores on it and on its two corners, and corlab2026p's held-out errors."""
    loaded = _model_and_scores(folder)
    if loaded is None:
        return "<p><i>No particle-pair dataset found (data/fe_restitution_pairs).</i></p>"
    model, scores = loaded
    box = _core.dataset_box("pairs")
    rows = []
    for name, s in scores["scores"].items():
        rows.append([esc(f"{name} (all rows)"), *_score_cells(s["all cases"]["all"])])
        for corner, c in s.get("corners", {}).items():
            rows.append([esc(f"{name} ({corner})"), *_score_cells(c["all"])])
    skip = ("all", "train", "corner holdout")  # the fitted rows, and both corners together
    held = [[esc(f"{scope}: {regime}"), *_score_cells(s)]
            for scope, regimes in model["scores"].items() if scope not in skip
            for regime, s in regimes.items()]
    return f"""<h3>Particle pairs</h3><p>{scores['rows']} FE runs of the particle-pair dataset
(<code>{esc(folder)}</code>): a sphere on a flat or on a free second sphere over the modulus
ratios {_span(box["modulus_ratio"])}, density ratios {_span(box["density_ratio"])} and R1/R2 0
(a flat) or {_span(box["radius_ratio"])}. A sphere-on-flat model sees a pair as the
sphere of the pair's density rho* on a flat; <code>corlab2026p</code> sees the pair and is
fitted on {model['rows_train']} rows of both datasets, with a random {model['rows_random_holdout']}
and the corners ({esc(model['corner'])}, {model['rows_corner_holdout']} rows) held out.</p>
{table(["model (rows)", "cases", "RMS", "worst", "bias"], rows)}
<h3>corlab2026p: held-out errors by regime</h3>
{table(["held-out set: regime", "cases", "RMS", "worst", "bias"], held)}"""


def dataset_section(fit, out_dir):
    """Beyond the paper: corlab's FE dataset, its model and every model's scores on it."""
    folder = fit.get("dataset_dir") or ""
    loaded = _model_and_scores(folder)
    if loaded is None:
        return "<p><i>No FE dataset found (data/fe_restitution).</i></p>"
    model, scores = loaded
    head = ["model", "cases", "RMS", "worst", "bias"]
    rows = []
    for name, s in scores["scores"].items():
        for scope in ("all cases", "own box"):
            rows.append([esc(f"{name} ({scope})"), *_score_cells(s[scope]["all"])])
    regimes = []
    for scope in ("random holdout", "corner holdout"):
        for regime, s in model["scores"][scope].items():
            regimes.append([esc(f"{scope}: {regime}"), *_score_cells(s)])
    coef = [[esc(n), fmt(v, 5), f"[{fmt(model['confidence_95'][n][0], 4)}, "
             f"{fmt(model['confidence_95'][n][1], 4)}]"] for n, v in model["coefficients"].items()]
    figure = ""
    try:
        os.makedirs(os.path.join(out_dir, "figures"), exist_ok=True)
        dataset.error_figure(dataset.read(os.path.join(folder, "dataset.csv")),
                             os.path.join(out_dir, "figures", "dataset_model_errors.png"))
        figure = ('<p><img src="figures/dataset_model_errors.png" alt="error of every model '
                  'against the FE dataset"></p>')
    except Exception as err:  # a broken figure must not lose the rest of the report
        print(f"corlab.report: dataset figure failed: {err}", file=sys.stderr)
    t2_rows, better, cases = table2_versus_eq19(fit)
    t2 = ""
    if cases:
        t2 = (f"<h3>The paper's corner: the Table 2 runs of this directory</h3><p>corlab2026 is "
              f"at least as close to the FE value as Ma eq. 19 in {better} of {cases} cases.</p>"
              + table(["model", "cases", "RMS", "worst", "bias"], t2_rows))
    return f"""<p>{scores['rows']} FE runs of corlab's open dataset (<code>{esc(folder)}</code>,
docs/theory/dataset.md): a Sobol design over k2, v/v_y, the modulus ratio, both Poisson ratios,
a yielding sphere and linear hardening. corlab's own model <code>corlab2026</code>
(docs/theory/corlab_model.md) is fitted on {model['rows_train']} of them; a random
{model['rows_random_holdout']} and a corner of {model['rows_corner_holdout']}
({esc(model['corner'])}) are held out. Relative errors (e_model - e_FE)/e_FE; a model's own box
is its calibration box and its assumptions (elastic sphere, perfectly plastic substrate).</p>
{table(head, rows)}
{figure}
<h3>corlab2026: held-out errors by regime</h3>
{table(["held-out set: regime", "cases", "RMS", "worst", "bias"], regimes)}
<p>95 % prediction interval: +-{pct(model['prediction_interval_95'], 1)} of e.</p>
<h3>corlab2026 coefficients (95 % bootstrap intervals)</h3>
{table(["coefficient", "value", "95 % interval"], coef)}
{t2}
{pairs_section(os.path.join(os.path.dirname(folder), "fe_restitution_pairs"))}"""
