"""Tests of the DEM bindings (corlab.dem): exact chi, impact integration, exports."""
import json
import math

import numpy as np
import pytest

import corlab


def test_exact_chi_relation_and_inverse_vectorised():
    e = np.array([0.1, 0.3, 0.5, 0.7, 0.9])
    chi = corlab.dem.exact_chi(e)
    assert np.all(chi > 0) and np.all(e * chi < 1)
    np.testing.assert_allclose(chi * (1 + e), np.log((1 + chi) / (1 - e * chi)), rtol=1e-10)
    np.testing.assert_allclose(corlab.dem.exact_restitution(chi), e, atol=1e-11)


def test_hysteresis_impact_delivers_exact_e():
    chi = float(corlab.dem.exact_chi(0.4))
    r = corlab.dem.simulate_impact("hysteresis", {"stiffness": 2e9, "chi": chi, "impact_velocity": 2.0},
                                   0.01, 2.0)
    assert r["e"] == pytest.approx(0.4, abs=1e-8)
    assert r["contact_time"] > 0 and r["max_overlap"] > 0


def test_published_formula_and_catalog():
    assert corlab.dem.published_chi("hunt_crossley", 0.3) == pytest.approx(1.05)
    assert "carvalho_martins" in corlab.dem.chi_formulas()
    names = [law["name"] for law in corlab.dem.laws()]
    assert "thornton_ning" in names and "hu_guo" in names


def test_export_constant_e_writes_compensated_lammps_input():
    out = corlab.dem.export([("steel_ma2023", 0.005)], wall="steel_ma2023", restitution=0.5)
    data = json.loads(out["json"])
    e_in = data["pairs"][0]["lammps_tsuji_input"]
    assert 0.3 < e_in < 0.5
    assert "damping tsuji" in out["lammps"] and "%.10g" % e_in in out["lammps"]
    assert "coefficientRestitution" in out["liggghts"]


def test_bad_input_is_value_error():
    with pytest.raises(ValueError, match="restitution"):
        corlab.dem.exact_chi(1.5)
    with pytest.raises(ValueError, match="law"):
        corlab.dem.simulate_impact("nope", {}, 1.0, 1.0)
    with pytest.raises(ValueError, match="params"):
        corlab.dem.simulate_impact("hertz", {}, 1.0, 1.0)
