"""Issue 42 reproducers through the Python module (the analytic models, the solver's inputs, the
error bar): bad input is a one-line ValueError naming the arrays or the field, never a crash, a
RuntimeError or a NaN."""
# SPDX-License-Identifier: BSD-3-Clause
import numpy as np
import pytest

import corlab


def corlab2026_inputs(n):
    """corlab2026_restitution's input dict: n copies of one impact's inputs."""
    one = corlab.corlab2026_inputs("alumina_ma2023", "aluminium_ma2023", 5.0)
    return {k: np.full(n, v) for k, v in one.items()}


def test_corlab2026_restitution_refuses_arrays_of_different_lengths():
    # 100,000 against 10 elements was a SIGSEGV; 1,000 garbage that differed run to run.
    for n in (1000, 100_000):
        inputs = corlab2026_inputs(n)
        inputs["velocity_ratio"] = np.full(10, 5.0)
        with pytest.raises(ValueError, match=r'^invalid len\(inputs\["velocity_ratio"\]\) = 10: '
                           rf'must be len\(inputs\["other_is_sphere"\]\) = {n} '):
            corlab.corlab2026_restitution(inputs, corlab.corlab2026_fitted())
    inputs = corlab2026_inputs(3)
    inputs["other_is_sphere"] = np.zeros(4)
    with pytest.raises(ValueError, match=r'len\(inputs\["velocity_ratio"\]\) = 3: must be '
                       r'len\(inputs\["other_is_sphere"\]\) = 4'):
        corlab.corlab2026_restitution(inputs, corlab.corlab2026_fitted())
    inputs = corlab2026_inputs(3)
    inputs["hardening_first"] = np.zeros((3, 1))
    with pytest.raises(ValueError, match=r'^invalid inputs\["hardening_first"\]\.ndim = 2'):
        corlab.corlab2026_restitution(inputs, corlab.corlab2026_fitted())


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_corlab2026_restitution_refuses_non_finite_inputs(bad):
    # a NaN velocity ratio returned e = 1.0
    inputs = corlab2026_inputs(3)
    inputs["velocity_ratio"][1] = bad
    with pytest.raises(ValueError, match=r'^invalid inputs\["velocity_ratio"\]\[1\] = -?(nan|inf): '
                       r'must be a finite number$'):
        corlab.corlab2026_restitution(inputs, corlab.corlab2026_fitted())
    good = corlab2026_inputs(3)
    e = corlab.corlab2026_restitution(good, corlab.corlab2026_fitted())
    assert np.all(np.isfinite(e)) and np.all(e <= 1.0)


def test_corlab2026_restitution_names_a_coefficient_or_input_of_the_wrong_type():
    # a string where a coefficient is due was RuntimeError "Unable to cast"
    k = corlab.corlab2026_fitted()
    k["c1"] = "abc"
    with pytest.raises(ValueError, match=r"^invalid coefficients\[\"c1\"\] = 'abc': must be a "
                       r"finite number$"):
        corlab.corlab2026_restitution(corlab2026_inputs(2), k)
    k["c1"] = float("nan")
    with pytest.raises(ValueError, match=r'^invalid coefficients\["c1"\] = nan'):
        corlab.corlab2026_restitution(corlab2026_inputs(2), k)
    inputs = corlab2026_inputs(2)
    inputs["hardening_first"] = "abc"
    with pytest.raises(ValueError, match=r'^invalid inputs\["hardening_first"\] = \'abc\': must '
                       r'be an array of numbers'):
        corlab.corlab2026_restitution(inputs, corlab.corlab2026_fitted())


def test_error_bar_refuses_a_ratio_that_is_not_a_mesh_size():
    for ratios in ([1.0, 0.0], [1.0, -2.0], [1.0, float("nan")], [2.0, 4.0]):
        with pytest.raises(ValueError, match=r"^invalid error bar ratios\[[01]\]"):
            corlab.error_bar("scatter", [0.5, 0.6], ratios)
    assert corlab.error_bar("scatter", [0.5, 0.6], [1.0, 2.0]) > 0.0


@pytest.mark.parametrize("settings, match", [
    ({"sphere.material": "a\ud800"},
     r"^invalid sphere\.material = 'a\\ud800': must be text that has a UTF-8 form"),
    ({"\ud800": 1.0}, r"^invalid settings key = '\\ud800': must be text that has a UTF-8 form"),
])
def test_a_lone_surrogate_is_a_value_error(settings, match):
    # was RuntimeError "Unable to cast Python instance to C++ type"
    with pytest.raises(ValueError, match=match) as err:
        corlab.simulate(settings)
    assert "\n" not in str(err.value)


def test_a_lone_surrogate_in_a_material_name_is_a_value_error():
    # corlab.predict's material names: was pybind11's TypeError (no overload matched)
    with pytest.raises(ValueError, match=r"^invalid sphere = 'a\\ud800': must be text that has"):
        corlab.predict("corlab2026", "a\ud800", "aluminium_ma2023", 2.0)
    with pytest.raises(ValueError, match=r"^invalid substrate = 'b\\ud800': must be text"):
        corlab.predict("jg2", "alumina_ma2023", "b\ud800", [1.0, 2.0])


def test_a_nul_in_a_config_path_is_named(tmp_path):
    # "/tmp\0x" was read as /tmp: "it is a directory"
    with pytest.raises(ValueError, match=r"^invalid config file = '.*\\x00x': must be a path "
                       r"without a NUL byte \(byte \d+ is NUL\)$"):
        corlab.simulate(config_file=str(tmp_path) + "\x00x")


def test_predict_refuses_speeds_from_the_speed_of_light_and_warns_beyond_the_fitted_ratio():
    # corlab2026 and corlab2026p at 1e307 m/s gave e = -nan
    for model in ("corlab2026", "corlab2026p"):
        with pytest.raises(ValueError,
                           match=r"^invalid velocity = 1e\+307: must be < 2\.99792e\+08"):
            corlab.predict(model, "alumina_ma2023", "aluminium_ma2023", 1e307)
        with pytest.raises(ValueError, match=r"^invalid velocity\[1\] = 1e\+307"):
            corlab.predict(model, "alumina_ma2023", "aluminium_ma2023", np.array([5.0, 1e307]))
    with pytest.warns(UserWarning, match=r"model 'corlab2026p' extrapolates: radius_ratio = "
                      r"R1/R2 = 5 is beyond its fitted 1"):
        e = corlab.predict("corlab2026p", "alumina_ma2023", "aluminium_ma2023", 5.0,
                           radius_ratio=5.0)
    assert 0.0 < e <= 1.0
    e = corlab.predict("ma2023", "alumina_ma2023", "aluminium_ma2023", 5.0, radius_ratio=1e200)
    assert np.isfinite(e)
