"""Sweeps from Python: load_spec, run_sweep (real solver, tiny case), read_results."""
# SPDX-License-Identifier: BSD-3-Clause
import pathlib

import numpy as np
import pytest

import corlab

SWEEPS = pathlib.Path(__file__).resolve().parents[2] / "tests" / "data" / "sweeps"


def test_load_spec_expands_cases_times_grid():
    spec = corlab.load_spec(str(SWEEPS / "example.toml"))
    assert spec["name"] == "example"
    assert spec["grid"]["impact.velocity"] == ["1", "5", "20"]
    assert len(spec["cases"]) == 2
    assert spec["swept_keys"] == ["sphere.material", "substrate.material", "sphere.rho",
                                  "impact.velocity"]
    runs = spec["runs"]
    assert len(runs) == 12
    assert len({r["id"] for r in runs}) == 12
    assert runs[0]["settings"]["sphere.material"] == "alumina_ma2023"
    # Stable ids: a second parse gives the same ones.
    assert [r["id"] for r in corlab.load_spec(str(SWEEPS / "example.toml"))["runs"]] == \
        [r["id"] for r in runs]


def test_bad_spec_is_a_value_error_with_one_line():
    with pytest.raises(ValueError) as err:
        corlab.load_spec(str(SWEEPS / "bad_velocity.toml"))
    message = str(err.value)
    assert "\n" not in message
    assert message.endswith('grid."impact.velocity"[2] = -1: must be in (0, 1000] [m/s] '
                            '(no equation of state for hypervelocity impact)')


def test_run_sweep_and_read_results(tmp_path):
    out = tmp_path / "tiny"
    summary = corlab.run_sweep(str(SWEEPS / "tiny.toml"), str(out), jobs=2)
    assert summary["total"] == 6 and summary["ran"] == 6 and summary["failed"] == 0
    assert not summary["interrupted"]
    table = corlab.read_results(str(out / "results.csv"))
    assert isinstance(table["e"], np.ndarray) and table["e"].dtype == np.float64
    assert isinstance(table["case_id"], list) and isinstance(table["status"], list)
    assert table["status"] == ["ok"] * 6
    assert np.all((table["e"] > 0) & (table["e"] < 1))
    np.testing.assert_array_equal(table["velocity"], table["impact.velocity"])
    # The columns come from the one result-field table.
    csv_fields = [f["name"] for f in corlab.result_fields() if f["in_csv"]]
    assert list(table) == ["case_id", "status", "substrate.sigma_y", "impact.velocity", *csv_fields,
                           "error"]
    assert sorted(table["case_id"]) == sorted(r["id"] for r in
                                              corlab.load_spec(str(SWEEPS / "tiny.toml"))["runs"])
    # A rerun resumes: nothing left to run.
    again = corlab.run_sweep(str(SWEEPS / "tiny.toml"), str(out))
    assert again["already_done"] == 6 and again["ran"] == 0


def test_read_results_of_a_hand_written_table(tmp_path):
    csv = tmp_path / "r.csv"
    csv.write_text('case_id,status,sphere.material,e,error\n'
                   'c1,ok,"E=1e9,nu=0.3,rho=1000",0.5,\n'
                   'c2,failed,steel,,"boom, badly"\n')
    table = corlab.read_results(str(csv))
    assert table["sphere.material"] == ["E=1e9,nu=0.3,rho=1000", "steel"]
    assert table["error"] == ["", "boom, badly"]
    assert table["e"][0] == 0.5 and np.isnan(table["e"][1])


def test_docs_name_every_results_csv_column():
    page = (pathlib.Path(__file__).resolve().parents[2] / "docs" / "user" / "sweeps.md").read_text()
    missing = [f["name"] for f in corlab.result_fields()
               if f["in_csv"] and f"`{f['name']}`" not in page]
    assert not missing, f"docs/user/sweeps.md does not name the results.csv columns {missing}"


def test_read_results_never_drops_or_doubles_silently(tmp_path):
    csv = tmp_path / "r.csv"
    csv.write_text("case_id,status,e,error\nc1,ok,0.5,\nc2,ok,0.25,")  # no final line break
    assert list(corlab.read_results(str(csv))["e"]) == [0.5, 0.25]
    csv.write_text("case_id,status,e,error\nc1,ok,0.5,\nc1,ok,0.5,\n")
    with pytest.warns(UserWarning, match="case_id 'c1' repeats line 2"):
        assert list(corlab.read_results(str(csv))["e"]) == [0.5]
    csv.write_text("case_id,status,e,error\nc1,ok,0.5,\nc2,ok,0.")
    with pytest.warns(UserWarning, match="dropped a partial last line"):
        assert list(corlab.read_results(str(csv))["e"]) == [0.5]
    csv.write_text("case_id,e,e\nc1,0.5,0.6\n")
    with pytest.raises(ValueError, match="column 'e': must appear once"):
        corlab.read_results(str(csv))
