"""Tests of the DEM bindings (corlab.dem): exact chi, impact integration, exports."""
# SPDX-License-Identifier: BSD-3-Clause
import json
import subprocess

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
    params = {"stiffness": 2e9, "chi": chi, "impact_velocity": 2.0}
    r = corlab.dem.simulate_impact("hysteresis", params, 0.01, 2.0)
    assert r["e"] == pytest.approx(0.4, abs=1e-8)
    assert r["contact_time"] > 0 and r["max_overlap"] > 0


def test_published_formula_and_catalog():
    assert corlab.dem.published_chi("hunt_crossley", 0.3) == pytest.approx(1.05)
    assert "carvalho_martins" in corlab.dem.chi_formulas()
    names = [law["name"] for law in corlab.dem.laws()]
    assert "thornton_ning" in names and "hu_guo" in names


def test_schwager_poeschel_matches_the_contact_ode():
    k, m, v = 1e9, 1e-4, 1.0
    c = 0.25 * k**0.6 * m**0.4  # x = 0.5: e = 0.76
    params = {"stiffness": k, "damping": c}
    e_ode = corlab.dem.simulate_impact("viscoelastic", params, m, v)["e"]
    e_pade = corlab.dem.schwager_poeschel(k, c, m, v)
    e_series = corlab.dem.schwager_poeschel(k, c, m, v, form="series")
    # the papers separate at F = 0; the law as integrated separates at delta = 0 (lower e)
    assert e_pade == pytest.approx(0.7605, abs=1e-3)
    assert e_ode < e_pade and e_pade - e_ode < 1e-2
    assert abs(e_series - e_pade) < 2e-3
    assert "schwager_poeschel" in [law["name"] for law in corlab.dem.laws()]
    with pytest.raises(ValueError, match="form"):
        corlab.dem.schwager_poeschel(k, c, m, v, form="nope")


def test_export_constant_e_writes_compensated_lammps_input():
    out = corlab.dem.export([("steel_ma2023", 0.005)], wall="steel_ma2023", restitution=0.5)
    data = json.loads(out["json"])
    e_in = data["pairs"][0]["lammps_tsuji_input"]
    assert 0.3 < e_in < 0.5
    assert "damping tsuji" in out["lammps"] and "%.10g" % e_in in out["lammps"]
    assert "coefficientRestitution" in out["liggghts"]


def test_export_from_an_fe_table_matches_it_at_its_points():
    # An FE e(v) table (rows unsorted, as a sweep writes them) instead of a model or constant.
    velocities, e = [4.0, 0.5, 1.0], [0.55, 0.8, 0.7]
    out = corlab.dem.export([("steel_ma2023", 0.004)], wall="steel_ma2023", wall_only=True,
                            table=(velocities, e), table_source="my results.csv",
                            v_min=0.5, v_max=4.0, fit_points=4)
    assert "my results.csv" in out["json"]
    rows = [line.split(",") for line in out["csv"].splitlines() if not line.startswith("#")]
    header = rows[0]
    v_col, e_col = header.index("velocity_m_s"), header.index("e_target")
    table = {float(r[v_col]): float(r[e_col]) for r in rows[1:]}
    for v, expected in zip(velocities, e):  # the table's end points and a node it passes
        assert table[v] == pytest.approx(expected, rel=1e-7)
    with pytest.raises(ValueError, match="table"):
        corlab.dem.export([("steel_ma2023", 0.004)], wall="steel_ma2023", table=([1.0, 2.0], [0.9]))


def test_bad_input_is_value_error():
    with pytest.raises(ValueError, match="restitution"):
        corlab.dem.exact_chi(1.5)
    with pytest.raises(ValueError, match="law"):
        corlab.dem.simulate_impact("nope", {}, 1.0, 1.0)
    with pytest.raises(ValueError, match="params"):
        corlab.dem.simulate_impact("hertz", {}, 1.0, 1.0)


