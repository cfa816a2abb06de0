"""Issue 31 reproducers through the Python module: bounded, checked input files (special files,
caps, UTF-8 and the byte-order mark), no silent defaults, every missing result said. The CLI side:
tests/regression/reliability_cli_test.sh."""
# SPDX-License-Identifier: BSD-3-Clause
import re
import time

import pytest

import corlab

# A cheap, valid impact (a few tenths of a second).
TINY = {"sphere.radius": 2.5e-3, "substrate.radius": 2.5e-3, "substrate.depth": 2.5e-3,
        "mesh.h_min": 0.125e-3, "mesh.h_max": 1e-3, "mesh.contact_elements": 0}
SPECIAL = re.escape("must be a regular file or a pipe (it is a character device)")


def write_csv(path, text, bom=False):
    path.write_bytes((b"\xef\xbb\xbf" if bom else b"") + text.encode())
    return str(path)


@pytest.mark.parametrize("call, match", [
    (lambda: corlab.read_results("/dev/zero"), f"^invalid results file = '/dev/zero': {SPECIAL}$"),
    (lambda: corlab.fit_paper("/dev/urandom"), "^invalid results file = '/dev/urandom'"),
    (lambda: corlab.load_spec("/dev/zero"), f"^invalid spec = '/dev/zero': {SPECIAL}$"),
    (lambda: corlab.simulate({}, config_file="/dev/zero"), "^invalid config file = '/dev/zero'"),
    (lambda: corlab.simulate({}, config_file="."),
     r"^invalid config file = '\.': must be a regular file or a pipe \(it is a directory\)$"),
])
def test_special_files_are_refused_at_once(call, match):
    start = time.monotonic()
    with pytest.raises(ValueError, match=match):
        call()
    assert time.monotonic() - start < 2.0


def test_an_empty_config_is_an_error_not_the_default_case(tmp_path):
    (tmp_path / "empty.toml").write_text("# only a comment\n")
    with pytest.raises(ValueError, match="must be a TOML file that sets at least one key"):
        corlab.simulate({}, config_file=str(tmp_path / "empty.toml"))


def test_every_reader_drops_a_byte_order_mark_the_same_way(tmp_path):
    """issue 31 item 11: read_results kept it in the key ('\\ufeffcase_id')."""
    text = "case_id,status,e,velocity\nc1,ok,0.5,1\n"
    table = corlab.read_results(write_csv(tmp_path / "bom.csv", text, bom=True))
    assert list(table)[:2] == ["case_id", "status"]
    plain = corlab.read_results(write_csv(tmp_path / "plain.csv", text))
    assert list(table) == list(plain)
    (tmp_path / "spec.toml").write_bytes(b"\xef\xbb\xbf[study]\nname = \"b\"\n")
    assert corlab.load_spec(str(tmp_path / "spec.toml"))["name"] == "b"


def test_a_non_utf8_byte_is_refused_naming_the_line(tmp_path):
    path = tmp_path / "latin1.csv"
    path.write_bytes(b"case_id,status,e\nc1,fa\xffiled,0.5\n")
    with pytest.raises(ValueError, match=r"must be UTF-8 text \(line 2: byte 0xff is not valid"):
        corlab.read_results(str(path))


def test_a_long_grid_is_refused_before_it_is_expanded(tmp_path):
    values = ", ".join(str(1 + i) for i in range(300_000))
    (tmp_path / "long.toml").write_text(
        f'[study]\nname = "g"\n[grid]\n"impact.velocity" = [{values}]\n')
    start = time.monotonic()
    with pytest.raises(ValueError, match="expands to 300000 runs, more than"):
        corlab.load_spec(str(tmp_path / "long.toml"))
    assert time.monotonic() - start < 10.0


def test_a_huge_integer_setting_is_a_value_error():
    """issue 31 item 11: 10**400 raised RuntimeError (a failed cast), not ValueError."""
    with pytest.raises(ValueError, match=r"^invalid impact\.velocity = '1000000000"):
        corlab.simulate({"impact.velocity": 10 ** 400})


@pytest.mark.parametrize("spec, lacks", [
    ("E=200e9,rho=7800", "nu"), ("nu=0.3,rho=7800", "E"), ("E=200e9,nu=0.3", "rho"),
    ("sy=1e8", "E, nu, rho")])
