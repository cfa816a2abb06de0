#!/usr/bin/python3
"""Assembles the corlab e(v) explorer into one self-contained HTML file (docs/user/explorer.md).

Inlines into explorer/page/explorer.html: the style, plotly.js (Debian's python3-plotly), the
WebAssembly module built by em++ with -sSINGLE_FILE (corlab's C++, explorer/CMakeLists.txt), the
FE dataset's columns the nearest-run search reads (explorer/src/nearest_runs.hpp) and the page's
scripts (SCRIPTS, in that order). The result loads nothing from the network and runs from file://.

    build_page.py --module corlab_explorer.js --plotly plotly.js --dataset dataset.csv \
                  --columns columns.json --out explorer.html
"""
# SPDX-License-Identifier: BSD-3-Clause
import argparse
import csv
import json
import math
import os
import sys
import tempfile
from pathlib import Path

PAGE = Path(__file__).resolve().parent / "page"
# The page's scripts, helpers first: units.js (spec text), link.js (URL state), plot.js (plotly),
# explorer.js (the page logic, which starts it).
SCRIPTS = ["units.js", "link.js", "plot.js", "explorer.js"]
# The dataset columns explorer/src/nearest_runs.cpp reads (runs_from_columns).
DATASET_COLUMNS = ["design_index", "case_id", "status", "included", "k1", "k2", "modulus_ratio",
                   "sphere_yield_ratio", "nu_sphere", "nu_substrate", "hardening_ratio_sphere",
                   "hardening_ratio_substrate", "density_ratio", "velocity", "e", "e_error"]


def script_text(text):
    """Text safe inside a <script> element: no `</` closes it early."""
    return text.replace("</", "<\\/")


def cell(text, kind, name):
    """A CSV cell as JSON: numbers (null for an empty or infinite cell), booleans, text."""
    if kind in ("real", "integer"):
        if text == "":
            return None
        value = float(text)
        if math.isnan(value) or math.isinf(value):
            return None
        return int(value) if kind == "integer" else value
    if kind == "boolean":
        if text not in ("true", "false"):
            raise ValueError(f"dataset column {name}: {text!r} is not true or false")
        return text == "true"
    return text


def dataset_columns(dataset, columns):
    """The columns of DATASET_COLUMNS of dataset.csv, typed by columns.json."""
    kinds = {c["name"]: c["kind"] for c in json.loads(Path(columns).read_text())}
    with open(dataset, newline="") as f:
        rows = list(csv.DictReader(f))
    out = {}
    for name in DATASET_COLUMNS:
        if name not in kinds or (rows and name not in rows[0]):
            raise ValueError(f"dataset column {name!r} is missing from {dataset} or {columns}")
        out[name] = [cell(r[name], kinds[name], name) for r in rows]
    return out


def build(args):
    page = (PAGE / "explorer.html").read_text()
    parts = {
        "@@STYLE@@": (PAGE / "explorer.css").read_text(),
        "@@PLOTLY@@": script_text(Path(args.plotly).read_text()),
        "@@MODULE@@": script_text(Path(args.module).read_text()),
        "@@DATASET@@": script_text(json.dumps(dataset_columns(args.dataset, args.columns),
                                              allow_nan=False, separators=(",", ":"))),
        "@@EXPLORER@@": script_text("\n".join((PAGE / s).read_text() for s in SCRIPTS)),
    }
    for key, text in parts.items():
        if page.count(key) != 1:
            raise ValueError(f"{PAGE / 'explorer.html'}: {key} must appear once")
        head, tail = page.split(key)
        page = head + text + tail
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    with tempfile.NamedTemporaryFile("w", dir=out.parent, delete=False, suffix=".tmp") as f:
        f.write(page)
    os.chmod(f.name, 0o644)
    os.replace(f.name, out)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--module", required=True, help="corlab_explorer.js (em++ SINGLE_FILE)")
    parser.add_argument("--plotly", required=True, help="plotly.js (python3-plotly)")
    parser.add_argument("--dataset", required=True, help="data/fe_restitution/dataset.csv")
    parser.add_argument("--columns", required=True, help="data/fe_restitution/columns.json")
    parser.add_argument("--out", required=True, help="the page to write")
    args = parser.parse_args(argv)
    try:
        build(args)
    except (OSError, ValueError) as err:
        print(f"build_page.py: error: {err}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
