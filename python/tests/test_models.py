"""Tests of the analytic CoR model bindings: corlab.models, .predict, .yield_velocity."""
# SPDX-License-Identifier: BSD-3-Clause
import math
import warnings

import numpy as np
import pytest

import corlab

SPHERE = "alumina_ma2023"
AL = "aluminium_ma2023"
STEEL = "steel_jackson2010"


def test_models_lists_every_model_with_metadata():
    infos = corlab.models()
    names = [m["name"] for m in infos]
    assert names == corlab.model_names()
    for required in ("ma2023", "ma2023-exact", "thornton1997", "thornton1997-cnu",
                     "thornton1997-sy", "jg1", "jg2", "jg2010-fit", "jg2010-fit-c", "wu2003",
                     "johnson1985"):
        assert required in names
    for m in infos:
        assert m["status"] in ("verified-paper", "verified-second-source", "verified-dataset",
                               "unverified")
        assert m["citation"] and m["equation"] and m["validity"] and m["status_note"]
    by_name = {m["name"]: m for m in infos}
    assert by_name["wu2003"]["status"] == "unverified"
    assert by_name["wu2003"]["clamped_by_default"] is False
    assert by_name["ma2023"]["status"] == "verified-paper"


def test_predict_scalar_golden_values():
    e = corlab.predict("ma2023", SPHERE, AL, 1.0)
    assert isinstance(e, float)
    assert e == pytest.approx(0.7932, abs=5e-5)
    assert corlab.predict("ma2023", SPHERE, STEEL, 1.0) == pytest.approx(0.8908, abs=5e-5)
    assert corlab.predict("thornton1997", SPHERE, AL, 1.0) == pytest.approx(0.5716, abs=5e-5)
    assert corlab.predict("thornton1997", SPHERE, STEEL, 1) == pytest.approx(0.7127, abs=5e-5)


def test_predict_numpy_in_numpy_out_same_shape():
    v = np.array([[0.1, 0.5], [1.0, 6.0]])
    e = corlab.predict("ma2023", SPHERE, AL, v)
    assert isinstance(e, np.ndarray)
    assert e.shape == v.shape
    assert e.dtype == np.float64
    expected = [[1.000, 0.871], [0.793, 0.592]]  # reference sec. 9
    np.testing.assert_allclose(e, expected, atol=6e-4)
    for idx in np.ndindex(v.shape):
        assert e[idx] == corlab.predict("ma2023", SPHERE, AL, float(v[idx]))


def test_predict_accepts_lists_and_material_objects():
    sphere = corlab.material(SPHERE)
    substrate = corlab.Material(E=68e9, nu=0.33, rho=2700.0, sigma_y=380e6)
    with pytest.warns(UserWarning):
        e = corlab.predict("jg2010-fit", sphere, substrate, [0.1, 1.0, 6.0])
    np.testing.assert_allclose(e, [0.968, 0.787, 0.614], atol=6e-4)


def test_all_clamped_models_in_unit_interval():
    v = np.logspace(-3, 3, 200)
    for name in corlab.model_names():
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            e = corlab.predict(name, SPHERE, STEEL, v)
        assert np.all(np.isfinite(e)), name
        if name != "wu2003":
            assert np.all((e >= 0.0) & (e <= 1.0)), name


def test_wu_unclamped_by_default_and_clamp_option():
    with pytest.warns(UserWarning, match="'wu2003' is UNVERIFIED"):
        assert corlab.predict("wu2003", SPHERE, AL, 0.2) == pytest.approx(1.441, abs=6e-4)
    with pytest.warns(UserWarning, match="UNVERIFIED"):
        assert corlab.predict("wu2003", SPHERE, AL, 0.2, clamp=True) == 1.0