def test_cli_writes_all_files_and_reads_an_fe_table(tmp_path, corlab_bin):
    table = tmp_path / "results.csv"
    table.write_text("case_id,status,velocity,e\n"
                     "a,ok,0.5,0.8\nb,ok,1,0.7\nc,failed,2,\nd,ok,4,0.55\n")
    out = tmp_path / "x"
    done = subprocess.run([corlab_bin, "dem", "--type", "steel_ma2023:0.004",
                           "--wall", "steel_ma2023", "--wall-only", "--table", str(table),
                           "--v-min", "0.5", "--v-max", "4", "--fit-points", "4",
                           "--out", str(out)],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    for name in ("lammps.in", "lammps_nopython.in", "liggghts.in", "yade_fragment.py",
                 "restitution_table.csv",
                 "dem_export.json"):
        assert (out / name).stat().st_size > 0
    data = json.loads((out / "dem_export.json").read_text())
    pair = data["pairs"][0]
    assert pair["target"].startswith("table")
    assert pair["table"][0]["e"] == pytest.approx(0.8)
    fit = pair["thornton_limiting_pressure_Pa"]  # corlab's FE-calibrated plastic law
    assert fit["parameter"] > 0 and fit["max_abs_error"] < 0.1


def test_cli_pair_table_sets_one_pair(tmp_path, corlab_bin):
    # Two types: the FE e(v) of the glass-copper pair (--pair-table) for 1-2 only; 2-2 keeps the
    # model; bad input is one line naming pair-table, exit 2.
    table = tmp_path / "pair.csv"
    table.write_text("case_id,status,velocity,e\nb,ok,4,0.6\na,ok,0.5,0.8\n")
    types = ["--type", "glass=E=63e9,nu=0.22,rho=2500:0.002",
             "--type", "copper=E=120e9,nu=0.34,rho=8900,sy=200e6:0.005"]
    common = [corlab_bin, "dem", *types, "--model", "corlab2026", "--pair", "glass/glass=1",
              "--v-min", "0.5", "--v-max", "4", "--fit-points", "4", "--out", str(tmp_path / "x")]
    done = subprocess.run(common + ["--pair-table", "glass/copper=%s" % table],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    pairs = {p["pair"]: p for p in
             json.loads((tmp_path / "x" / "dem_export.json").read_text())["pairs"]}
    assert pairs["1-2"]["target"] == "table %s (--pair-table)" % table
    assert pairs["1-2"]["table"][0]["e"] == pytest.approx(0.8)
    assert pairs["1-2"]["table"][-1]["e"] == pytest.approx(0.6)
    assert pairs["2-2"]["target"].startswith("corlab2026 (copper on copper")
    for bad, field in (("glass=%s" % table, "pair-table"), ("glass/lead=%s" % table, "pair-table"),
                       ("glass/copper=%s" % (tmp_path / "none.csv"), "results file")):
        done = subprocess.run(common + ["--pair-table", bad], capture_output=True, text=True,
                              timeout=60)
        assert done.returncode == 2, done.stderr
        lines = done.stderr.strip().splitlines()
        assert len(lines) == 1 and lines[0].startswith("corlab: error: invalid %s = " % field)


def test_cli_bad_input_is_one_line_and_nonzero(tmp_path, corlab_bin):
    done = subprocess.run([corlab_bin, "dem", "--type", "steel_ma2023:0.004",
                           "--restitution", "1.5", "--out", str(tmp_path)],
                          capture_output=True, text=True, timeout=60)
    assert done.returncode != 0
    assert "restitution" in done.stderr and len(done.stderr.strip().splitlines()) == 1


def test_export_labels_pairs_and_time_step():
    # Issue 30's glass bead on copper: the elastic glass-glass pair set by `pairs`, labels as given.
    out = corlab.dem.export([("glass=E=63e9,nu=0.22,rho=2500", 0.002)],
                            wall="copper=E=120e9,nu=0.34,rho=8900,sy=200e6", model="corlab2026",
                            v_min=0.5, v_max=4.0, pairs={"glass/glass": 1.0})
    data = json.loads(out["json"])
    assert [p["label"] for p in data["pairs"]] == ["glass-glass", "glass-copper"]
    assert data["pairs"][0]["constant_e"] == 1.0
    assert "label='glass'" in out["yade"] and "label='copper'" in out["yade"]
    for key, text in (("lammps", out["lammps"]), ("liggghts", out["liggghts"])):
        assert "timestep %.4g\n" % data["time_step_s"][key] in text
    assert "O.dt = %.4g\n" % data["time_step_s"]["yade"] in out["yade"]
    assert "python/invoke 1 post_force" in out["lammps"]
    assert "python/invoke 1 post_force" not in out["lammps_nopython"]
    with pytest.raises(ValueError, match="glass/glass"):
        corlab.dem.export([("glass=E=63e9,nu=0.22,rho=2500", 0.002)],
                          wall="copper=E=120e9,nu=0.34,rho=8900,sy=200e6", model="corlab2026")


def test_export_friction_adds_mindlin():
    out = corlab.dem.export([("alumina=E=380e9,nu=0.23,rho=4000", 0.0025)],
                            wall="glass=E=70e9,nu=0.25,rho=2500", wall_only=True,
                            pairs={"alumina/wall": 1.0}, friction=0.092)
    pair = json.loads(out["json"])["pairs"][0]
    assert pair["friction"] == 0.092
    # 1/G* = (2 - nu1)/G1 + (2 - nu2)/G2, G = E/(2 (1 + nu)); k_t = 8 G* a
    g = 1.0 / (1.77 * 2.46 / 380e9 + 1.75 * 2.5 / 70e9)
    assert pair["mindlin_kt_per_contact_radius_Pa"] == pytest.approx(8.0 * g, rel=1e-12)
    assert "tangential mindlin_rescale %.10g " % (8.0 * g) in out["lammps"]
    assert "tangential history" in out["liggghts"]
    with pytest.raises(ValueError, match="friction"):
        corlab.dem.export([("steel_ma2023", 0.005)], wall="steel_ma2023", restitution=0.5,
                          friction=-1.0)


def test_export_has_the_clis_walls_pair_friction_and_rolling(tmp_path, corlab_bin):
    # corlab.dem.export and `corlab dem` calibrate through one entry (calibrate_export): the same
    # arguments give the same files, byte for byte, walls, per-pair mu and rolling included.
    side = "side=E=6e6,nu=0.3,rho=2000@plane:0.04,0,0,-1,0,0"
    oblique = "side=E=6e6,nu=0.3,rho=2000@plane:0,0,0.1,0,1,1,0.05"
    out = corlab.dem.export([("soft=E=1e6,nu=0.3,rho=1000", 0.004)],
                            wall="floor=E=4e6,nu=0.3,rho=2000", walls=[side, oblique],
                            restitution=0.5, friction=0.3, pair_friction={"soft/side": 0.1},
                            rolling=0.05, v_max=2.0)
    done = subprocess.run([corlab_bin, "dem", "--type", "soft=E=1e6,nu=0.3,rho=1000:0.004",
                           "--wall", "floor=E=4e6,nu=0.3,rho=2000", "--wall", side,
                           "--wall", oblique, "--restitution", "0.5", "--friction", "0.3",
                           "--friction", "soft/side=0.1", "--rolling", "0.05", "--v-max", "2",
                           "--out", str(tmp_path)], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    for key, name in (("lammps", "lammps.in"), ("lammps_nopython", "lammps_nopython.in"),
                      ("liggghts", "liggghts.in"), ("yade", "yade_fragment.py"),
                      ("json", "dem_export.json")):
        assert out[key] == (tmp_path / name).read_text(), key
    assert out["stl"] == {"corlab_wall3.stl": (tmp_path / "corlab_wall3.stl").read_text()}
    pairs = {p["label"]: p for p in json.loads(out["json"])["pairs"]}
    assert pairs["soft-side"]["friction"] == 0.1 and pairs["soft-floor"]["friction"] == 0.3
    assert "includeMoment=True" in out["yade"]
    with pytest.raises(ValueError, match="pair_friction"):
        corlab.dem.export([("steel_ma2023", 0.005)], wall="steel_ma2023", restitution=0.5,
                          pair_friction={"steel_ma2023/wall": "x"})
    with pytest.raises(ValueError, match="wall shape"):
        corlab.dem.export([("steel_ma2023", 0.005)], wall="steel_ma2023", restitution=0.5,
                          walls=["steel_ma2023@plane:0,0,0,1,0,1"])
