#!/usr/bin/env python3
"""Coverage of the discretisation-error bars (issue 28; docs/theory/error_bars.md).

Draws cases at random (seeded) from Table 2, the yield-velocity study and the FE dataset's box,
runs each at its default mesh h, at the coarser meshes of every companion set below and at h/2
(a subset also at h/4), then scores every estimator on issue 28's companions and the scatter
estimator on each companion set: the fraction of cases whose finer value lies inside e(h) +/- U,
and the bar's median width against the median |e(h/2) - e(h)|. The runs go to OUT/runs.jsonl as
they finish; a second call resumes (and runs only the meshes a new companion set adds).

    PYTHONPATH=build/python /usr/bin/python3 scripts/error_bar_coverage.py --out out/coverage \
        [--seed 20261127]

The scatter estimator's factor was calibrated with seed 20261127 and checked with 20261128.
Every call also runs the paper's case at the issue's finer meshes (0.18-0.0625 mm).

The estimators are corlab's (corlab.error_bar, one C++ implementation); this script only runs
and counts.
"""
# SPDX-License-Identifier: BSD-3-Clause
import argparse
import concurrent.futures
import csv
import json
import math
import pathlib
import random
import statistics
import sys
import threading

import corlab

ROOT = pathlib.Path(__file__).resolve().parents[1]
SOURCES = {
    "table2": ROOT / "studies/paper/table2.toml",
    "yield_velocity": ROOT / "studies/paper/yield_velocity.toml",
    "dataset": ROOT / "studies/dataset/fe_restitution.toml",
}
# The companion sets scored, each with its scatter estimator (mesh ratios h_i / h): issue 28's,
# corlab's (kErrorBarRatios, discretisation_error.hpp), on which the estimators were compared and
# the scatter factor calibrated, and issue 43's cheaper candidate (not adopted: error_bars.md).
COMPANION_SETS = {
    "issue28": ("scatter", [math.sqrt(2.0), 2.0, 2.0 * math.sqrt(2.0)]),
    "issue43": ("scatter_coarse", [2.0, 2.0 * math.sqrt(2.0), 4.0, 4.0 * math.sqrt(2.0)]),
}
# issue 28's grids: the default h and its companions, on which every estimator is scored.
COARSE_RATIOS = [1.0] + COMPANION_SETS["issue28"][1]
# The meshes of every run: the default h, every set's companions, h/2 (and h/4).
RUN_RATIOS = sorted({q for _, ratios in COMPANION_SETS.values() for q in ratios} | {1.0})
FINE_RATIO = 0.5
FINEST_RATIO = 0.25


def sample_cases(count, seed, max_wall):
    """`count` cases, a third from each source, drawn with `seed`. Dataset points whose default run
    took more than `max_wall` seconds (dataset.csv's wall_s, the slowest tenth: all below 0.01 m/s
    or stiff, dense pairs) are left out of the draw: h/4 of them would take hours."""
    rng = random.Random(seed)
    walls = {}
    with open(ROOT / "data/fe_restitution/dataset.csv") as f:
        for row in csv.DictReader(f):
            if row["wall_s"]:
                walls[row["case_id"]] = float(row["wall_s"])
    cases = []
    names = list(SOURCES)
    for k, name in enumerate(names):
        runs = corlab.load_spec(str(SOURCES[name]))["runs"]
        if name == "dataset":
            runs = [r for r in runs if walls.get(r["id"], math.inf) <= max_wall]
        n = count // len(names) + (1 if k < count % len(names) else 0)
        for r in rng.sample(runs, n):
            cases.append({"case": f"{name}:{r['id']}", "settings": r["settings"]})
    return cases


# The paper's case (5 m/s, the default config at h_min = 0.25 mm) at the finer meshes
# (0.18, 0.125, 0.09 and 0.0625 mm).
PAPER_CASE = {"case": "paper:5m/s", "settings": {}}
PAPER_FINE = [0.72, 0.5, 0.36, 0.25]


def load_done(path):
    done = {}
    if path.exists():
        for line in path.read_text().splitlines():
            if line.strip():
                row = json.loads(line)
                done[(row["case"], row["ratio"])] = row
    return done


def run_one(case, ratio):
    r = corlab.simulate(case["settings"], mesh_ratio=ratio)
    return {"case": case["case"], "ratio": ratio, "settings": case["settings"], "e": r["e"],
            "status": r["status"], "elements": r["elements"], "wall_s": r["wall_s"]}