def test_unverified_models_warn_and_verified_do_not():
    for info in corlab.models():
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            corlab.predict(info["name"], SPHERE, AL, np.array([1.0]))
        unverified = [w for w in caught if "UNVERIFIED" in str(w.message)]
        assert bool(unverified) == (info["status"] == "unverified"), info["name"]
    assert corlab.predict("johnson1985", SPHERE, AL, 0.5, clamp=False) == pytest.approx(
        1.314, abs=6e-4)


def test_yield_velocity():
    assert corlab.yield_velocity("ma2023", SPHERE, AL) == pytest.approx(0.15736, abs=5e-6)
    assert corlab.yield_velocity("ma2023-exact", SPHERE, AL) == pytest.approx(0.15776, abs=5e-6)
    assert corlab.yield_velocity("thornton1997", SPHERE, STEEL) == pytest.approx(0.1399, abs=5e-5)
    assert corlab.yield_velocity("jg2", SPHERE, AL) == pytest.approx(0.0601, abs=5e-5)
    assert corlab.yield_velocity("johnson1985", SPHERE, STEEL) == pytest.approx(0.1411, abs=5e-5)
    with pytest.warns(UserWarning, match="'jg1' is UNVERIFIED"):
        assert math.isfinite(corlab.yield_velocity("jg1", SPHERE, STEEL))


@pytest.mark.parametrize("v", [0.0, -1.0, float("nan"), float("inf")])
def test_bad_velocity_raises_value_error(v):
    with pytest.raises(ValueError, match=r"^invalid velocity = .*: must be > 0 \[m/s\]$"):
        corlab.predict("ma2023", SPHERE, AL, v)


def test_bad_velocity_in_array_names_index():
    with pytest.raises(ValueError, match=r"invalid velocity\[2\] = -3"):
        corlab.predict("ma2023", SPHERE, AL, np.array([1.0, 2.0, -3.0]))


def test_unknown_model_raises_value_error():
    with pytest.raises(ValueError, match=r"invalid model = 'foo': must be one of \[ma2023, "):
        corlab.predict("foo", SPHERE, AL, 1.0)
    with pytest.raises(ValueError, match="invalid model = 'foo'"):
        corlab.yield_velocity("foo", SPHERE, AL)


def test_substrate_without_yield_stress_raises():
    with pytest.raises(ValueError, match=r"invalid substrate.sigma_y = 'missing'"):
        corlab.predict("ma2023", SPHERE, SPHERE, 1.0)


def test_bad_material_spec_raises():
    with pytest.raises(ValueError, match=r"invalid sphere.rho = -1"):
        corlab.predict("ma2023", "E=370e9,nu=0.22,rho=-1", AL, 1.0)


