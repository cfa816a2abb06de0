"""tests/regression/sweep_compare.py: exact mode (the regression tests) and --relative mode (two
solver versions compared run by run, as the README's "every e within x %" claims are made)."""
# SPDX-License-Identifier: BSD-3-Clause
import pathlib
import subprocess
import sys

import corlab

SCRIPT = pathlib.Path(__file__).resolve().parents[2] / "tests" / "regression" / "sweep_compare.py"
HEADER = "case_id,e,e_coarse,energy_balance_error,wall_s\n"


def write(path, rows):
    path.write_text(HEADER + "".join(",".join(str(v) for v in r) + "\n" for r in rows))
    return str(path)


def compare(*args):
    out = subprocess.run([sys.executable, str(SCRIPT), *args], capture_output=True, text=True)
    return out.returncode, out.stdout


def test_relative_reports_the_largest_change_and_the_run_that_made_it(tmp_path):
    a = write(tmp_path / "a.csv", [("c1", 0.5, 0.51, 1e-6, 2.0), ("c2", 0.8, 0.81, 3e-6, 1.0)])
    b = write(tmp_path / "b.csv", [("c2", 0.8008, 0.81, 2e-6, 0.5), ("c1", 0.5, 0.5151, 4e-5, 1.5)])
    code, text = compare("--relative", a, b)
    assert code == 0
    assert "2 runs joined on case_id; e: largest |change| 1.000e-03" in text
    assert "0 without a number in either file" in text
    assert "e_coarse: largest |change| 1.000e-02" in text
    assert text.index("c2: e 0.8 -> 0.8008 (+1.000e-03)") < text.index("c1: e 0.5 -> 0.5")
    assert "A: largest energy balance 3.00e-06, runs with e > 1: 0, summed wall_s 3.0" in text
    assert "B: largest energy balance 4.00e-05, runs with e > 1: 0, summed wall_s 2.0" in text


def test_relative_refuses_files_that_do_not_join(tmp_path):
    a = write(tmp_path / "a.csv", [("c1", 0.5, 0.51, 1e-6, 2.0)])
    b = write(tmp_path / "b.csv", [("c9", 0.5, 0.51, 1e-6, 2.0)])
    code, text = compare("--relative", a, b)
    assert code == 1
    assert "do not join" in text


def test_relative_refuses_empty_files_and_repeated_cases(tmp_path):
    a = write(tmp_path / "a.csv", [("c1", 0.5, 0.51, 1e-6, 2.0), ("c1", 0.6, 0.51, 1e-6, 2.0)])
    b = write(tmp_path / "b.csv", [("c1", 0.5, 0.51, 1e-6, 2.0)])
    assert compare("--relative", a, b) == (1, f"{a}: duplicate case ids\n")
    empty = write(tmp_path / "e.csv", [])
    assert compare("--relative", empty, b) == (1, f"{empty}: no rows\n")


def test_relative_skips_nan_but_not_the_numbers_beside_it(tmp_path):
    a = write(tmp_path / "a.csv", [("c1", 0.5, 0.51, "nan", 2.0), ("c2", 0.8, 0.81, 1e-3, 1.0)])
    b = write(tmp_path / "b.csv", [("c1", "nan", 0.51, "nan", 2.0), ("c2", 0.8, 0.81, 1e-3, 1.0)])
    code, text = compare("--relative", a, b)
    assert code == 0
    assert "largest |change| 0.000e+00 (relative), mean change +0.000e+00, 1 without" in text
    assert "A: largest energy balance 1.00e-03" in text


def test_exact_ignores_timing_and_sees_any_other_difference(tmp_path):
    a = write(tmp_path / "a.csv", [("c1", 0.5, 0.51, 1e-6, 2.0)])
    same_but_slower = write(tmp_path / "b.csv", [("c1", 0.5, 0.51, 1e-6, 9.0)])
    assert compare(a, same_but_slower, "1") == (0, "identical: 1 rows (timing columns excluded)\n")
    moved = write(tmp_path / "c.csv", [("c1", 0.5000001, 0.51, 1e-6, 2.0)])
    code, text = compare(a, moved)
    assert code == 1
    assert "rows differ" in text


def test_exact_leaves_out_every_machine_dependent_column_of_the_table(tmp_path):
    timing = [f["name"] for f in corlab.result_fields() if f["in_csv"] and f["machine_dependent"]]
    assert timing, "the table marks no column machine_dependent"
    header = ["case_id", "e", *timing]
    a, b = tmp_path / "a.csv", tmp_path / "b.csv"
    a.write_text(",".join(header) + "\nc1,0.5," + ",".join("1" for _ in timing) + "\n")
    b.write_text(",".join(header) + "\nc1,0.5," + ",".join("2" for _ in timing) + "\n")
    assert compare(str(a), str(b), "1") == (0, "identical: 1 rows (timing columns excluded)\n")
    b.write_text(",".join(header) + "\nc1,0.6," + ",".join("1" for _ in timing) + "\n")
    assert compare(str(a), str(b))[0] == 1


def test_exact_without_the_corlab_module_fails_and_says_so(tmp_path):
    a = write(tmp_path / "a.csv", [("c1", 0.5, 0.51, 1e-6, 2.0)])
    # -I: no PYTHONPATH, so no corlab module
    out = subprocess.run([sys.executable, "-I", str(SCRIPT), a, a], capture_output=True, text=True)
    assert out.returncode == 2
    assert "cannot import the corlab module" in out.stderr and "PYTHONPATH" in out.stderr
