"""Side by side per study: two reproductions (or samples) of the paper studies, before and after.

For each study present in both output folders: the runs joined on their swept inputs (the
columns between status and e: a key added to a study's [base] changes every case_id), the largest
|e_after - e_before| / e_error_before (and its case), the summed main runs' element updates
(elements x steps: what the load cannot touch) and summed wall_s, each as after / before. Exit 1 if
a run moved by more than FRACTION of its error bar (default 0.2), 2 on bad input (issue 43).
    python3 scripts/paper_sample_compare.py BEFORE_DIR AFTER_DIR [--fraction F]
(BEFORE_DIR/STUDY/results.csv as `corlab reproduce --out` writes them.)"""
# SPDX-License-Identifier: BSD-3-Clause
import argparse
import csv
import math
import os
import sys


def read(path):
    """{inputs: row}, the inputs the values of the columns between status and e."""
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        names = reader.fieldnames
        inputs = names[names.index("status") + 1:names.index("e")]
        return {",".join(row[k] for k in inputs): row for row in reader}


def number(row, key):
    try:
        return float(row[key])
    except (KeyError, ValueError):
        return math.nan


def compare(before, after):
    """(runs, largest |de|/e_error, its case (before), element-updates ratio, wall ratio)."""
    worst, worst_case = 0.0, ""
    cost = {"b": 0.0, "a": 0.0}
    wall = {"b": 0.0, "a": 0.0}
    common = sorted(set(before) & set(after))
    for case in common:
        b, a = before[case], after[case]
        ratio = abs(number(a, "e") - number(b, "e")) / number(b, "e_error")
        if math.isfinite(ratio) and ratio > worst:
            worst, worst_case = ratio, b["case_id"]
        for key, row in (("b", b), ("a", a)):
            cost[key] += number(row, "elements") * number(row, "steps")
            wall[key] += number(row, "wall_s")
    return len(common), worst, worst_case, cost["a"] / cost["b"], wall["a"] / wall["b"]


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("before_dir")
    parser.add_argument("after_dir")
    parser.add_argument("--fraction", type=float, default=0.2)
    args = parser.parse_args(argv)
    before_dir, after_dir, fraction = args.before_dir, args.after_dir, args.fraction
    moved = False
    print(f"{'study':16s} {'runs':>4s} {'max|de|/e_err':>13s} {'case':>11s} "
          f"{'elem-steps':>10s} {'wall_s':>7s}")
    for study in sorted(os.listdir(before_dir)):
        b = os.path.join(before_dir, study, "results.csv")
        a = os.path.join(after_dir, study, "results.csv")
        if not (os.path.isfile(b) and os.path.isfile(a)):
            continue
        runs, worst, case, cost, wall = compare(read(b), read(a))
        moved = moved or worst > fraction
        print(f"{study:16s} {runs:4d} {worst:13.3g} {case:>11s} {cost:10.3f} {wall:7.3f}")
    return 1 if moved else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
