"""corlab.simulate: the explicit FE impact from Python."""
# SPDX-License-Identifier: BSD-3-Clause
import numpy as np
import pytest

import corlab

# A small, fast case (about 1000 elements): R = 2.5 mm sphere, 0.05 mm at the contact.
SMALL = {
    "sphere.radius": 2.5e-3,
    "substrate.radius": 5e-3,
    "substrate.depth": 5e-3,
    "impact.gap": 1e-5,
    "mesh.h_min": 0.05e-3,
    "mesh.h_max": 0.5e-3,
    "mesh.contact_elements": 0,
    "output.history_every": 5,
}


def test_elastic_small_case_rebounds():
    r = corlab.simulate({**SMALL, "impact.velocity": 5.0, "substrate.sigma_y": "none"})
    assert r["e"] > 0.97
    assert r["energy_balance_error"] < 1e-3
    assert r["separated"] is True
    h = r["history"]
    assert isinstance(h["time"], np.ndarray)
    assert h["time"].shape == h["contact_force"].shape
    assert h["contact_force"].max() == pytest.approx(r["F_max"], rel=0.05)
    assert r["config"]["impact"]["velocity"] == 5.0


def test_plastic_case_dissipates():
    r = corlab.simulate({**SMALL, "impact.velocity": 5.0})
    assert 0.3 < r["e"] < 0.8
    assert r["energy_dissipated_plastic"] > 0.0
    assert r["hysteresis_area"] == pytest.approx(r["energy_sphere_loss"], rel=0.02)


def test_run_cut_during_contact_has_a_status_and_no_restitution():
    """issue 12: a run that did not end as a clean rebound never reports an e."""
    # contact starts at gap / v = 2 us; the Hertz contact lasts ~12 us: t_max = 6 us cuts it
    r = corlab.simulate({**SMALL, "impact.velocity": 5.0, "solver.t_max": 6e-6})
    assert r["status"] == "not_separated"
    assert r["separated"] is False
    assert np.isnan(r["e"]) and np.isnan(r["e_energy"])  # null in summary.json
    assert "t_max" in r["status_detail"]
    assert r["suspect"] == ""


def test_bad_settings_raise_value_error():
    with pytest.raises(ValueError, match="impact.velocity"):
        corlab.simulate({"impact.velocity": -1.0})
    with pytest.raises(ValueError, match="impact.speed"):
        corlab.simulate({"impact.speed": 1.0})


def test_bad_input_carries_field_value_and_constraint():
    with pytest.raises(ValueError) as err:
        corlab.simulate({"impact.velocity": -1.0})
    assert (err.value.field, err.value.value) == ("impact.velocity", "-1")
    assert err.value.constraint.startswith("in (0, 1000] [m/s]")
    assert str(err.value) == f"invalid impact.velocity = -1: must be {err.value.constraint}"


def test_config_file(tmp_path):
    f = tmp_path / "case.toml"
    f.write_text("[impact]\nvelocity = 4.5\n[substrate]\nsigma_y = \"none\"\n")
    r = corlab.simulate(SMALL, config_file=str(f))
    assert r["config"]["impact"]["velocity"] == 4.5
    assert r["e"] > 0.97


def test_result_fields_are_the_summary_keys_and_the_csv_columns():
    fields = corlab.result_fields()
    names = [f["name"] for f in fields]
    assert len(names) == len(set(names))
    assert {"e", "F_max", "wall_s", "k1"} <= set(names)
    assert all(f["unit"] and f["description"] for f in fields)
    assert {f["kind"] for f in fields} <= {"real", "integer", "boolean", "text", "real_list"}
    r = corlab.simulate({**SMALL, "impact.velocity": 1.0, "substrate.sigma_y": "none"})
    summary = {f["name"] for f in fields if f["in_summary"]}
    assert set(r) - {"config", "history"} == summary


def test_simulate_runs_in_two_threads_from_a_fresh_interpreter():
    """The GIL is released during a run; the first two calls at once used to deadlock in
    pybind11's NumPy API set-up (a fresh interpreter: in this one it is set up already)."""
    import subprocess
    import sys
    code = (
        "import threading, corlab\n"
        f"s = {SMALL!r}\n"
        "out = []\n"
        "ts = [threading.Thread(target=lambda: out.append(corlab.simulate(s)['e']), daemon=True)"
        " for _ in range(2)]\n"
        "[t.start() for t in ts]\n"
        "[t.join(60) for t in ts]\n"
        "assert len(out) == 2 and out[0] == out[1], out\n")
    subprocess.run([sys.executable, "-c", code], check=True, timeout=150)


def test_repeated_impacts_list_each_impacts_e():
    r = corlab.simulate({**SMALL, "impact.repeats": 3})
    assert r["status"] == "separated"
    assert len(r["e_impacts"]) == 3
    assert r["e_impacts"][0] == r["e"] and r["e_last"] == r["e_impacts"][-1]
    assert r["e_impacts"][0] < r["e_impacts"][1] < r["e_impacts"][2] < 1.0  # shakedown


def test_cli_prints_each_impacts_e(tmp_path, corlab_bin):
    import json
    import subprocess
    cmd = [corlab_bin, "simulate", "--quiet", "--out", str(tmp_path), "--set", "impact.repeats=3"]
    for key, value in SMALL.items():
        cmd += ["--set", f"{key}={value}"]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    summary = json.loads((tmp_path / "summary.json").read_text())
    listed = ", ".join(f"{e:.4f}" for e in summary["e_impacts"])
    assert len(summary["e_impacts"]) == 3
    assert f"e of each impact (impact.repeats): {listed}\n" in out


def test_history_columns_are_the_history_keys_and_the_csv_header(tmp_path, corlab_bin):
    """One table (history_columns.cpp): simulate()'s history arrays and history.csv's header."""
    import csv
    import json
    import subprocess
    columns = corlab.history_columns()
    names = [c["name"] for c in columns]
    assert names[0] == "time" and "energy_balance_error" in names
    assert all(c["unit"] and c["description"] for c in columns)
    settings = {**SMALL, "impact.velocity": 1.0, "substrate.sigma_y": "none"}
    r = corlab.simulate(settings)
    assert list(r["history"]) == names
    cmd = [corlab_bin, "simulate", "--quiet", "--out", str(tmp_path)]
    for key, value in settings.items():
        cmd += ["--set", f"{key}={value}"]
    subprocess.run(cmd, check=True)
    with open(tmp_path / "history.csv") as f:
        rows = list(csv.reader(f))
    assert rows[0] == [c["csv_header"] for c in columns]
    assert rows[0][:2] == ["time_s", "contact_force_N"]
    assert len(rows) - 1 == len(r["history"]["time"])
    # The dict is summary.json's fields: the same names and, for the numbers, the same values.
    summary = json.loads((tmp_path / "summary.json").read_text())
    for f in corlab.result_fields():
        if f["in_summary"] and not f["machine_dependent"] and f["kind"] != "text":
            want = summary[f["name"]]
            got = r[f["name"]]
            assert (want is None and np.isnan(got)) or got == want, f["name"]
