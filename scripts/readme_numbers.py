#!/usr/bin/python3
"""The README's reproduction numbers, rendered from a reproduction's fit.json, and a check of the
README against them (one source of truth: the C++ writes every number into fit.json).

    /usr/bin/python3 scripts/readme_numbers.py out/report/fit.json                    # print
    /usr/bin/python3 scripts/readme_numbers.py out/report/fit.json --check README.md
        # exit 1 on a mismatch

A fit.json of the paper preset (`make run`) is checked line for line: every rendered line must
stand in the README as printed. Another preset (the coarse one the tests run) meshes and samples
differently, so only what does not depend on the preset is compared: the paper's published
constants of the refit table (fit.json's `paper`).
"""
# SPDX-License-Identifier: BSD-3-Clause
import argparse
import json
import sys

# README refit table: (row label, where our value is in fit.json's `fits`, key in fit.json's
# `paper`, significant digits of our value and CI)
REFIT_ROWS = (
    ("slope s of ln k1 (eq. 9)", ("restitution_law", "slope"), "slope", 4),
    ("alpha (eq. 11)", ("restitution_law", "alpha"), "alpha", 4),
    ("beta (eq. 11)", ("restitution_law", "beta"), "beta", 4),
    ("n in ρ v_y² = b σ̄ⁿ (eq. 15)", ("yield_velocity_fe", "n"), "n", 4),
    ("m in b = c Ē*^m (eq. 17)", ("yield_velocity_fe", "m"), "m", 4),
    ("c in Pa (eq. 17)", ("yield_velocity_fe", "c"), "c", 3),
    ("K of eq. 18 with n = 4.5, m = −3.5", ("yield_velocity_fe", "K_fixed_exponents"), "K", 3),
)


def sig(x, digits):
    """x to `digits` significant digits, plain notation, U+2212 for the minus sign."""
    return f"{x:#.{digits}g}".rstrip(".").replace("-", "−")


def paper_cell(value):
    return f"{value:g}".replace("-", "−")


def difference(ours, paper):
    ratio = ours / paper
    if ratio >= 2:
        return f"×{ratio:.1f}"
    return f"{100 * (ratio - 1):+.1f} %".replace("-", "−")


def refit_row(fit, label, path, paper_key, digits):
    """One README table row, or None when the run has no such fit (e.g. a subset of studies)."""
    fits = fit.get("fits", {})
    value = fits.get(path[0], {}).get(path[1])
    if not isinstance(value, dict) or value.get("value") is None:
        return None
    v, lo, hi = value["value"], value["ci_lower"], value["ci_upper"]
    paper = fit["paper"][paper_key]
    inside = "yes" if lo <= paper <= hi else "no"
    return (f"| {label} | {sig(v, digits)} | [{sig(lo, digits)}, {sig(hi, digits)}] | "
            f"{paper_cell(paper)} | {difference(v, paper)} | {inside} |")


def mesh_line(fit):
    """The mesh study of the report (Fig. 2), coarsest first, and the two finest meshes' change."""
    mesh = fit.get("verification", {}).get("mesh", [])
    if len(mesh) < 2:
        return None
    hs = ", ".join(f"{1e3 * r['h_min']:g}" for r in mesh)
    es = ", ".join(f"{r['e']:.4f}" for r in mesh)
    change = mesh[-1]["e"] / mesh[-2]["e"] - 1
    return (f"h_min = {hs} mm: e = {es}; {1e3 * mesh[-2]['h_min']:g} → "
            f"{1e3 * mesh[-1]['h_min']:g} mm: {100 * change:+.2f} %").replace("-", "−")


def error_bar_line(fit):
    d = fit.get("fits", {}).get("discretisation_error", {}).get("all")
    if not d:
        return None
    return (f"over {d['count']} runs the median error bar is {d['median']:#.2g}, the largest "
            f"{d['max']:#.2g} ({100 * d['max_relative']:.1f} % of e = {d['max_case']['e']:.3f})")


def eq19_line(fit):
    err = fit.get("fits", {}).get("model_error", {})
    paper, ours = err.get("e_paper", {}).get("overall"), err.get("e_ours", {}).get("overall")
    if not paper or not paper.get("runs") or not ours:
        return None
    return (f"eq. 19 with the paper's constants against our {paper['runs']} runs: RMS "
            f"{100 * paper['rms_relative_error']:.1f} %, largest "
            f"{100 * abs(paper['largest_relative_error']):.0f} %; with our refitted constants RMS "
            f"{100 * ours['rms_relative_error']:.1f} %")


def corlab2026_line(fit):
    t = fit.get("fits", {}).get("corlab2026_versus_eq19")
    if not t or not t.get("cases"):
        return None
    c, m = t["corlab2026"], t["ma2023"]
    return (f"on the {t['cases']} Table 2 runs corlab2026 has RMS {100 * c['rms']:.1f} % against "
            f"eq. 19's {100 * m['rms']:.1f} %, and is at least as close in "
            f"{t['corlab2026_at_least_as_close']} of {t['cases']}")


def lines(fit):
    """Every README line this fit.json gives, in README order (None where it has no such number)."""
    out = [refit_row(fit, *row) for row in REFIT_ROWS]
    return out + [mesh_line(fit), error_bar_line(fit), eq19_line(fit), corlab2026_line(fit)]


def table_paper_cells(readme):
    """The refit table's paper column as the README shows it: {row label: cell}."""
    cells = {}
    labels = {row[0] for row in REFIT_ROWS}
    for line in readme.splitlines():
        parts = [p.strip() for p in line.strip().strip("|").split("|")]
        if len(parts) == 6 and parts[0] in labels:
            cells[parts[0]] = parts[3]
    return cells


def check(fit, readme):
    """The README's mismatches with this fit.json (empty when it agrees)."""
    problems = []
    cells = table_paper_cells(readme)
    for label, _, key, _ in REFIT_ROWS:
        want = paper_cell(fit["paper"][key])
        if cells.get(label) != want:
            problems.append(f"refit table row {label!r}: paper column {cells.get(label)!r}, "
                            f"fit.json's paper value {want!r}")
    if fit.get("preset") == "paper":
        # "|" of a table row and the sentence fragments alike: each must stand in the README.
        flat = " ".join(readme.split())
        for line in lines(fit):
            if line is not None and line not in flat:
                problems.append(f"not in the README: {line}")
    return problems


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("fit_json", help="fit.json of `corlab reproduce`")
    parser.add_argument("--check", metavar="README", help="compare this README with fit.json")
    args = parser.parse_args(argv)
    with open(args.fit_json) as f:
        fit = json.load(f)
    if not args.check:
        print("\n".join(line for line in lines(fit) if line is not None))
        return 0
    with open(args.check) as f:
        problems = check(fit, f.read())
    scope = "every number" if fit.get("preset") == "paper" else "the preset-independent numbers"
    for p in problems:
        print(p)
    print(f"{args.check} against {args.fit_json} (preset {fit.get('preset')}, {scope}): "
          f"{len(problems)} mismatches")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
