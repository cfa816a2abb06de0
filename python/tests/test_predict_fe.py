"""`corlab predict --model fe|auto`, `corlab cache` and corlab.predict_curve: FE e(v) with error
bars from a result cache (study/fe_curve.hpp, result_cache.hpp, dataset/auto_restitution.hpp).
Each FE speed costs four runs (the error estimate): the tests keep to a few speeds."""
# SPDX-License-Identifier: BSD-3-Clause
import csv
import io
import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

import corlab
from corlab import model_fit

SPHERE = "alumina_ma2023"
AL = "aluminium_ma2023"
GLASS = "E=70e9,nu=0.22,rho=2500"  # elastic: no yield stress
ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def cache_dir(tmp_path_factory):
    """One cache for the module: the Python call reuses the CLI's run."""
    return tmp_path_factory.mktemp("corlab_cache")


def predict(corlab_bin, cache, *args, expect=0):
    env = {**os.environ, "CORLAB_CACHE_DIR": str(cache)}
    out = subprocess.run([corlab_bin, "predict", *args, "--quiet"], capture_output=True,
                         text=True, env=env, timeout=600)
    assert out.returncode == expect, out.stderr
    return list(csv.DictReader(io.StringIO(out.stdout))), out.stderr


def cache_cmd(corlab_bin, cache, *args):
    env = {**os.environ, "CORLAB_CACHE_DIR": str(cache)}
    out = subprocess.run([corlab_bin, "cache", *args], capture_output=True, text=True, env=env,
                         timeout=60, check=True)
    return out.stdout


