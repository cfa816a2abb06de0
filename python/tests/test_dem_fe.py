"""corlab dem --model fe|auto and corlab.dem.export(model="fe"|"auto") (issue 40): each pair's
e(v) from corlab's FE solver at the fit speeds, through the result cache, elastic pairs
included, the pair taken as predict takes it (the particle on the wall)."""
# SPDX-License-Identifier: BSD-3-Clause
import json
import os
import subprocess

import numpy as np
import pytest

import corlab

ALUMINA = "alumina_ma2023"
GLASS = "glass=E=70e9,nu=0.22,rho=2500"  # elastic: no yield stress


def dem(corlab_bin, cache, out, *args):
    done = subprocess.run([corlab_bin, "dem", "--type", f"{ALUMINA}:0.001", "--wall-only",
                           "--fit-points", "2", "--quiet", "--out", str(out), *args],
                          capture_output=True, text=True, timeout=600,
                          env={**os.environ, "CORLAB_CACHE_DIR": str(cache)})
    assert done.returncode == 0, done.stderr
    pair, = json.loads((out / "dem_export.json").read_text())["pairs"]
    return pair, done


def test_an_elastic_pair_gets_the_fe_e_and_a_second_export_is_cached(corlab_bin, tmp_path):
    """alumina on an elastic glass wall at 1 and 2 m/s: the elastic-wave loss of a half-space
    (0.9945 at 1 m/s, measured), not the 1 (or refusal) of a model; again from the cache."""
    args = ("--wall", GLASS, "--model", "fe", "--v-min", "1", "--v-max", "2")
    cold, _ = dem(corlab_bin, tmp_path / "cache", tmp_path / "cold", *args)
    assert cold["target"].startswith(f"corlab's FE ({ALUMINA} on glass: a flat; 2 speeds "
                                     "(0 cached)")
    e = {row["v"]: row["e"] for row in cold["table"]}
    assert 0.99 < e[1.0] < 0.998 and e[2.0] < e[1.0]
    warm, _ = dem(corlab_bin, tmp_path / "cache", tmp_path / "warm", *args)
    assert "2 speeds (2 cached)" in warm["target"]
    assert warm["table"] == cold["table"]


def test_auto_answers_past_corlab2026p_s_range_with_the_fe(corlab_bin, tmp_path, monkeypatch):
    """alumina on aluminium (v_y = 0.060 m/s): corlab2026p at 0.12 m/s, the FE at 2 m/s
    (v/v_y = 33 > 3), each the e predict --model auto gives; Python's export the same. (The
    CLI and the Python module share a cache only when built from a clean tree: a -dirty build
    id counts each binary.)"""
    monkeypatch.setenv("CORLAB_CACHE_DIR", str(tmp_path / "cache"))
    pair, _ = dem(corlab_bin, tmp_path / "cache", tmp_path / "auto", "--wall",
                  "aluminium_ma2023", "--model", "auto", "--v-min", "0.12", "--v-max", "2")
    assert "2 speeds: corlab2026p at 1, the FE at 1" in pair["target"]
    curve = corlab.predict_curve("auto", ALUMINA, "aluminium_ma2023", [0.12, 2.0])
    assert curve["answered_by"] == ["corlab2026p", "fe"]
    e = {row["v"]: row["e"] for row in pair["table"]}
    np.testing.assert_allclose([e[0.12], e[2.0]], curve["e"], rtol=1e-12)
    out = corlab.dem.export([(ALUMINA, 0.001)], wall="aluminium_ma2023", wall_only=True,
                            model="auto", v_min=0.12, v_max=2.0, fit_points=2)
    assert json.loads(out["json"])["pairs"][0]["table"] == pair["table"]


def test_fe_without_the_solver_and_a_model_past_its_range(corlab_bin, tmp_path):
    """A registered model past its accurate range warns as predict does; an elastic pair with a
    registered model names the FE as the way out; an FE option without the FE is refused."""
    pair, done = dem(corlab_bin, tmp_path / "cache", tmp_path / "m", "--wall",
                     "aluminium_ma2023", "--model", "corlab2026p", "--v-min", "1",
                     "--v-max", "20")
    assert pair["target"] == f"corlab2026p ({ALUMINA} on aluminium_ma2023)"
    assert "warning: pair 1-wall" in done.stderr and "damage number" in done.stderr
    with pytest.warns(UserWarning, match="damage number"):
        corlab.dem.export([(ALUMINA, 0.001)], wall="aluminium_ma2023", wall_only=True,
                          model="corlab2026p", v_min=1.0, v_max=20.0)
    with pytest.raises(ValueError, match="--model fe or auto"):
        corlab.dem.export([(ALUMINA, 0.001)], wall=GLASS, wall_only=True, model="corlab2026p")
    bad = subprocess.run([corlab_bin, "dem", "--type", f"{ALUMINA}:0.001", "--restitution", "0.5",
                          "--jobs", "2", "--out", str(tmp_path / "bad")],
                         capture_output=True, text=True, timeout=60)
    assert bad.returncode == 2 and bad.stderr.count("\n") == 1
    assert "invalid --jobs = '2': must be unset unless --model fe or auto" in bad.stderr
