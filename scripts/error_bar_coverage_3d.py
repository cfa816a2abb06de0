#!/usr/bin/env python3
"""Coverage of the 3-D model's error bars on e_n, e_t and omega (issue 39, item 5;
docs/theory/error_bars.md, "The 3-D model").

Draws oblique cases at random (seeded): angles 2-80 deg, mu 0.1-0.4, alternately elastic (normal
speeds 2-10 m/s) and elastic-plastic (the flat's sigma_y 300-1000 MPa, normal speeds 1-2.5 m/s,
where the plastic contact stays below R/5, so that the companions up to 2h stay within the
sphere mesh's bound R/20): the paper's steel pair scaled to a 2.5 mm sphere on a 2.5 mm block, at
h = a/4 (the 3-D model's default a/h), at most R/20. Each case runs at h (in full, as the
estimate's run), at the companions sqrt 2, 2^(3/4) and 2 h and at h / sqrt 2 (for e only, as the
estimate's companions: SimulationControl::e_only; h/2 would cost about 16 runs at h), one run at
a time, cheapest first; every run is appended to OUT/runs.csv as it finishes, and a second call
resumes (`--cases 12`: the sample's first 12, the same draws; each row names the corlab build
that made it). Then it scores corlab's bars (e_n by scatter_3d_e_n, e_t and omega by scatter)
and every estimator of
corlab.error_bar_estimators() on the companions corlab keeps (>= 2 elements across the predicted
contact radius): per quantity, the cases whose h / sqrt 2 value lies inside the bar, and the
median bar over the median |x(h / sqrt 2) - x(h)| (both relative to |x(h)|); and the observed
order p of each quantity, from x(h) - x(h / sqrt 2) = (1 - 2^(-p/2)) (x(h) - x*) against the
nearest companion: p = -2 log2 |x(h / sqrt 2) - x(h)| / |x(h) - x(sqrt 2 h)|.

    PYTHONPATH=build/python nice /usr/bin/python3 scripts/error_bar_coverage_3d.py \
        --out out/coverage3d [--seed 20261129] [--cases 24] [--score-only]

The estimators are corlab's (corlab.error_bar, one C++ implementation); this script only runs and
counts, and `--score-only` re-estimates from runs.csv without running anything.
"""
# SPDX-License-Identifier: BSD-3-Clause
import argparse
import csv
import json
import math
import pathlib
import random
import re
import statistics
import sys

import corlab

QUANTITIES = ["e_n", "e_t", "omega"]
# The finer mesh the bars are checked against: h / sqrt 2 (h / 2 costs 16 runs at h).
REFERENCE = 2.0 ** -0.5
# corlab's 3-D companions (kErrorBarRatios3d), kept where MIN_CONTACT_ELEMENTS fit across a.
COMPANIONS = [2.0 ** 0.5, 2.0 ** 0.75, 2.0]
MIN_CONTACT_ELEMENTS = 2.0
# The estimator corlab's 3-D estimate uses per quantity (error_bar_estimator, kDefaultErrorBar).
CORLAB_3D = {"e_n": "scatter_3d_e_n", "e_t": "scatter", "omega": "scatter"}
# Every mesh ratio a case runs at, cheapest first, the reference last (the dearest).
RATIOS = COMPANIONS[::-1] + [1.0, REFERENCE]
# The case's own mesh: a/4 (the 3-D model's default a/h), at most R/20 (the sphere mesh's bound),
# graded fast (growth 1.6 up to 1 mm) so that h / sqrt 2 stays affordable.
BASE = {
    "solver.model": "3d",
    "sphere.radius": 2.5e-3,
    "substrate.radius": 2.5e-3,
    "substrate.depth": 2.5e-3,
    "mesh.contact_elements": 4.0,
    "mesh.h_min": 2.5e-3 / 20.0,
    "mesh.h_max": 1e-3,
    "mesh.growth": 1.6,
}
FIELDS = ["case", "ratio", "angle", "velocity", "friction", "sigma_y", "a_over_h", "e_n", "e_t",
          "omega", "elements", "status", "wall_s", "corlab_build"]


