"""HTML formatting of the report's numbers: escaping, significant digits, percentages, tables."""
from __future__ import annotations

import html
import math


def esc(x):
    return html.escape(str(x))


def fmt(x, digits=4):
    try:
        v = float(x)
    except (TypeError, ValueError):
        return "-"
    if math.isnan(v) or math.isinf(v):
        return "-"
    return f"{v:.{digits}g}"


def pct(x, digits=2):
    try:
        v = float(x)
    except (TypeError, ValueError):
        return "-"
    return "-" if math.isnan(v) else f"{100 * v:.{digits}f} %"


def table(headers, rows):
    out = ["<table><tr>" + "".join(f"<th>{esc(h)}</th>" for h in headers) + "</tr>"]
    for r in rows:
        out.append("<tr>" + "".join(f"<td>{c}</td>" for c in r) + "</tr>")
    out.append("</table>")
    return "\n".join(out)
