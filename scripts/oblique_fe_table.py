"""An oblique-impact sweep of corlab's 3-D model as a table (issue 27): the rows that rebounded,
by speed and angle, with their error bars, as CSV (--out) and as Markdown on standard output. With
--kharaz (the Kharaz et al. 2001 sweep) the Markdown compares with the measured points (the mean of
the two digitisations, interpolated) and, given --mbf, with the elastic theory of Maw, Barber &
Fawcett (example_mbf_oblique_table).

    build/bin/corlab sweep studies/oblique/kharaz2001.toml --out OUT --error-estimate
    /usr/bin/python3 scripts/oblique_fe_table.py OUT/results.csv --kharaz \\
        --mbf build/bin/example_mbf_oblique_table --out data/kharaz2001/fe_oblique.csv
    build/bin/corlab sweep studies/oblique/steel_pair.toml --out OUT2 --error-estimate
    /usr/bin/python3 scripts/oblique_fe_table.py OUT2/results.csv \\
        --out data/oblique_studies/steel_pair.csv
"""
# SPDX-License-Identifier: BSD-3-Clause
import argparse
import csv
import io
import math
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "verification", "dem"))
from dem_oblique_check import measured  # noqa: E402  (the DEM table's reading of the points)

#: The table's columns: the name there and the results.csv column it comes from.
COLUMNS = (("impact_velocity", "velocity"), ("impact_angle_deg", "impact.angle"),
           ("e_n", "e_n"), ("e_n_error", "e_error"),
           ("e_t", "e_t"), ("e_t_error", "e_t_error"), ("omega", "omega"),
           ("omega_error", "omega_error"), ("rebound_angle_com", "rebound_angle"),
           ("energy_balance_error", "energy_balance_error"), ("elements", "elements"),
           ("status", "status"), ("corlab_build", "corlab_build"))


def fe_rows(results):
    with open(results) as f:
        rows = [r for r in csv.DictReader(f) if r["status"] == "ok"]
    return sorted(({name: r[source] for name, source in COLUMNS} for r in rows),
                  key=lambda r: (float(r["impact_velocity"]), float(r["impact_angle_deg"])))


def mbf_rows(binary, angles):
    out = subprocess.run([binary, "angles", *angles], check=True, capture_output=True,
                         text=True).stdout
    return {float(r["impact_angle_deg"]): r for r in csv.DictReader(io.StringIO(out))}


def number(text):
    """A results.csv cell as a float; an empty cell (no value: e_t of a normal impact) is nan."""
    return float(text) if text.strip() else math.nan


def cell(value, error=None, spec="%.4f"):
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "–"
    text = spec % value
    return text + (" ± " + spec % error if error is not None and math.isfinite(error) else "")


def plain_markdown(rows):
    """The FE table by speed and angle."""
    lines = ["| v [m/s] | θ [°] | e_n | e_t | ω [rad/s] | rebound angle [°] |",
             "|" + " --- |" * 6]
    for r in rows:
        f = {k: number(r[k]) for k in ("e_n", "e_n_error", "e_t", "e_t_error", "omega",
                                       "omega_error", "rebound_angle_com")}
        lines.append("| %g | %g | %s | %s | %s | %s |" % (
            float(r["impact_velocity"]), float(r["impact_angle_deg"]),
            cell(f["e_n"], f["e_n_error"]),
            cell(f["e_t"], f["e_t_error"]), cell(f["omega"], f["omega_error"], "%.1f"),
            cell(f["rebound_angle_com"], spec="%.2f")))
    return "\n".join(lines)


def markdown(rows, mbf):
    lines = ["| θ [°] | e_t FE | e_t MBF | e_t meas. | ω FE [rad/s] | ω MBF | ω meas. "
             "| angle FE [°] | angle meas. | e_n FE |", "|" + " --- |" * 10]
    for r in rows:
        angle = float(r["impact_angle_deg"])
        m = measured(angle)
        t = mbf.get(angle, {})
        f = {k: number(r[k]) for k in ("e_t", "e_t_error", "omega", "omega_error",
                                       "rebound_angle_com", "e_n", "e_n_error")}
        lines.append("| %g | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            angle, cell(f["e_t"], f["e_t_error"]), cell(float(t["e_t"]) if t else None),
            cell(m["e_t"]), cell(f["omega"], f["omega_error"], "%.1f"),
            cell(float(t["omega"]) if t else None, spec="%.0f"), cell(m["omega"], spec="%.0f"),
            cell(f["rebound_angle_com"], spec="%.2f"), cell(m["rebound_angle_com"], spec="%.2f"),
            cell(f["e_n"], f["e_n_error"])))
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results", help="results.csv of the kharaz2001 sweep")
    parser.add_argument("--kharaz", action="store_true",
                        help="compare with Kharaz et al.'s measured points (data/kharaz2001)")
    parser.add_argument("--mbf", help="with --kharaz: example_mbf_oblique_table (the theory)")
    parser.add_argument("--out", help="write the FE table here (fe_oblique.csv)")
    args = parser.parse_args()
    rows = fe_rows(args.results)
    if args.out:
        with open(args.out, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=[name for name, _ in COLUMNS])
            writer.writeheader()
            writer.writerows(rows)
    if not args.kharaz:
        print(plain_markdown(rows))
        return
    mbf = mbf_rows(args.mbf, [r["impact_angle_deg"] for r in rows]) if args.mbf else {}
    print(markdown(rows, mbf))


if __name__ == "__main__":
    main()