def run_all(cases, finest_subset, out, jobs):
    path = out / "runs.jsonl"
    done = load_done(path)
    todo = [(PAPER_CASE, q) for q in RUN_RATIOS + PAPER_FINE
            if (PAPER_CASE["case"], q) not in done]
    for i, case in enumerate(cases):
        ratios = RUN_RATIOS + [FINE_RATIO] + ([FINEST_RATIO] if i < finest_subset else [])
        todo += [(case, q) for q in ratios if (case["case"], q) not in done]
    # The cheapest first: a partial study still has whole cases.
    todo.sort(key=lambda t: -t[1])
    lock = threading.Lock()
    with concurrent.futures.ThreadPoolExecutor(jobs) as pool, open(path, "a") as f:
        futures = [pool.submit(run_one, c, q) for c, q in todo]
        for n, fut in enumerate(concurrent.futures.as_completed(futures), 1):
            row = fut.result()
            with lock:
                f.write(json.dumps(row, allow_nan=True) + "\n")
                f.flush()
            print(f"[{n}/{len(todo)}] {row['case']} ratio {row['ratio']:.3f}: e = {row['e']:.6f} "
                  f"({row['status']}, {row['wall_s']:.1f} s)", file=sys.stderr)
    return load_done(path)


def tally(cases, runs, name, ratios):
    """Estimator `name` on the grids h x [1] + ratios: coverage of e(h/2) and e(h/4), the bars'
    median width and the median |e(h/2) - e(h)|."""
    grids = [1.0] + ratios
    hits, total, hits4, total4, widths, diffs = 0, 0, 0, 0, [], []
    for case in cases:
        e = {q: runs.get((case["case"], q), {}).get("e", math.nan)
             for q in grids + [FINE_RATIO, FINEST_RATIO]}
        bar = corlab.error_bar(name, [e[q] for q in grids], grids)
        if not math.isfinite(bar) or not math.isfinite(e[FINE_RATIO]):
            continue
        total += 1
        hits += abs(e[FINE_RATIO] - e[1.0]) <= bar
        widths.append(bar)
        diffs.append(abs(e[FINE_RATIO] - e[1.0]))
        if math.isfinite(e[FINEST_RATIO]):
            total4 += 1
            hits4 += abs(e[FINEST_RATIO] - e[1.0]) <= bar
    median = (lambda v: statistics.median(v) if v else math.nan)
    return {"cases": total, "covered": hits, "cases_h4": total4, "covered_h4": hits4,
            "median_width": median(widths), "median_difference": median(diffs)}


def score(cases, runs):
    """Every estimator on issue 28's companions; each companion set with its estimator."""
    table = {name: tally(cases, runs, name, COMPANION_SETS["issue28"][1])
             for name in corlab.error_bar_estimators()}
    sets = {name: tally(cases, runs, estimator, ratios)
            for name, (estimator, ratios) in COMPANION_SETS.items()}
    return table, sets


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", required=True, help="directory for runs.jsonl and coverage.json")
    ap.add_argument("--cases", type=int, default=48)
    ap.add_argument("--seed", type=int, default=20261127)
    ap.add_argument("--finest-subset", type=int, default=6, help="cases also run at h/4")
    ap.add_argument("--max-wall", type=float, default=20.0, help="dataset points' cost cap [s]")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--score-only", action="store_true", help="count what runs.jsonl has")
    a = ap.parse_args()
    out = pathlib.Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    cases = sample_cases(a.cases, a.seed, a.max_wall)
    runs = load_done(out / "runs.jsonl") if a.score_only else run_all(
        cases, a.finest_subset, out, a.jobs)
    table, sets = score(cases, runs)
    paper = {q: runs.get((PAPER_CASE["case"], q), {}).get("e", math.nan)
             for q in RUN_RATIOS + PAPER_FINE}
    (out / "coverage.json").write_text(json.dumps({"estimators": table, "companion_sets": {
        name: dict(t, estimator=COMPANION_SETS[name][0], ratios=COMPANION_SETS[name][1])
        for name, t in sets.items()}, "paper_case": {
        str(q): e for q, e in paper.items()}}, indent=2) + "\n")
    e1 = paper[1.0]
    print(f"paper case, h = 0.25 mm: e = {e1:.5f}")
    bars = [(name, name, COARSE_RATIOS) for name in corlab.error_bar_estimators()]
    bars += [(f"{est} ({name})", est, [1.0] + q) for name, (est, q) in COMPANION_SETS.items()
             if name != "issue28"]
    for label, name, grids in bars:
        bar = corlab.error_bar(name, [paper[q] for q in grids], grids)
        inside = ", ".join(f"{0.25 * q:.4g} mm {paper[q]:.5f} "
                           f"{'inside' if abs(paper[q] - e1) <= bar else 'OUTSIDE'}"
                           for q in PAPER_FINE)
        print(f"  {label}: +/- {bar:.5f}; {inside}")
    print("| estimator (companions) | e(h/2) inside | e(h/4) inside | median U | "
          "median abs(e(h/2) - e(h)) | width ratio |")
    print("|---|---|---|---|---|---|")
    rows = [(f"{name} (issue28)", t) for name, t in table.items()]
    rows += [(f"{COMPANION_SETS[name][0]} ({name})", t) for name, t in sets.items()
             if name != "issue28"]
    for name, t in rows:
        print(f"| {name} | {t['covered']}/{t['cases']} | {t['covered_h4']}/{t['cases_h4']} | "
              f"{t['median_width']:.2e} | {t['median_difference']:.2e} | "
              f"{t['median_width'] / t['median_difference']:.2f} |")


if __name__ == "__main__":
    main()
