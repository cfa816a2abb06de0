"""Every fitted coefficient of a new fit.json against its 95 % interval in an old one (issue 43).

Walks both files' `fits` and compares each coefficient that carries an interval (an object with
value, ci_lower and ci_upper): the new value inside [ci_lower, ci_upper] of the old, and its shift
in old half-widths. Prints the count, the largest shifts and every one outside; exit 1 if one is
outside, 2 on bad input.
    python3 scripts/fit_interval_check.py OLD/fit.json NEW/fit.json [--show N]"""
# SPDX-License-Identifier: BSD-3-Clause
import argparse
import json
import math
import sys


def coefficients(old, new, path=""):
    """(path, old value, new value, ci_lower, ci_upper) of every coefficient with an interval."""
    if isinstance(old, dict) and isinstance(new, dict):
        if {"value", "ci_lower", "ci_upper"} <= old.keys() and "value" in new:
            yield path, old["value"], new["value"], old["ci_lower"], old["ci_upper"]
            return
        for key in old:
            if key in new:
                yield from coefficients(old[key], new[key], f"{path}/{key}")
    elif isinstance(old, list) and isinstance(new, list):
        for i, (a, b) in enumerate(zip(old, new)):
            yield from coefficients(a, b, f"{path}[{i}]")


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("old")
    parser.add_argument("new")
    parser.add_argument("--show", type=int, default=10, help="largest shifts printed")
    args = parser.parse_args(argv)
    try:
        with open(args.old) as f:
            old = json.load(f)["fits"]
        with open(args.new) as f:
            new = json.load(f)["fits"]
    except (OSError, ValueError, KeyError) as err:
        print(f"fit_interval_check: {err}", file=sys.stderr)
        return 2
    rows = []
    for path, v0, v1, lo, hi in coefficients(old, new):
        if not all(isinstance(x, (int, float)) for x in (v0, v1, lo, hi)):
            continue
        half = 0.5 * (hi - lo)
        shift = (v1 - v0) / half if half > 0 else (0.0 if v1 == v0 else math.inf)
        rows.append((path, v0, v1, lo, hi, shift, lo <= v1 <= hi))
    outside = [r for r in rows if not r[6]]
    print(f"{len(rows)} coefficients with a 95 % interval; {len(outside)} outside the old one")
    largest = sorted(rows, key=lambda r: -abs(r[5]))[:args.show]
    for path, v0, v1, lo, hi, shift, inside in largest + [r for r in outside if r not in largest]:
        print(f"  {path}: {v0:.6g} -> {v1:.6g} in [{lo:.6g}, {hi:.6g}], "
              f"shift {shift:+.3g} half-widths{'' if inside else '  OUTSIDE'}")
    return 1 if outside else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
