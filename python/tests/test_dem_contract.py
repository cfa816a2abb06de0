"""corlab.dem's contract (issue 42): bad values end in a one-line ValueError naming the field, and
the exported scripts hold a table's name as data (comments), never as code."""
# SPDX-License-Identifier: BSD-3-Clause
import json
import math

import pytest

import corlab

GLASS = "glass=E=63e9,nu=0.22,rho=2500"
HOSTILE = ('z\n__import__("os").system("touch PWNED")\n#.csv',
           "x\nshell touch PWNED\n.csv", "q'\"\"\"$x & # r\u00e9sultats")


def one_line_value_error(call, *needles):
    with pytest.raises(ValueError) as info:
        call()
    message = str(info.value)
    assert "\n" not in message
    for needle in needles:
        assert needle in message, message
    return message


@pytest.mark.parametrize("law,params,field", [
    ("hertz", {"stiffness": math.nan}, "params['stiffness'] = nan: must be > 0"),
    ("tsuji", {"stiffness": 1e9, "alpha": -5.0, "effective_mass": 1.0},
     "params['alpha'] = -5: must be >= 0"),
    ("viscoelastic", {"stiffness": 1e9, "damping": -5.0}, "params['damping'] = -5: must be >= 0"),
    ("linear", {"stiffness": 1e9, "damping": -5.0}, "params['damping'] = -5"),
    ("hysteresis", {"stiffness": 1e9, "chi": math.inf, "impact_velocity": 1.0},
     "params['chi'] = inf"),
    ("hertz", {"stiffness": "abc"}, "params['stiffness'] = ''abc'': must be a number"),
])
def test_simulate_impact_bad_params_are_value_errors(law, params, field):
    one_line_value_error(lambda: corlab.dem.simulate_impact(law, params, 1.0, 1.0), field)


def test_simulate_impact_law_that_never_separates_is_a_value_error():
    params = {"stiffness": 1e9, "chi": 1e300, "impact_velocity": 1.0}
    one_line_value_error(lambda: corlab.dem.simulate_impact("hysteresis", params, 1.0, 1.0),
                         "invalid params of law hysteresis = 'chi=1e+300, ")
    params = {"stiffness": 1e9, "chi": 1e12, "impact_velocity": 1.0}
    one_line_value_error(lambda: corlab.dem.simulate_impact("hysteresis", params, 1.0, 1.0),
                         "overdamped or sticks")


def test_tsuji_alpha_only_where_it_delivers_e():
    for e in (1e-20, 0.0, 1.0):
        one_line_value_error(lambda: corlab.dem.tsuji_alpha(e), "must be in [1e-12, 1)")
    one_line_value_error(lambda: corlab.dem.lammps_tsuji_input(1e-20), "restitution = 1e-20")
    alpha = corlab.dem.tsuji_alpha(1e-12)
    params = {"stiffness": 1.0, "alpha": alpha, "effective_mass": 1.0}
    e = corlab.dem.simulate_impact("tsuji", params, 1.0, 1.0)["e"]
    assert e == pytest.approx(1e-12, rel=1e-6)


def test_export_pairs_and_labels_are_refused_in_one_line():
    export = corlab.dem.export
    one_line_value_error(lambda: export([(GLASS, 0.001)], restitution=0.5,
                                        pairs={"glass/glass": "x"}),
                         "pairs['glass/glass'] = ''x'': must be a number")
    one_line_value_error(lambda: export([(GLASS, 0.001)], wall=GLASS.replace("glass", "w"),
                                        restitution=0.5, pairs={"wall/wall": 0.3}),
                         "invalid pair = 'wall/wall'")
    one_line_value_error(lambda: export([(GLASS, 0.001)], wall="w=E=63e9,nu=0.22,rho=2500",
                                        restitution=0.5, pairs={"1/w": 0.3, "glass/wall": 0.4}),
                         "must be a pair that no other --pair or --pair-table names")
    one_line_value_error(lambda: export([("2=E=63e9,nu=0.22,rho=2500", 0.001)], restitution=0.5),
                         "invalid type label = '2'")
    one_line_value_error(lambda: export([(GLASS, 0.001)], wall=GLASS, restitution=0.5),
                         "invalid wall label = 'glass'")
    one_line_value_error(lambda: export([(GLASS, 1e-300)], restitution=0.5),
                         "invalid type 1 (glass) radius = 1e-300: must be in [1e-09, 1000] [m]")


def commands(script):
    return [line for line in script.splitlines() if not line.startswith("#")]


@pytest.mark.parametrize("name", HOSTILE)
def test_export_table_source_stays_in_the_comments(name):
    def fragments(source):
        return corlab.dem.export([("alumina_ma2023", 0.005)], wall="aluminium_ma2023",
                                 wall_only=True, v_min=0.3, v_max=3.0, fit_points=3,
                                 table=([0.3, 3.0], [0.9, 0.7]), table_source=source)
    plain, hostile = fragments("fe.csv"), fragments(name)
    for key in ("lammps", "lammps_nopython", "liggghts", "yade"):
        assert commands(hostile[key]) == commands(plain[key]), key
        assert len(hostile[key].splitlines()) == len(plain[key].splitlines()), key
    compile(hostile["yade"], "yade_fragment.py", "exec")  # still Python, nothing injected
    target = json.loads(hostile["json"])["pairs"][0]["target"]
    assert target.startswith("table ") and all(" " <= c <= "~" for c in target), target
    assert not any(c in target for c in "\"'$&#"), target