def test_fe_is_cached_and_a_corrupted_or_foreign_entry_is_recomputed(corlab_bin, cache_dir):
    args = ["--model", "fe", "--sphere", SPHERE, "--substrate", AL, "--velocity", "5"]
    (cold,), _ = predict(corlab_bin, cache_dir, *args)
    assert cold["status"] == "separated" and cold["cached"] == "false"
    assert 0.3 < float(cold["e"]) < 0.9 and 0 < float(cold["e_error"]) < 0.1
    (warm,), _ = predict(corlab_bin, cache_dir, *args)
    assert warm["cached"] == "true"
    assert (warm["e"], warm["e_error"]) == (cold["e"], cold["e_error"])
    listed = list(csv.DictReader(io.StringIO(cache_cmd(corlab_bin, cache_dir, "list"))))
    assert len(listed) == 1 and listed[0]["this_build"] == "true"
    assert float(listed[0]["e"]) == float(cold["e"])
    entry = cache_dir / "runs" / listed[0]["file"]
    # A corrupted entry and one of another build are recomputed, never served.
    text = entry.read_text()
    entry.write_text(text[: len(text) // 2])
    (again,), _ = predict(corlab_bin, cache_dir, *args)
    assert again["cached"] == "false" and again["e"] == cold["e"]
    doc = json.loads(entry.read_text())
    doc["build"] = "0.0.1+git.another"
    doc["value"]["e"] = 0.123
    entry.write_text(json.dumps(doc))
    (rebuilt,), _ = predict(corlab_bin, cache_dir, *args)
    assert rebuilt["cached"] == "false" and rebuilt["e"] == cold["e"]
    assert "1 entries (1 of this build" in cache_cmd(corlab_bin, cache_dir, "size")
    assert cache_cmd(corlab_bin, cache_dir, "path").strip() == str(cache_dir)
    assert cache_cmd(corlab_bin, cache_dir, "clear", "--other-builds").startswith("removed 0 ")
    assert cache_cmd(corlab_bin, cache_dir, "clear").startswith("removed 1 ")
    (cleared,), _ = predict(corlab_bin, cache_dir, *args)
    assert cleared["cached"] == "false" and cleared["e"] == cold["e"]


def test_auto_answers_with_the_model_inside_its_range_and_the_fe_beyond(corlab_bin, tmp_path):
    """alumina on aluminium (v_y = 0.060 m/s): corlab2026p at 0.12 m/s (v/v_y = 2), the FE at
    20 m/s (v/v_y = 333 > 3); an elastic pair (no closed form) from the FE. The cache is a
    file, not a directory: one warning, the answers still given."""
    blocked = tmp_path / "a_file"
    blocked.write_text("")
    rows, err = predict(corlab_bin, blocked, "--model", "auto", "--sphere", SPHERE,
                        "--substrate", AL, "--velocity", "0.12,20")
    assert [r["answered_by"] for r in rows] == ["corlab2026p", "fe"]
    model, fe = rows
    assert float(model["e"]) == pytest.approx(corlab.predict("corlab2026p", SPHERE, AL, 0.12),
                                              rel=1e-12)
    p = corlab.CORLAB2026P_ACCURATE_INTERVAL_95
    assert float(model["e_error"]) == pytest.approx(float(model["e"]) * p / (1 - p), rel=1e-9)
    assert fe["status"] == "separated" and "v/v_y = 332.8 above 3" in fe["detail"]
    assert float(fe["e_error"]) > 0
    assert err.count("not writable") == 1, err
    (elastic,), err = predict(corlab_bin, blocked, "--model", "auto", "--sphere", SPHERE,
                              "--substrate", GLASS, "--velocity", "1")
    assert elastic["answered_by"] == "fe" and "does not yield" in elastic["detail"]
    assert 0.99 < float(elastic["e"]) <= 1.0 and elastic["k2"] == ""
    assert err.count("not writable") == 1, err


def test_python_predict_curve_returns_e_and_e_error(cache_dir, monkeypatch):
    monkeypatch.setenv("CORLAB_CACHE_DIR", str(cache_dir))
    curve = corlab.predict_curve("auto", SPHERE, AL, [0.1, 0.15])
    assert curve["answered_by"] == ["corlab2026p", "corlab2026p"]
    np.testing.assert_allclose(curve["e"], corlab.predict("corlab2026p", SPHERE, AL,
                                                          np.array([0.1, 0.15])), rtol=1e-12)
    fe = corlab.predict_curve("fe", SPHERE, AL, 5.0)
    assert fe["status"] == ["separated"] and np.isfinite(fe["e_error"][0])
    assert corlab.predict("fe", SPHERE, AL, 5.0) == fe["e"][0]
    with pytest.raises(ValueError, match="radius_ratio"):
        corlab.predict_curve("fe", SPHERE, AL, 5.0, shape="sphere")
    with pytest.raises(ValueError, match="fe or auto"):
        corlab.predict_curve("ma2023", SPHERE, AL, 5.0)


def test_bad_input_is_one_line_and_exit_2(corlab_bin, tmp_path):
    for args, field in ((["--model", "fe", "--substrate", "E=70e9,nu=0.6,rho=2500"],
                         "substrate.nu"),
                        (["--model", "fe", "--substrate", AL, "--shape", "sphere"],
                         "--radius-ratio"),
                        (["--model", "ma2023", "--substrate", AL, "--shape", "rigid"], "--shape"),
                        (["--model", "auto", "--substrate", AL, "--tolerance", "0.01"],
                         "--tolerance")):
        out = subprocess.run([corlab_bin, "predict", "--sphere", SPHERE, "--velocity", "1",
                              *args], capture_output=True, text=True, timeout=60,
                             env={**os.environ, "CORLAB_CACHE_DIR": str(tmp_path)})
        assert out.returncode == 2 and out.stdout == ""
        assert out.stderr.count("\n") == 1 and f"invalid {field} = " in out.stderr
    out = subprocess.run([corlab_bin, "predict", "--model", "fe", "--sphere", SPHERE,
                          "--substrate", AL, "--velocity", "1"], capture_output=True, text=True,
                         timeout=60, env={**os.environ, "OMPI_COMM_WORLD_SIZE": "2",
                                          "CORLAB_CACHE_DIR": str(tmp_path)})
    assert out.returncode == 2 and "invalid mpirun ranks = 2" in out.stderr


def test_the_accurate_interval_is_measured():
    """CORLAB2026P_ACCURATE_INTERVAL_95 is the 95th percentile of |e_model - e_FE| / e_FE over
    the held-out rows (random 20 % and corners) where --model auto lets corlab2026p answer
    (from 1.1 to CORLAB2026P_ACCURATE_VELOCITY_RATIO = 3 v_y, up to the accurate damage
    number), rounded up."""
    limit = next(m for m in corlab.models() if m["name"] == "corlab2026p")[
        "accurate_damage_number"]
    table = model_fit.read_union([ROOT / "data" / "fe_restitution" / "dataset.csv",
                                  ROOT / "data" / "fe_restitution_pairs" / "dataset.csv"])
    e = model_fit.predict(model_fit.model_inputs(table, "corlab2026p"),
                          corlab.corlab2026p_fitted())
    rel = np.abs(e - table["e"]) / table["e"]
    _, random_out, corner = model_fit.split(table, "corlab2026p")
    inside = ((table["damage_number"] <= limit) & (table["velocity_ratio"] >= 1.1)
              & (table["velocity_ratio"] <= corlab.CORLAB2026P_ACCURATE_VELOCITY_RATIO))
    held = (random_out | corner) & inside
    assert held.sum() == 130
    measured = np.percentile(rel[held], 95)
    assert measured <= corlab.CORLAB2026P_ACCURATE_INTERVAL_95 < measured + 1e-3
