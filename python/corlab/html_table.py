"""HTML formatting of the report's numbers: escaping, significant digits, percentages, tables;
the table of contents."""
# SPDX-License-Identifier: BSD-3-Clause
from __future__ import annotations

import html
import math
import re


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


def slug_of(title):
    """The anchor of a heading's HTML text: its words in lower case joined by '-'."""
    text = re.sub(r"<[^>]+>", "", html.unescape(title))
    return re.sub(r"[^a-z0-9]+", "-", text.lower()).strip("-") or "section"


def with_contents(body):
    """`body` (the report's HTML) with an id on every <h2> and, before the first one, a table of
    contents linking to each (slugs from the heading's text; a repeated slug gets -2, -3, ...)."""
    entries, seen = [], {}

    def anchor(match):
        title = match.group(1)
        slug = slug_of(title)
        seen[slug] = seen.get(slug, 0) + 1
        if seen[slug] > 1:
            slug = f"{slug}-{seen[slug]}"
        entries.append((slug, title))
        return f'<h2 id="{slug}">{title}</h2>'

    body = re.sub(r"<h2>(.*?)</h2>", anchor, body, flags=re.S)
    if not entries:
        return body
    toc = ('<nav class="toc"><b>Contents</b><ol>' +
           "".join(f'<li><a href="#{slug}">{title}</a></li>' for slug, title in entries) +
           "</ol></nav>\n")
    first = body.index("<h2 id=")
    return body[:first] + toc + body[first:]
