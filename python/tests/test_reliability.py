"""Issue 12 reproducers through the Python module: bad input is a one-line ValueError naming the
field (never a crash of the interpreter, a hang or a NaN)."""
# SPDX-License-Identifier: BSD-3-Clause
import numpy as np
import pytest

import corlab


@pytest.mark.parametrize("settings, match", [
    ({"impact.gap": 1e20, "mesh.h_min": 1.5e-3, "mesh.contact_elements": 0},
     r"^invalid impact\.gap = 1e\+20: must be in \[0, 1\] \[m\]$"),
    ({"impact.gap": 1e10}, r"^invalid impact\.gap = 10000000000"),
    ({"sphere.E": 2.1e17}, r"^invalid sphere\.E = 2\.1e\+17"),
    ({"substrate.rho": 1e308}, r"^invalid substrate\.rho = 1e\+308"),
    ({"solver.hourglass": 1e308}, r"^invalid solver\.hourglass = 1e\+308"),
    ({"solver.bulk_viscosity_quadratic": 1e308}, r"^invalid solver\.bulk_viscosity_quadratic"),
    ({"impact.velocity": 1e308}, r"^invalid impact\.velocity = 1e\+308"),
    ({"solver.penalty_scale": 1.0, "solver.safety_factor": 1.0}, r"^invalid solver\.penalty_scale"),
    ({"substrate.radius": 2e-3}, r"^invalid substrate\.radius = 0\.002: must be >="),
    ({"substrate.sigma_y": ""}, r"^invalid substrate\.sigma_y = '': must be a finite number, or"),
    ({"impact.velocity": [5.0]}, r"^invalid impact\.velocity = '\[5\.0\]': must be a single value"),
    ({"impact.velocity": True}, r"^invalid impact\.velocity = 'True'"),
    ({"substrate.sigma_y": None}, r"^invalid substrate\.sigma_y = 'None'"),
    ({"sphere.material": "E=1e9,E=2e9,nu=0.3,rho=1000"}, r"^invalid sphere\.E = '2e9': must be "
                                                         r"given once"),
    ({"substrate.nu": 0.4999999}, r"^invalid solver\.max_steps = 20000000: must be >= the"),
])
def test_bad_simulate_settings_are_one_line_value_errors(settings, match):
    with pytest.raises(ValueError, match=match) as err:
        corlab.simulate(settings)
    assert "\n" not in str(err.value)


@pytest.mark.parametrize("call, match", [
    (lambda: corlab.k1(-1e9, 7850.0, 5.0), r"^invalid E_star = -1000000000: must be > 0 \[Pa\]$"),
    (lambda: corlab.k1(1e11, 0.0, 5.0), r"^invalid rho = 0"),
    (lambda: corlab.k1(1e11, 7850.0, float("nan")), r"^invalid v = nan"),
    (lambda: corlab.k2(-1.0, 1e11), r"^invalid sigma_y = -1"),
    (lambda: corlab.k2(5e8, float("inf")), r"^invalid E_star = inf"),
])
def test_dimensionless_groups_validate(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_good_groups_unchanged():
    assert corlab.k1(1.0e11, 1.0e4, 10.0) == pytest.approx(1.0e5)
    assert corlab.k2(5.0e8, 1.0e11) == pytest.approx(5.0e-3)


def test_list_is_accepted_for_a_list_key():
    with pytest.raises(ValueError, match=r"^invalid output\.times = -1"):
        corlab.simulate({"output.times": [1e-5, -1.0]})


def test_predict_outside_the_calibration_warns():
    with pytest.warns(UserWarning, match=r"beyond 1000 m/s, outside every model"):
        corlab.predict("ma2023", "steel_ma2023", "steel_ma2023", 1e6)
    with pytest.warns(UserWarning, match=r"model 'ma2023' extrapolates: 1 of 2 velocities"):
        corlab.predict("ma2023", "steel_ma2023", "steel_ma2023", np.array([5.0, 500.0]))


def test_predict_inside_the_calibration_is_silent():
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert 0.0 < corlab.predict("ma2023", "steel_ma2023", "steel_ma2023", 5.0) < 1.0
