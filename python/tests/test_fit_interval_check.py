"""scripts/fit_interval_check.py: every refit coefficient against its old 95 % interval (issue 43's
"every refit coefficient inside its current interval")."""
# SPDX-License-Identifier: BSD-3-Clause
import json
import pathlib
import subprocess
import sys

SCRIPT = pathlib.Path(__file__).resolve().parents[2] / "scripts" / "fit_interval_check.py"


def coefficient(value, lower, upper):
    return {"value": value, "ci_lower": lower, "ci_upper": upper, "name": "x"}


def write(path, alpha, slope):
    fits = {"restitution_law": {"alpha": coefficient(alpha, alpha - 0.1, alpha + 0.1),
                                "cases": [{"a": coefficient(slope, slope - 0.01, slope + 0.01)}]},
            "discretisation_error": {"all": {"median": 0.006}}}
    path.write_text(json.dumps({"fits": fits}))
    return str(path)


def check(*args):
    out = subprocess.run([sys.executable, str(SCRIPT), *args], capture_output=True, text=True)
    return out.returncode, out.stdout + out.stderr


def test_a_shift_inside_the_interval_passes_and_is_counted_in_half_widths(tmp_path):
    old = write(tmp_path / "old.json", 1.0, 0.05)
    code, text = check(old, write(tmp_path / "new.json", 1.05, 0.05))
    assert code == 0
    assert "2 coefficients with a 95 % interval; 0 outside the old one" in text
    assert "/restitution_law/alpha: 1 -> 1.05 in [0.9, 1.1], shift +0.5 half-widths" in text


def test_a_coefficient_outside_its_old_interval_fails(tmp_path):
    old = write(tmp_path / "old.json", 1.0, 0.05)
    code, text = check(old, write(tmp_path / "new.json", 1.0, 0.07))
    assert code == 1
    assert ("/restitution_law/cases[0]/a: 0.05 -> 0.07 in [0.04, 0.06], "
            "shift +2 half-widths  OUTSIDE") in text


def test_a_file_without_fits_is_bad_input(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text("{}")
    code, text = check(str(bad), str(bad))
    assert code == 2
    assert "fit_interval_check" in text
