"""The report's first screen (corlab.report): what was reproduced, the key numbers and links to
the sections that hold them. Every number is fit.json's (computed by ``corlab reproduce``), as in
the rest of the report; this module only picks and formats them."""
# SPDX-License-Identifier: BSD-3-Clause
from __future__ import annotations

import math

from .html_table import esc, fmt, pct, slug_of

# The sections the summary links to: their <h2> text in corlab.report (the anchors are its slugs,
# html_table.with_contents).
COEFFICIENTS = "Fitted coefficients (95 % confidence intervals, Student t)"
MODEL_ERROR = "Error of the paper's model against our solver, per case"
LAW = "Restitution law (paper section 2.1)"
YIELD = "Yield velocity (paper section 2.2)"
VERIFICATION = "Verification (paper section 1)"
MODELS = "Model comparison (paper section 3, Tables 3-4)"
DATASET = "Beyond the paper: corlab's FE dataset and its model"
RUNS = "Runs and time"
DISCUSSION = "Summary"


def link(title, text):
    return f'<a href="#{slug_of(esc(title))}">{esc(text)}</a>'


def _number(x):
    try:
        v = float(x)
    except (TypeError, ValueError):
        return math.nan
    return v


def duration(seconds):
    """'42 s', '3.5 min' or '1.6 h' [s]; '-' when missing."""
    s = _number(seconds)
    if math.isnan(s):
        return "-"
    if s < 120:
        return f"{s:.3g} s"
    return f"{s / 60:.1f} min" if s < 7200 else f"{s / 3600:.1f} h"


def _versus(c, name, digits=4):
    """'name = ours (paper p, +d %, in our 95 % CI)' of a fit.json "versus_paper" entry."""
    if not c or math.isnan(_number(c.get("value"))):
        return None
    where = "inside" if c.get("paper_in_ci") else "outside"
    return (f"{name} = {fmt(c['value'], digits)} against the paper's {fmt(c.get('paper'), digits)}"
            f" ({pct(c.get('relative_difference'), 1)}, {where} our 95 % CI)")


def glance_items(fit):
    """The summary's lines, HTML, in reading order (a missing study's line is left out)."""
    fits = fit.get("fits", {})
    vs = fits.get("versus_paper", {})
    total = fit.get("studies_total", {})
    items = [f"<b>Reproduced</b>: the FE study of Ma et al. (2023) with corlab's solver, preset "
             f"<code>{esc(fit.get('preset', '?'))}</code>: {esc(total.get('runs_on_disk', '-'))}"
             f" finished runs ({duration(total.get('solver_s_on_disk'))} of solver time), its "
             f"Figs. 2-13 redrawn ({link(VERIFICATION, 'verification')}, {link(LAW, 'law')}, "
             f"{link(YIELD, 'yield velocity')}, {link(MODELS, 'models')})."]
    law = [x for x in (_versus(vs.get(k), k) for k in ("slope", "alpha", "beta")) if x]
    if law:
        items.append(f"<b>Restitution law</b> e = a + s ln k1, a = alpha + beta ln k2: "
                     f"{'; '.join(law)} ({link(COEFFICIENTS, 'coefficients')}).")
    overall = fits.get("model_error", {}).get("e_paper", {}).get("overall", {})
    ours = fits.get("model_error", {}).get("e_ours", {}).get("overall", {})
    if overall.get("runs"):
        refitted = (f"; refitted: RMS {pct(ours.get('rms_relative_error'))}, largest "
                    f"{pct(ours.get('largest_relative_error'))}" if ours.get("runs") else "")
        items.append(
            f"<b>The paper's eq. 19 against our FE</b> over {overall['runs']} runs: RMS "
            f"{pct(overall.get('rms_relative_error'))}, largest "
            f"{pct(overall.get('largest_relative_error'))}{refitted} "
            f"({link(MODEL_ERROR, 'per case')}).")
    c26 = fits.get("corlab2026_versus_eq19", {})
    if c26.get("cases"):
        items.append(
            f"<b>corlab2026</b> (corlab's model) on Table 2: RMS "
            f"{pct(c26.get('corlab2026', {}).get('rms'))} against eq. 19's "
            f"{pct(c26.get('ma2023', {}).get('rms'))}; at least as close to the FE in "
            f"{c26.get('corlab2026_at_least_as_close')} of {c26['cases']} runs "
            f"({link(DATASET, 'dataset and model')}).")
    if not math.isnan(_number(vs.get("crossing_velocity_ratio"))):
        items.append(f"<b>Yield velocity</b>: our e = 1 crossings are "
                     f"{fmt(vs['crossing_velocity_ratio'], 3)} x the paper's eq. 18 "
                     f"({link(YIELD, 'Figs. 9-10')}).")
    bars = fits.get("discretisation_error", {}).get("all")
    if bars:
        items.append(f"<b>Error bars</b>: the FE e carry a discretisation error of median "
                     f"{fmt(bars.get('median'), 2)}, largest {fmt(bars.get('max'), 2)} over "
                     f"{bars.get('count')} runs ({link(DISCUSSION, 'discussion')}, "
                     f"{link(RUNS, 'runs and time')}).")
    return items


def glance(fit):
    """The first screen: a short list of the key numbers with links."""
    return ('<div class="glance" id="at-a-glance"><b>At a glance</b><ul>' +
            "".join(f"<li>{i}</li>" for i in glance_items(fit)) + "</ul></div>")
