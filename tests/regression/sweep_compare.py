"""Compare two sweep results.csv files: same header, same rows after sorting by case_id, with the
timing columns (wall_s, element_steps_per_s) left out. Exit 0 if equal, 1 with a diff line if not.
Usage: python3 sweep_compare.py A.csv B.csv [expected_rows]"""
import csv
import sys

TIMING = {"wall_s", "element_steps_per_s"}


def load(path):
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        keep = [i for i, c in enumerate(header) if c not in TIMING]
        rows = sorted(tuple(r[i] for i in keep) for r in reader)
    return header, rows


def main():
    ha, a = load(sys.argv[1])
    hb, b = load(sys.argv[2])
    if ha != hb:
        print(f"headers differ:\n  {ha}\n  {hb}")
        return 1
    if len(sys.argv) > 3 and len(a) != int(sys.argv[3]):
        print(f"{sys.argv[1]}: {len(a)} rows, expected {sys.argv[3]}")
        return 1
    if len({r[0] for r in a}) != len(a):
        print(f"{sys.argv[1]}: duplicate case ids")
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


if __name__ == "__main__":
    sys.exit(main())
