"""An oblique-impact sweep of corlab's 3-D model as a table (issue 27): the rows that rebounded,
by speed and angle, with their error bars, as CSV (--out) and as Markdown on standard output. With
--kharaz (the Kharaz et al. 2001 sweep) the Markdown is the validation table (issue 39, item 6):
at each FE angle both digitisations of the measured points (each interpolated between its own
points, absent outside them), whether the FE lies within their spread plus 0.02 in e_t and plus
10 % in omega, and, given --mbf, the elastic theory of Maw, Barber & Fawcett
(example_mbf_oblique_table); then the readings against the sphere's rigid-body relation
(consistency_markdown): where e_t and omega were both read, which omega the e_t readings imply
and whether any model that obeys the relation can meet both bounds.

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
# The DEM table's reading of the digitisations, and Kharaz's sphere radius [m].
from dem_oblique_check import KHARAZ, RADIUS, interpolate, measured  # noqa: E402

#: The digitisations of data/kharaz2001/measured_points.csv (column `source`), in table order.
SOURCES = ("kratos_chung_ooi_2011", "mfix_di_renzo_di_maio_2004")
#: Issue 39's validation bounds: the FE within the digitisations' spread plus E_T_MARGIN in e_t
#: [-] and plus OMEGA_MARGIN of the measured value in omega [relative].
E_T_MARGIN = 0.02
OMEGA_MARGIN = 0.10
#: A digitisation's end point stands for an angle this close beyond it [deg] (the 2 deg row: the
#: readings start at 2.03 and 2.24 deg).
END_TOLERANCE_DEG = 0.25

#: A homogeneous sphere's moment of inertia over m R^2 [-]: the relation below.
GYRATION = 0.4

#: The table's columns: the name there and the results.csv column it comes from.
COLUMNS = (("impact_velocity", "velocity"), ("impact_angle_deg", "impact.angle"),
           ("e_n", "e_n"), ("e_n_error", "e_error"),
           ("e_t", "e_t"), ("e_t_error", "e_t_error"), ("omega", "omega"),
           ("omega_error", "omega_error"), ("rebound_angle_com", "rebound_angle"),
           ("energy_balance_error", "energy_balance_error"), ("elements", "elements"),
           ("status", "status"), ("corlab_build", "corlab_build"))


def fe_rows(results):
    """The ok rows of a sweep's results.csv, or of a table this script wrote (its columns)."""
    with open(results) as f:
        rows = [r for r in csv.DictReader(f) if r["status"] == "ok"]
    table = bool(rows) and "impact_angle_deg" in rows[0]
    return sorted(({name: r[name if table else source] for name, source in COLUMNS}
                   for r in rows),
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


def reading(points, angle):
    """One digitisation at `angle`: interpolated between its points, its first or last point
    within END_TOLERANCE_DEG beyond them, else None."""
    value = interpolate(points, angle)
    if value is None and points:
        x, y = min(points, key=lambda p: abs(p[0] - angle))
        value = y if abs(x - angle) <= END_TOLERANCE_DEG else None
    return value


def digitisations(angle):
    """{quantity: [the reading of each source in SOURCES that has one]} for e_t and omega."""
    series = {}
    with open(os.path.join(KHARAZ, "measured_points.csv")) as f:
        for row in csv.DictReader(f):
            series.setdefault((row["source"], row["quantity"]), []).append(
                (float(row["impact_angle_deg"]), float(row["value"])))
    out = {}
    for quantity in ("e_t", "omega"):
        values = [reading(series.get((s, quantity), []), angle) for s in SOURCES]
        out[quantity] = [v for v in values if v is not None]
    return out


def within(value, readings, margin, relative):
    """'yes'/'no' for `value` inside [min - m, max + m] of the readings (m = margin, or margin x
    the reading where relative); '–' without a reading."""
    if not readings or math.isnan(value):
        return "–"
    low, high = bounds(readings, margin, relative)
    return "yes" if low <= value <= high else "no (%+.3g)" % (
        value - (low if value < low else high))


def markdown(rows, mbf):
    lines = ["| θ [°] | e_t FE | e_t MBF | e_t meas. (Kratos / MFIX) | within | ω FE [rad/s] "
             "| ω MBF | ω meas. | within | angle FE [°] | angle meas. | e_n FE |",
             "|" + " --- |" * 12]
    for r in rows:
        angle = float(r["impact_angle_deg"])
        m = measured(angle)
        d = digitisations(angle)
        t = mbf.get(angle, {})
        f = {k: number(r[k]) for k in ("e_t", "e_t_error", "omega", "omega_error",
                                       "rebound_angle_com", "e_n", "e_n_error")}
        lines.append("| %g | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            angle, cell(f["e_t"], f["e_t_error"]), cell(float(t["e_t"]) if t else None),
            " / ".join(cell(v) for v in d["e_t"]) or "–",
            within(f["e_t"], d["e_t"], E_T_MARGIN, False),
            cell(f["omega"], f["omega_error"], "%.1f"),
            cell(float(t["omega"]) if t else None, spec="%.0f"),
            " / ".join(cell(v, spec="%.0f") for v in d["omega"]) or "–",
            within(f["omega"], d["omega"], OMEGA_MARGIN, True),
            cell(f["rebound_angle_com"], spec="%.2f"), cell(m["rebound_angle_com"], spec="%.2f"),
            cell(f["e_n"], f["e_n_error"])))
    return "\n".join(lines)