def sample_cases(count, seed):
    """`count` cases drawn with `seed`, elastic and elastic-plastic alternately."""
    rng = random.Random(seed)
    cases = []
    for k in range(count):
        angle = round(rng.uniform(2.0, 80.0), 2)
        u = rng.uniform(0.0, 1.0)
        friction = round(rng.uniform(0.1, 0.4), 3)
        sigma_y = None if k % 2 == 0 else round(rng.uniform(300.0, 1000.0)) * 1e6
        normal = 2.0 * 5.0 ** u if sigma_y is None else 2.5 ** u  # [m/s]
        velocity = round(normal / math.cos(math.radians(angle)), 3)
        settings = dict(BASE, **{"impact.angle": angle, "impact.velocity": velocity,
                                 "contact.friction": friction,
                                 "substrate.sigma_y": "none" if sigma_y is None else sigma_y})
        cases.append({"case": f"s{seed}-{k:02d}", "angle": angle, "velocity": velocity,
                      "friction": friction, "sigma_y": sigma_y, "settings": settings})
    return cases


def load_runs(path, cases):
    """The runs of `cases` in runs.csv by (case, ratio); a row made with other settings (an
    earlier draw of the same name) is left out."""
    velocity = {c["case"]: c["velocity"] for c in cases}
    runs = {}
    if path.exists():
        with open(path) as f:
            for row in csv.DictReader(f):
                if float(row["velocity"]) == velocity.get(row["case"]):
                    runs[(row["case"], round(float(row["ratio"]), 6))] = row
    return runs


def run_one(case, q):
    """One run of `case` at mesh ratio q: its runs.csv row."""
    row = {k: case[k] for k in ("case", "angle", "velocity", "friction", "sigma_y")}
    row["ratio"] = q
    try:
        r = corlab.simulate(case["settings"], mesh_ratio=q, e_only=q != 1.0)
    except ValueError as err:  # a companion beyond R/20: left out, as corlab does
        row.update(status="refused", a_over_h=math.nan)
        print(f"{case['case']} ratio {q:.3f}: {err}", file=sys.stderr, flush=True)
        return row
    a_over_h = float(re.search(r"a/h = ([0-9.e+-]+)", r["mesh_reason"]).group(1))
    row.update(a_over_h=a_over_h, e_n=r["e_n"], e_t=r["e_t"], omega=r["omega"],
               elements=r["elements"], status=r["status"], wall_s=r["wall_s"],
               corlab_build=r["corlab_build"])
    print(f"{case['case']} ratio {q:.3f}: a/h {a_over_h:.3g} e_n {r['e_n']:.5f} "
          f"e_t {r['e_t']:.5f} omega {r['omega']:.2f} ({r['status']}, "
          f"{r['elements']} elements, {r['wall_s']:.1f} s)", file=sys.stderr, flush=True)
    return row


def run_all(cases, path):
    done = load_runs(path, cases)
    new = not path.exists()
    # A runs.csv from before a column was added keeps its own header (the new column left out).
    fields = FIELDS if new else next(csv.reader(open(path)))
    with open(path, "a", newline="") as f:
        out = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        if new:
            out.writeheader()
        # Case by case (a partial sample has whole cases), each cheapest first.
        for case in cases:
            for q in RATIOS:
                if (case["case"], round(q, 6)) not in done:
                    out.writerow(run_one(case, q))
                    f.flush()
    return load_runs(path, cases)


def value(runs, case, q, quantity):
    row = runs.get((case, round(q, 6)))
    if row is None or row["status"] != "separated":
        return math.nan
    return float(row[quantity])


def companions_of(runs, case):
    """corlab's companions that ran and keep the contact resolved (others are left out, as
    corlab leaves them out)."""
    kept = []
    for q in COMPANIONS:
        row = runs.get((case, round(q, 6)))
        if row is not None and row["status"] == "separated" and \
                float(row["a_over_h"]) >= MIN_CONTACT_ELEMENTS * (1 - 1e-9):
            kept.append(q)
    return kept


def median(v):
    return statistics.median(v) if v else math.nan


def score(cases, runs, names=None, bar_scale=1.0):
    """Per estimator and quantity: cases with a bar, covered, the median bar and the median
    |x(h / sqrt 2) - x(h)|, and their ratio over the values relative to |x(h)| (omega spans
    30-4000 rad/s over the sample: absolute medians would compare different cases). Every bar is
    multiplied by bar_scale: a candidate factor's ratio to the estimator's own."""
    table = {}
    for name in names or ["corlab"] + corlab.error_bar_estimators():
        for quantity in QUANTITIES:
            estimator = CORLAB_3D[quantity] if name == "corlab" else name
            hits, widths, diffs, rel_widths, rel_diffs, misses = 0, [], [], [], [], []
            for case in cases:
                ratios = [1.0] + companions_of(runs, case["case"])
                x = [value(runs, case["case"], q, quantity) for q in ratios]
                ref = value(runs, case["case"], REFERENCE, quantity)
                bar = bar_scale * corlab.error_bar(estimator, x, ratios)
                if not (math.isfinite(bar) and math.isfinite(ref)):
                    continue
                d = abs(ref - x[0])
                hits += d <= bar
                if d > bar:
                    misses.append(f"{case['case'][-2:]} ({d / bar if bar > 0 else math.inf:.2f})")
                widths.append(bar)
                diffs.append(d)
                rel_widths.append(bar / abs(x[0]))
                rel_diffs.append(d / abs(x[0]))
            rel = median(rel_diffs)
            width = median(rel_widths) / rel if rel > 0 else math.nan
            table[f"{name}:{quantity}"] = {
                "cases": len(widths), "covered": hits, "median_bar": median(widths),
                "median_change": median(diffs), "width_ratio": width,
                "width_at_95": width * scale_to_95(widths, diffs), "misses": misses}
    return table


