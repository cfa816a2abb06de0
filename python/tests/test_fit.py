"""Fitting from Python: fit_linear (NIST Norris), fit_expression (NIST Misra1a, user forms),
fit_paper (Ma et al. 2023 forms on a synthetic results.csv)."""
# SPDX-License-Identifier: BSD-3-Clause
import csv
import math
import subprocess
import pathlib

import numpy as np
import pytest

import corlab

NIST = pathlib.Path(__file__).resolve().parents[2] / "data" / "nist"


def read_nist(name):
    """(y, x, certified {name: (value, sd)}, starts {start1: [..]}) of data/nist/<name>.dat."""
    y, x, cert, starts = [], [], {}, {}
    for line in (NIST / name).read_text().splitlines():
        tok = line.split()
        if not tok:
            continue
        if tok[0] == "#":
            if len(tok) > 3 and tok[1] == "certified":
                sd = float(tok[5]) if len(tok) > 5 and tok[4] == "sd" else None
                cert[tok[2]] = (float(tok[3]), sd)
            elif len(tok) > 2 and tok[1].startswith("start"):
                starts[tok[1]] = [float(v) for v in tok[3::2]]
            continue
        y.append(float(tok[0]))
        x.append(float(tok[1]))
    return np.array(y), np.array(x), cert, starts


def digits(a, b):
    return 16.0 if a == b else -math.log10(abs(a - b) / abs(b))


def test_fit_linear_matches_nist_norris_to_at_least_six_digits():
    y, x, cert, _ = read_nist("Norris.dat")
    fit = corlab.fit_linear(np.column_stack([np.ones_like(x), x]), y, names=["B0", "B1"])
    b0, b1 = fit["coefficients"]
    assert b0["name"] == "B0"
    assert digits(b0["value"], cert["B0"][0]) >= 6
    assert digits(b1["value"], cert["B1"][0]) >= 6
    assert digits(b0["standard_error"], cert["B0"][1]) >= 6
    assert digits(b1["standard_error"], cert["B1"][1]) >= 6
    assert digits(fit["goodness"]["r_squared"], cert["r_squared"][0]) >= 6
    assert fit["dof"] == 34
    assert b1["ci_lower"] < b1["value"] < b1["ci_upper"]


def test_fit_linear_rejects_collinear_columns():
    X = np.column_stack([np.ones(5), 2 * np.ones(5)])
    with pytest.raises(ValueError, match="rank deficient"):
        corlab.fit_linear(X, np.arange(5.0))


def test_fit_expression_matches_nist_misra1a_to_at_least_four_digits():
    y, x, cert, starts = read_nist("Misra1a.dat")
    for start in ("start1", "start2"):
        b1, b2 = starts[start]
        fit = corlab.fit_expression("y ~ b1*(1-exp(-b2*x))", {"b1": b1, "b2": b2},
                                    {"x": x.tolist(), "y": y.tolist()})
        assert fit["converged"], fit["message"]
        got = {c["name"]: c for c in fit["coefficients"]}
        for name in ("b1", "b2"):
            assert digits(got[name]["value"], cert[name][0]) >= 4
            assert digits(got[name]["standard_error"], cert[name][1]) >= 4


def test_fit_expression_user_form_with_filter_covers_truth():
    rng = np.random.default_rng(3)
    lk1 = np.tile(np.linspace(8, 22, 10), 4)
    lk2 = np.repeat([-6.0, -5.5, -5.0, -4.5], 10)
    e = np.minimum(1.0, 1.16 + 0.253 * lk2 + 0.056 * lk1 + rng.normal(0, 0.005, lk1.size))
    fit = corlab.fit_expression("e ~ alpha + beta*ln(k2) + s*ln(k1)",
                                {"alpha": 1.0, "s": 0.1, "beta": 0.1},
                                {"e": e.tolist(), "k1": np.exp(lk1).tolist(),
                                 "k2": np.exp(lk2).tolist()}, where="e < 0.999")
    assert fit["observations"] < e.size
    assert [c["name"] for c in fit["coefficients"]] == ["alpha", "s", "beta"]  # dict order
    truth = {"alpha": 1.16, "beta": 0.253, "s": 0.056}
    for c in fit["coefficients"]:
        assert c["ci_lower"] <= truth[c["name"]] <= c["ci_upper"]


def test_fit_expression_bad_form_is_a_value_error():
    with pytest.raises(ValueError, match="unknown name 'z'"):
        corlab.fit_expression("y ~ a*z", {"a": 1.0}, {"x": [1.0, 2, 3], "y": [1.0, 2, 3]})


def write_results(path, rows, extra=()):
    cols = ["case_id", "status", "e", "velocity", "sphere_rho", "E_star", "sigma_y", "k1", "k2"]
    cols += list(extra)
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(cols)
        for r in rows:
            w.writerow([r.get(c, "") for c in cols])


def paper_rows():
    """A synthetic results table from the paper's own law: 3 densities x 5 yield stresses x 7 v."""
    es = 210e9 / (2 * (1 - 0.3 ** 2))
    rows, k = [], 0
    for rho in (3925.0, 7850.0, 15700.0):
        for sy in (300e6, 500e6, 700e6, 1000e6, 1300e6):
            for v in (0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0):
                k1, k2 = es / (rho * v * v), sy / es
                e = min(1.0, 1.16 + 0.253 * math.log(k2) + 0.056 * math.log(k1))
                rows.append({"case_id": f"c{k}", "status": "ok", "e": e, "velocity": v,
                             "sphere_rho": rho, "E_star": es, "sigma_y": sy, "k1": k1, "k2": k2,
                             "error": ""})
                k += 1
    return rows