def implied_omega(e_t, speed, angle, radius=RADIUS, gyration=GYRATION):
    """The rebound spin [rad/s] that e_t [-] implies for a sphere of `radius` [m] hit at `speed`
    [m/s] and `angle` [deg] from the normal, from rest: the tangential impulse acts at the contact
    point, so m (1 - e_t) v_t = I omega / R, omega = (1 - e_t) v sin(angle) / (gyration R). Any
    contact law whose force acts at the contact point obeys it (MBF exactly; the FE within its
    lever arm R - delta and the normal pressure's offset)."""
    return (1.0 - e_t) * speed * math.sin(math.radians(angle)) / (gyration * radius)


def bounds(readings, margin, relative):
    """[low, high] of `within`: the readings' spread widened by the margin."""
    low, high = min(readings), max(readings)
    if relative:
        return low * (1.0 - margin), high * (1.0 + margin)
    return low - margin, high + margin


def consistency(angle, speed, d):
    """The e_t and omega readings `d` (digitisations) at `angle` [deg], `speed` [m/s] against the
    rigid-body relation: the readings' mean e_t [-] and the omega it implies [rad/s], the measured
    mean omega, and the e_t interval [-] that meets both the e_t bound and (through the relation)
    the omega bound: (low, high), empty when low > high."""
    e_low, e_high = bounds(d["e_t"], E_T_MARGIN, False)
    w_low, w_high = bounds(d["omega"], OMEGA_MARGIN, True)
    # omega is linear in 1 - e_t and falls as e_t rises: omega's high end gives the lowest e_t.
    per_unit = implied_omega(0.0, speed, angle)  # the spin [rad/s] at e_t = 0
    e_from_w = (1.0 - w_high / per_unit, 1.0 - w_low / per_unit)
    e_t = sum(d["e_t"]) / len(d["e_t"])
    return {"e_t": e_t, "implied_omega": implied_omega(e_t, speed, angle),
            "omega": sum(d["omega"]) / len(d["omega"]),
            "both": (max(e_low, e_from_w[0]), min(e_high, e_from_w[1]))}


def consistency_markdown(rows):
    """Where both e_t and omega were read: the readings against the rigid-body relation, and the
    FE's own (1 - e_t) v_t / (omega R)."""
    lines = ["| θ [°] | e_t meas. (mean) | ω it implies [rad/s] | ω meas. (mean) | ratio "
             "| e_t meeting both bounds | FE (1 − e_t) v_t / (ω R) |", "|" + " --- |" * 7]
    for r in rows:
        angle = float(r["impact_angle_deg"])
        d = digitisations(angle)
        if not d["e_t"] or not d["omega"]:
            continue
        speed = float(r["impact_velocity"])
        c = consistency(angle, speed, d)
        low, high = c["both"]
        e_t, omega = number(r["e_t"]), number(r["omega"])
        fe_ratio = GYRATION * implied_omega(e_t, speed, angle) / omega
        lines.append("| %g | %.4f | %.1f | %.1f | %.3f | %s | %.4f |" % (
            angle, c["e_t"], c["implied_omega"], c["omega"],
            c["omega"] / c["implied_omega"],
            "%.4f – %.4f" % (low, high) if low <= high else "none (%.4f > %.4f)" % (low, high),
            fe_ratio))
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results", help="results.csv of the sweep, or a table written by --out")
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
    print()
    print(consistency_markdown(rows))


if __name__ == "__main__":
    main()