def test_an_inline_material_gives_E_nu_and_rho(spec, lacks):
    """issue 31 item 7: a missing nu became 0 and ran."""
    with pytest.raises(ValueError, match=rf"^invalid sphere\.material = '{spec}': .*\(it lacks "
                                         rf"{lacks}; "):
        corlab.simulate({"sphere.material": spec})
    with pytest.raises(ValueError, match=rf"^invalid sphere = '{spec}': .*\(it lacks {lacks}; "):
        corlab.predict("ma2023", spec, "steel_ma2023", 2.0)
    # a database name to start from may be modified by any subset
    assert 0 < corlab.predict("ma2023", "steel_ma2023,nu=0.29", "steel_ma2023", 2.0) < 1


def test_hardening_is_checked_on_an_elastic_body_too():
    with pytest.raises(ValueError, match=r"^invalid sphere\.hardening = 300000000000: must be < "
                                         r"sphere\.E"):
        corlab.simulate({"sphere.hardening": 300e9})


def test_output_times_after_the_run_are_warned_about():
    """issue 31 item 11: 300 asked, 200 written, nothing said."""
    with pytest.warns(UserWarning, match=r"output\.times 1 s \(1 of 2\) after the run's end"):
        corlab.simulate(dict(TINY, **{"output.times": [3e-5, 1.0]}))


def test_the_error_estimate_reason_is_a_result_field():
    names = [f["name"] for f in corlab.result_fields()]
    assert "e_error_reason" in names
    assert corlab.simulate(TINY)["e_error_reason"] == ""  # not asked for: no reason needed


def test_fit_expression_lists_every_row_it_leaves_out():
    """issue 31 item 11: a NaN/inf response was dropped silently."""
    data = {"x": [1.0, 2, 3, 4, 5], "y": [1.1, 2.0, float("nan"), 3.9, float("inf")]}
    with pytest.warns(UserWarning, match=r"left out 2 row\(s\) with a non-finite response "
                                         r"\(first row 2: y = nan\)"):
        fit = corlab.fit_expression("y ~ a*x", {"a": 1.0}, data)
    assert fit["observations"] == 3
    assert fit["left_out"] == [{"row": 2, "reason": "y = nan"}, {"row": 4, "reason": "y = inf"}]
    kept = corlab.fit_expression("y ~ a*x", {"a": 1.0}, {"x": [1.0, 2, 3, 4], "y": [1.0, 2, 3, 9]},
                                 where="y < 5")
    assert kept["left_out"] == [{"row": 3, "reason": "where: y < 5 is false"}]


def test_an_unfitted_form_has_no_goodness(tmp_path):
    """issue 31 item 11: form (ii) over two cases reported a perfect fit (0.00 %)."""
    import math
    es = 210e9 / (2 * (1 - 0.3 ** 2))
    rows = ["case_id,status,e,velocity,sphere_rho,E_star,sigma_y,k1,k2"]
    for k, sy in enumerate((300e6, 500e6)):
        for j, v in enumerate((0.5, 1.0, 2.0, 5.0)):
            k1, k2 = es / (3925.0 * v * v), sy / es
            e = 1.16 + 0.253 * math.log(k2) + 0.056 * math.log(k1)
            rows.append(f"c{k}{j},ok,{e!r},{v},3925.0,{es!r},{sy},{k1!r},{k2!r}")
    fit = corlab.fit_paper(write_csv(tmp_path / "two.csv", "\n".join(rows) + "\n"))
    law = fit["restitution_law"]
    assert law["goodness_form_i"]["r_squared"] == pytest.approx(1.0)
    for form in ("goodness_form_ii", "goodness_combined"):
        assert all(v is None for v in law[form].values()), law[form]


def test_dem_calibrates_a_constant_e_below_2e_3():
    """issue 31 item 5: e < 2e-3 raised RuntimeError (the bodies did not separate)."""
    for e in (1e-3, 1e-6, 1e-12):
        alpha = corlab.dem.tsuji_alpha(e)
        delivered = corlab.dem.simulate_impact(
            "tsuji", {"stiffness": 1.0, "alpha": alpha, "effective_mass": 1.0}, 1.0, 1.0)["e"]
        assert delivered == pytest.approx(e, rel=1e-6)
    out = corlab.dem.export([("alumina_ma2023", 0.005)], wall="steel_ma2023", restitution=1e-3)
    assert "damping tsuji" in out["lammps"]