def test_fit_paper_recovers_the_paper_constants_from_its_own_model(tmp_path):
    rows = paper_rows()
    rows.append(dict(rows[0], case_id="bad", status="failed", e="nan"))
    write_results(tmp_path / "results.csv", rows)
    fit = corlab.fit_paper(str(tmp_path / "results.csv"))
    law = fit["restitution_law"]
    assert law["slope"]["value"] == pytest.approx(0.056, abs=1e-10)
    assert law["alpha"]["value"] == pytest.approx(1.16, abs=1e-9)
    assert law["beta"]["value"] == pytest.approx(0.253, abs=1e-10)
    assert law["slope"]["paper"] == 0.056
    assert len(law["cases"]) == 15
    assert fit["yield_velocity"] is None  # one E* only


def test_fit_paper_missing_file_is_a_value_error(tmp_path):
    with pytest.raises(ValueError):
        corlab.fit_paper(str(tmp_path / "nope.csv"))


def test_fit_lists_every_excluded_row_with_its_reason(tmp_path, corlab_bin):
    """issue 12 item 3: rows with e = nan / inf / < 0, failed or elastic are named, not lost."""
    rows = paper_rows()
    bad = {"bad_nan": "nan", "bad_inf": "inf", "bad_negative": "-0.5"}
    for case_id, e in bad.items():
        rows.append(dict(rows[10], case_id=case_id, e=e))
    rows.append(dict(rows[10], case_id="bad_failed", status="failed", e=""))
    rows.append(dict(rows[10], case_id="bad_elastic", sigma_y=""))  # no value: elastic
    rows.append(dict(rows[10], case_id="bad_zero_yield", sigma_y="0"))
    write_results(tmp_path / "results.csv", rows)
    fit = corlab.fit_paper(str(tmp_path / "results.csv"))
    reasons = {r["case_id"]: r["reason"] for r in fit["excluded"]}
    assert reasons["bad_nan"] == "e = nan" and reasons["bad_inf"] == "e = inf"
    assert reasons["bad_negative"] == "e = -0.5: not > 0"
    assert reasons["bad_failed"] == "status = failed"
    assert reasons["bad_elastic"] == "no sigma_y: elastic substrate"
    assert reasons["bad_zero_yield"] == "sigma_y = 0: elastic substrate"
    clamped = [r for r in rows if r["case_id"].startswith("c") and r["e"] >= 1 - 1e-3]
    assert clamped
    assert all(reasons[r["case_id"]].endswith(": elastic (>= 1 - 0.001)") for r in clamped)
    assert fit["rows"] == len(rows)
    assert fit["rows_excluded"] == len(reasons) == len(rows) - fit["restitution_law"]["points_used"]
    assert fit["restitution_law"]["slope"]["value"] == pytest.approx(0.056, abs=1e-10)
    # the CLI lists them too, one per line
    out = subprocess.run([corlab_bin, "fit", str(tmp_path / "results.csv")],
                         capture_output=True, text=True, check=True).stdout
    assert f"excluded rows ({len(reasons)}):" in out
    assert "  bad_inf: e = inf\n" in out and "  bad_failed: status = failed\n" in out


def test_fit_leaves_out_suspect_runs_unless_asked_and_says_which(tmp_path, corlab_bin):
    """issue 12 item 1: a run flagged suspect (quality guards) is not fitted by default."""
    rows = paper_rows()
    write_results(tmp_path / "clean.csv", rows, extra=["suspect"])
    clean = corlab.fit_paper(str(tmp_path / "clean.csv"))["restitution_law"]
    reason = "energy balance error 0.12 > 0.01"
    rows.append(dict(rows[10], case_id="bad_suspect", e=0.1, suspect=reason))
    write_results(tmp_path / "results.csv", rows, extra=["suspect"])
    fit = corlab.fit_paper(str(tmp_path / "results.csv"))
    reasons = {r["case_id"]: r["reason"] for r in fit["excluded"]}
    assert reasons["bad_suspect"] == f"suspect ({reason})"
    assert fit["restitution_law"]["points_used"] == clean["points_used"]
    assert fit["restitution_law"]["slope"]["value"] == pytest.approx(0.056, abs=1e-10)
    kept = corlab.fit_paper(str(tmp_path / "results.csv"), include_suspect=True)
    assert "bad_suspect" not in {r["case_id"] for r in kept["excluded"]}
    assert kept["restitution_law"]["points_used"] == clean["points_used"] + 1
    cli = [corlab_bin, "fit", str(tmp_path / "results.csv")]
    out = subprocess.run(cli, capture_output=True, text=True, check=True).stdout
    assert f"  bad_suspect: suspect ({reason})\n" in out
    out = subprocess.run(cli + ["--include-suspect"], capture_output=True, text=True,
                         check=True).stdout
    assert "bad_suspect" not in out
    form = ["--form", "e ~ a + s*ln(k1)", "--param", "a=1,s=0.05", "--json"]
    out = subprocess.run(cli + form, capture_output=True, text=True, check=True).stdout
    assert "bad_suspect" in out


def test_fit_counts_a_repeated_row_once_and_says_so(tmp_path):
    rows = paper_rows()
    write_results(tmp_path / "once.csv", rows)
    write_results(tmp_path / "twice.csv", rows + rows)
    once = corlab.fit_paper(str(tmp_path / "once.csv"))["restitution_law"]
    with pytest.warns(UserWarning, match="repeats line"):
        twice = corlab.fit_paper(str(tmp_path / "twice.csv"))["restitution_law"]
    assert twice["points_used"] == once["points_used"]
    assert twice["slope"]["ci_upper"] == once["slope"]["ci_upper"]