def scale_to_95(bars, changes):
    """The factor that scales every bar just enough to hold 95 % of the changes (the
    ceil(0.95 n)-th smallest change / bar): the width the estimator's shape of bar would need to
    meet the coverage (width_at_95 = width_ratio times it)."""
    ratios = sorted(d / b if b > 0 else math.inf for b, d in zip(bars, changes))
    return ratios[math.ceil(0.95 * len(ratios)) - 1] if ratios else math.nan


def observed_orders(cases, runs):
    """Per quantity (and elastic / elastic-plastic): the median observed order p from the
    nearest companion and the reference, and the cases with a p (both changes nonzero)."""
    orders = {}
    for quantity in QUANTITIES:
        for kind in ("elastic", "elastic-plastic"):
            p = []
            for case in cases:
                if (case["sigma_y"] is None) != (kind == "elastic"):
                    continue
                x = [value(runs, case["case"], q, quantity) for q in (REFERENCE, 1.0, 2.0 ** 0.5)]
                fine, coarse = abs(x[0] - x[1]), abs(x[2] - x[1])
                if all(map(math.isfinite, x)) and fine > 0 and coarse > 0:
                    p.append(-2.0 * math.log2(fine / coarse))
            orders[f"{quantity}:{kind}"] = {
                "cases": len(p), "median_order": median(p),
                "quartiles": statistics.quantiles(p, n=4)[::2] if len(p) > 1 else []}
    return orders


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", required=True, help="directory for runs.csv and coverage.json")
    ap.add_argument("--cases", type=int, default=24)
    ap.add_argument("--seed", type=int, default=20261129)
    ap.add_argument("--score-only", action="store_true", help="count what runs.csv has")
    ap.add_argument("--bar-scale", type=float, default=1.0,
                    help="score every bar times this (a candidate factor over today's)")
    a = ap.parse_args()
    out = pathlib.Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    cases = sample_cases(a.cases, a.seed)
    path = out / "runs.csv"
    runs = load_runs(path, cases) if a.score_only else run_all(cases, path)
    table = score(cases, runs, bar_scale=a.bar_scale)
    # corlab's bars on each kind: the elastic runs converge faster than their companions scatter
    by_kind = {kind: score([c for c in cases if (c["sigma_y"] is None) == (kind == "elastic")],
                           runs, ["corlab"], a.bar_scale)
               for kind in ("elastic", "elastic-plastic")}
    orders = observed_orders(cases, runs)
    if a.bar_scale == 1.0:  # a candidate's score is printed only: coverage.json is corlab's
        (out / "coverage.json").write_text(
            json.dumps({"bars": table, "bars_by_kind": by_kind, "orders": orders}, indent=2) + "\n")
    print("| estimator | quantity | inside | median bar | median change | width ratio | "
          "width at 95 % | misses |")
    print("|---|---|---|---|---|---|---|---|")
    rows = list(table.items()) + [(f"{key} ({kind})", t) for kind, kt in by_kind.items()
                                  for key, t in kt.items()]
    for key, t in rows:
        name, quantity = key.split(":")
        print(f"| {name} | {quantity} | {t['covered']}/{t['cases']} | {t['median_bar']:.3g} | "
              f"{t['median_change']:.3g} | {t['width_ratio']:.2f} | {t['width_at_95']:.2f} | "
              f"{', '.join(t['misses'])} |")
    print("\n| quantity | cases | observed order p (median) | quartiles |")
    print("|---|---|---|---|")
    for key, o in orders.items():
        quartiles = ", ".join(f"{v:.2f}" for v in o["quartiles"])
        print(f"| {key} | {o['cases']} | {o['median_order']:.2f} | {quartiles} |")


if __name__ == "__main__":
    main()