def test_cli_predict_takes_a_velocity_list(corlab_bin):
    import subprocess
    args = [corlab_bin, "predict", "--model", "thornton1997", "--sphere", "alumina_ma2023",
            "--substrate", "aluminium_ma2023", "--velocity"]
    done = subprocess.run(args + ["0.5,1,2,4"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    rows = done.stdout.splitlines()[1:]
    assert [float(r.split(",")[1]) for r in rows] == [0.5, 1.0, 2.0, 4.0]
    e = [float(r.split(",")[2]) for r in rows]
    assert e == pytest.approx([corlab.predict("thornton1997", SPHERE, AL, v)
                               for v in (0.5, 1.0, 2.0, 4.0)], rel=1e-9)
    for bad in ("1,,2", "1,-2", "1:2,3"):
        done = subprocess.run(args + [bad], capture_output=True, text=True)
        assert done.returncode == 2 and done.stderr.count("\n") == 1, (bad, done.stderr)
        assert "velocity" in done.stderr


def test_cli_predict_takes_a_second_sphere(corlab_bin):
    """--radius-ratio R1/R2: the substrate is a free second sphere; corlab2026p reads the pair,
    k1 is at the pair's rho*; a negative ratio is the one-line error and exit 2."""
    import subprocess
    wc, al = "E=600e9,nu=0.24,rho=15000", "E=70e9,nu=0.33,rho=2700,sy=100e6"
    args = [corlab_bin, "predict", "--model", "corlab2026p", "--sphere", wc, "--substrate", al,
            "--velocity", "20", "--radius-ratio"]
    done = subprocess.run(args + ["0.5"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "damage number" in done.stderr  # rho* v^2/sigma_y = 0.12: beyond 2 % RMS
    row = done.stdout.splitlines()[1].split(",")
    with pytest.warns(UserWarning, match="less accurate"):
        pair = corlab.predict("corlab2026p", wc, al, 20.0, radius_ratio=0.5)
        flat = corlab.predict("corlab2026p", wc, al, 20.0)
    assert float(row[2]) == pytest.approx(pair, rel=1e-9)
    assert float(row[2]) != pytest.approx(flat, rel=1e-3)
    rho_star = 15000 * 1.5 ** 3 / (1 + (15000 / 2700) * 0.125)
    e_star = 1 / ((1 - 0.24 ** 2) / 600e9 + (1 - 0.33 ** 2) / 70e9)
    assert float(row[3]) == pytest.approx(e_star / (rho_star * 400.0), rel=1e-8)
    done = subprocess.run(args + ["-1"], capture_output=True, text=True)
    assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
    assert "radius_ratio = -1" in done.stderr


def test_a_second_sphere_is_checked_at_the_pairs_density():
    """ma2023's k1 box holds k1 = E*/(rho v^2) at the pair's rho*: two identical steel spheres
    (rho* = 4 rho) at 60 m/s fall below k1_min = E*/(15700 70^2) where one on a flat does not."""
    steel = "E=210e9,nu=0.3,rho=7850,sy=500e6"
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        corlab.predict("ma2023", steel, steel, 60.0)
    with pytest.warns(UserWarning, match="extrapolates"):
        corlab.predict("ma2023", steel, steel, 60.0, radius_ratio=1.0)


def test_corlab2026p_warns_above_the_damage_number_it_was_measured_accurate_to():
    """models() carries accurate_damage_number (None where not measured); predict warns above
    it, at the pair's rho* for a second sphere (4 rho for two identical spheres)."""
    by_name = {m["name"]: m for m in corlab.models()}
    assert by_name["corlab2026p"]["accurate_damage_number"] == 0.003
    assert by_name["corlab2026"]["accurate_damage_number"] is None
    steel = "E=210e9,nu=0.3,rho=7850,sy=500e6"
    v = math.sqrt(0.003 * 500e6 / 7850) / 1.5  # 0.44 of the limit on a flat, 1.8 x as a pair
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        corlab.predict("corlab2026p", steel, steel, v)
    with pytest.warns(UserWarning, match="less accurate"):
        corlab.predict("corlab2026p", steel, steel, v, radius_ratio=1.0)


def test_oblique_rebound_slides_by_the_coulomb_identity():
    """corlab.oblique_rebound is the C++ rigid-body theory (oblique_impact.hpp)."""
    theta = math.radians(60.0)
    vn, vt = 3.9 * math.cos(theta), 3.9 * math.sin(theta)
    r = corlab.oblique_rebound(vn, vt, 2.5e-3, normal_restitution=0.8, friction=0.092)
    assert r["slides"]
    e_t = 1 - 0.092 * 1.8 / math.tan(theta)
    assert r["tangential_restitution"] == pytest.approx(e_t, rel=1e-12)
    assert r["spin"] * 2.5e-3 == pytest.approx(2.5 * 0.092 * 1.8 * vn, rel=1e-12)
    rolling = corlab.oblique_rebound(vn, 0.1 * vn, 2.5e-3, normal_restitution=0.8, friction=0.5)
    assert not rolling["slides"] and rolling["tangential_restitution"] == pytest.approx(5 / 7)
    with pytest.raises(ValueError, match="friction"):
        corlab.oblique_rebound(1.0, 0.0, 1e-3, friction=-1.0)
