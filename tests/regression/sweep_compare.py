"""Compare two sweep results.csv files.

Exact (the regression tests): same header, same rows after sorting by case_id, with the
machine-dependent columns left out (timings, the build: `machine_dependent` in the one table of
result fields, read through the corlab module, so run with PYTHONPATH=<build>/python). Exit 0 if
equal, 1 with a diff line if not, 2 if the corlab module cannot be imported.
    python3 sweep_compare.py A.csv B.csv [expected_rows]

Relative (two solver versions, e.g. before and after a change, as the README's and the closing
notes' "every e within x %" claims are made): rows joined on case_id; prints the largest relative
change of e and of e_error's reference e_coarse, the runs that moved most, the largest energy
balance of each (NaN entries skipped), and the summed wall_s. Exit 1 if the files do not join
(different cases), are empty or repeat a case id.
    python3 sweep_compare.py --relative A.csv B.csv [--top N]

Against the error bar (a change meant to move e by less than its error bar, issue 43): the same
join; prints the largest |e_B - e_A| / e_error_A, how many runs moved by more than their error bar,
and the largest relative change of e_error. Exit 1 as --relative, or if any run moved by more
than its error bar.
    python3 sweep_compare.py --error-bar A.csv B.csv [--top N]"""
# SPDX-License-Identifier: BSD-3-Clause
import csv
import sys


def timing_columns():
    """The machine-dependent columns of results.csv, from src/fem/solver/result_fields.cpp."""
    try:
        import corlab
    except ImportError as err:
        print(f"sweep_compare.py: cannot import the corlab module ({err}), which names the timing"
              " columns: run with PYTHONPATH=<build>/python (built with CORLAB_BUILD_PYTHON=ON)",
              file=sys.stderr)
        sys.exit(2)
    return {f["name"] for f in corlab.result_fields() if f["in_csv"] and f["machine_dependent"]}


def load(path, timing):
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        keep = [i for i, c in enumerate(header) if c not in timing]
        rows = sorted(tuple(r[i] for i in keep) for r in reader)
    return header, rows


def exact(argv):
    timing = timing_columns()
    ha, a = load(argv[0], timing)
    hb, b = load(argv[1], timing)
    if ha != hb:
        print(f"headers differ:\n  {ha}\n  {hb}")
        return 1
    if len(argv) > 2 and len(a) != int(argv[2]):
        print(f"{argv[0]}: {len(a)} rows, expected {argv[2]}")
        return 1
    if len({r[0] for r in a}) != len(a):
        print(f"{argv[0]}: duplicate case ids")
        return 1
    for ra, rb in zip(a, b):
        if ra != rb:
            print(f"rows differ:\n  {ra}\n  {rb}")
            return 1
    if len(a) != len(b):
        print(f"row counts differ: {len(a)} vs {len(b)}")
        return 1
    print(f"identical: {len(a)} rows (timing columns excluded)")
    return 0


def by_case(path):
    """Rows by case_id; None (after saying why) for an empty file or duplicate case ids."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    cases = {r["case_id"]: r for r in rows}
    if not rows:
        print(f"{path}: no rows")
        return None
    if len(cases) != len(rows):
        print(f"{path}: duplicate case ids")
        return None
    return cases


def largest(values):
    """The largest of the numbers that are not NaN (NaN if none is)."""
    finite = [v for v in values if v == v]
    return max(finite) if finite else float("nan")


def number(row, key):
    try:
        return float(row.get(key, ""))
    except ValueError:
        return float("nan")


def relative_change(ra, rb, key):
    a, b = number(ra, key), number(rb, key)
    return (b - a) / a if a == a and b == b and a != 0.0 else float("nan")


def joined(argv):
    """(a, b, top) of the two files joined on case_id, or None (after saying why)."""
    top = 5
    if "--top" in argv:
        k = argv.index("--top")
        top = int(argv[k + 1])
        argv = argv[:k] + argv[k + 2:]
    a, b = by_case(argv[0]), by_case(argv[1])
    if a is None or b is None:
        return None
    if set(a) != set(b):
        print(f"the files do not join: {len(set(a) ^ set(b))} case ids in only one of them")
        return None
    return a, b, top


def against_error_bar(argv):
    files = joined(argv)
    if files is None:
        return 1
    a, b, top = files
    moves = []
    for c in a:
        d = abs(number(b[c], "e") - number(a[c], "e"))
        bar = number(a[c], "e_error")
        moves.append((d / bar if bar > 0.0 else float("nan"), d, c))
    moves.sort(key=lambda t: -t[0] if t[0] == t[0] else 0.0)
    ratios = [m for m, _, _ in moves if m == m]
    bars = [abs(relative_change(a[c], b[c], "e_error")) for c in a]
    outside = sum(1 for m in ratios if m > 1.0)
    print(f"{len(a)} runs joined on case_id; largest |de| / e_error {largest(ratios):.3e},"
          f" runs moved by more than their error bar: {outside},"
          f" {len(a) - len(ratios)} without an error bar in A;"
          f" e_error: largest |relative change| {largest(bars):.3e}")
    for m, d, c in moves[:top]:
        print(f"  {c}: e {a[c]['e']} -> {b[c]['e']} (|de| {d:.3e} = {m:.3e} x e_error"
              f" {a[c]['e_error']})")
    return 1 if outside else 0


def relative(argv):
    files = joined(argv)
    if files is None:
        return 1
    a, b, top = files
    changes = sorted(((relative_change(a[c], b[c], "e"), c) for c in a),
                     key=lambda t: -abs(t[0]) if t[0] == t[0] else 0.0)
    finite = [d for d, _ in changes if d == d]
    coarse = [abs(relative_change(a[c], b[c], "e_coarse")) for c in a]
    mean = sum(finite) / len(finite) if finite else float("nan")
    print(f"{len(a)} runs joined on case_id; e: largest |change| {largest(map(abs, finite)):.3e}"
          f" (relative), mean change {mean:+.3e}, {len(a) - len(finite)} without a number in"
          f" either file; e_coarse: largest |change| {largest(coarse):.3e}")
    for d, c in changes[:top]:
        print(f"  {c}: e {a[c]['e']} -> {b[c]['e']} ({d:+.3e})")
    for name, rows in (("A", a), ("B", b)):
        balance = largest(number(r, "energy_balance_error") for r in rows.values())
        wall = sum(number(r, "wall_s") for r in rows.values())
        above_one = sum(1 for r in rows.values() if number(r, "e") > 1.0)
        print(f"{name}: largest energy balance {balance:.2e}, runs with e > 1: {above_one},"
              f" summed wall_s {wall:.1f}")
    return 0


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1] == "--relative":
        sys.exit(relative(sys.argv[2:]))
    if len(sys.argv) > 1 and sys.argv[1] == "--error-bar":
        sys.exit(against_error_bar(sys.argv[2:]))
    sys.exit(exact(sys.argv[1:]))
