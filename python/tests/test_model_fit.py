"""corlab's model (corlab2026) and its fit: the shipped coefficients are what refitting the
shipped dataset gives; the kernel through Python is the library's; the split is fixed; and on
the paper's corner the model's form recovers the cavity-model and Tabor values."""
# SPDX-License-Identifier: BSD-3-Clause
import json
import math
import pathlib

import numpy as np
import pytest

import corlab
from corlab import dataset, model_fit

ROOT = pathlib.Path(__file__).resolve().parents[2]
DATA = ROOT / "data" / "fe_restitution"


def test_refitting_the_shipped_dataset_gives_the_shipped_coefficients():
    shipped = json.loads((DATA / "model_fit.json").read_text())
    table = dataset.read(DATA / "dataset.csv")
    inputs = model_fit.model_inputs(table)
    train, random_out, corner = model_fit.split(table)
    assert train.sum() == shipped["rows_train"]
    assert random_out.sum() == shipped["rows_random_holdout"]
    assert corner.sum() == shipped["rows_corner_holdout"]
    refit = model_fit.fit(table, inputs, train)
    for name in model_fit.NAMES:
        assert refit[name] == pytest.approx(shipped["coefficients"][name], rel=1e-6), name
    # The library's coefficients are the file's to the last bit (the build generates them from
    # it), under the C++ table's names, in the fit's order.
    assert tuple(corlab.corlab2026_fitted()) == model_fit.NAMES
    assert corlab.corlab2026_fitted() == shipped["coefficients"]


def test_kernel_through_python_is_the_registered_model():
    k = corlab.corlab2026_fitted()
    sphere, substrate = "E=300e9,nu=0.25,rho=7850,sy=900e6,H=3e9", "E=210e9,nu=0.3,rho=7850,sy=5e8"
    for v in (0.05, 0.5, 5.0, 50.0):
        inputs = {key: np.array([val]) for key, val in
                  corlab.corlab2026_inputs(sphere, substrate, v).items()}
        e = corlab.corlab2026_restitution(inputs, k)[0]
        assert e == corlab.predict("corlab2026", sphere, substrate, v)
    assert corlab.predict("corlab2026", sphere, substrate, 1e-4) == 1.0


def test_split_is_a_fifth_by_case_id_and_the_stiff_sphere_corner():
    table = {"case_id": ["c0000000005", "c0000000006", "c000000000a"],
             "modulus_ratio": np.array([1.0, 4.5, 1.0])}
    train, random_out, corner = model_fit.split(table)
    assert list(random_out) == [True, False, True]
    assert list(corner) == [False, True, False]
    assert list(train) == [False, False, False]


def test_scores_and_regimes():
    table = {"e": np.array([1.0, 0.5, 0.8, 0.4, 0.6]),
             "velocity_ratio": np.array([2.0, 10.0, 400.0, 20.0, 1.5])}
    e_model = np.array([1.01, 0.485, math.nan, 0.408, 0.6])
    s = dataset.score(table, e_model, np.array([True, True, True, True, False]))
    assert s["all"]["n"] == 3 and s["all"]["worst"] == pytest.approx(-0.03)
    assert s["all"]["rms"] == pytest.approx(math.sqrt((1 + 9 + 4) / 3) / 100)
    assert s["near-yield"]["n"] == 1 and s["near-yield"]["bias"] == pytest.approx(0.01)
    assert s["elastic-plastic"]["n"] == 2 and s["fully plastic"]["n"] == 0
    assert math.isnan(s["fully plastic"]["rms"])
    assert dataset.regime(np.array([1.5, 3.0, 10.0, 300.0, 301.0])) == [
        "near-yield", "near-yield", "elastic-plastic", "elastic-plastic", "fully plastic"]


def test_an_ablation_pins_the_named_coefficients_and_fits_the_rest():
    table = dataset.read(DATA / "dataset.csv")
    inputs = model_fit.model_inputs(table)
    train, _, _ = model_fit.split(table)
    pinned = {"compliance_first": 0.0, "compliance_other": 0.0, "flattening": 0.0}
    k = model_fit.fit(table, inputs, train, pinned)
    assert {n: k[n] for n in pinned} == pinned
    e = table["e"][train]
    rms = {name: float(np.sqrt(np.mean(((model_fit.predict(inputs, c, train) - e) / e) ** 2)))
           for name, c in (("pinned", k), ("free", model_fit.fit(table, inputs, train)))}
    # Freeing three coefficients cannot fit the same rows worse.
    assert rms["free"] <= rms["pinned"]


def test_fix_rejects_unknown_names_and_values(capsys):
    for bad in ("bogus=1", "c1=abc"):
        with pytest.raises(SystemExit):
            model_fit.main([str(DATA / "dataset.csv"), "--out", "/dev/null", "--fix", bad])
        assert "--fix" in capsys.readouterr().err


def test_compliance_share_is_the_spheres_part_of_one_over_e_star():
    same = corlab.corlab2026_inputs("E=210e9,nu=0.3,rho=7850", "E=210e9,nu=0.3,rho=7850,sy=5e8",
                                    1.0)
    assert same["compliance_share"] == pytest.approx(0.5, rel=1e-14)
    soft = corlab.corlab2026_inputs("E=70e9,nu=0.2,rho=2500", "E=210e9,nu=0.3,rho=7850,sy=5e8",
                                    1.0)
    c_sphere, c_substrate = (1 - 0.2**2) / 70e9, (1 - 0.3**2) / 210e9
    assert soft["compliance_share"] == pytest.approx(c_sphere / (c_sphere + c_substrate),
                                                     rel=1e-12)
    # The substrate yields first (the sphere is elastic): its nu and a_y/R = pi C(nu) sy / (2 E*).
    assert soft["poisson_first"] == 0.3
    e_star = 1 / (c_sphere + c_substrate)
    assert soft["contact_radius_at_yield"] == pytest.approx(
        math.pi * 1.295 * math.exp(0.736 * 0.3) * 5e8 / (2 * e_star), rel=1e-12)
    # A yielding sphere weaker than the substrate yields first: its nu.
    first = corlab.corlab2026_inputs("E=70e9,nu=0.2,rho=2500,sy=1e8",
                                     "E=210e9,nu=0.3,rho=7850,sy=5e8", 1.0)
    assert first["poisson_first"] == 0.2 and first["other_is_sphere"] == 0.0


PAIRS = ROOT / "data" / "fe_restitution_pairs"


def test_refitting_the_union_gives_the_pair_models_coefficients():
    shipped = json.loads((PAIRS / "model_fit.json").read_text())
    assert shipped["model"] == "corlab2026p"
    table = model_fit.read_union([DATA / "dataset.csv", PAIRS / "dataset.csv"])
    inputs = model_fit.model_inputs(table, "corlab2026p")
    train, random_out, corner = model_fit.split(table, "corlab2026p")
    assert train.sum() == shipped["rows_train"]
    assert random_out.sum() == shipped["rows_random_holdout"]
    assert corner.sum() == shipped["rows_corner_holdout"]
    refit = model_fit.fit(table, inputs, train)
    for name in model_fit.NAMES:
        assert refit[name] == pytest.approx(shipped["coefficients"][name], rel=1e-6), name
    assert corlab.corlab2026p_fitted() == shipped["coefficients"]


def test_union_and_corners_of_the_pair_model():
    table = model_fit.read_union([DATA / "dataset.csv", PAIRS / "dataset.csv"])
    flat = dataset.read(DATA / "dataset.csv")
    n = len(flat["e"])
    assert list(table["case_id"][:n]) == list(flat["case_id"])
    assert not table["radius_ratio"][:n].any() and table["radius_ratio"][n:].any()
    corners = model_fit.corners(table, "corlab2026p")
    assert sorted(corners) == ["corner holdout density_ratio > 5",
                               "corner holdout modulus_ratio > 10"]
    assert corners["corner holdout modulus_ratio > 10"].sum() == np.sum(
        table["modulus_ratio"] > 10)
    # The flat model's split is unchanged.
    assert model_fit.corners(flat).keys() == {"corner holdout"}


def test_pair_inputs_reduce_to_the_flat_models_for_equal_densities():
    sphere, flat = "E=300e9,nu=0.25,rho=7850,sy=900e6,H=3e9", "E=210e9,nu=0.3,rho=7850,sy=5e8"
    assert corlab.corlab2026p_inputs(sphere, flat, 5.0) == corlab.corlab2026_inputs(
        sphere, flat, 5.0)
    # A dense elastic sphere on a light flat: the damage number on the flat's density.
    dense, light = "E=600e9,nu=0.24,rho=15000", "E=70e9,nu=0.33,rho=2700,sy=100e6"
    ours = corlab.corlab2026p_inputs(dense, light, 20.0)
    old = corlab.corlab2026_inputs(dense, light, 20.0)
    assert ours["damage_at_yield"] == pytest.approx(old["damage_at_yield"] * 2700 / 15000,
                                                    rel=1e-14)
    second = corlab.corlab2026p_inputs(dense, light, 20.0, radius_ratio=0.5)
    assert second["radius_ratio"] == 0.5
    with pytest.raises(ValueError):
        corlab.corlab2026p_inputs(dense, light, 20.0, radius_ratio=-1.0)


def test_models_are_scored_on_pair_rows_through_the_reduced_sphere():
    """A sphere-on-flat model sees a pair row as the sphere of density rho* on a flat of the
    other body; corlab2026's own box is the flat dataset's box, so no row of the pair box but a
    flat of equal densities with E ratio 0.2-5."""
    pairs = dataset.read(PAIRS / "dataset.csv")
    spheres = np.flatnonzero(np.array(pairs["substrate_shape"]) == "sphere")
    i = int(spheres[0])
    sphere, other = dataset.material_specs(pairs, i, reduced=True)
    assert f"rho={pairs['effective_density'][i]!r}" in sphere
    assert f"rho={pairs['sphere_rho'][i]!r}" in dataset.material_specs(pairs, i)[0]
    e = dataset.predictions({k: (v[[i]] if isinstance(v, np.ndarray) else [v[i]])
                             for k, v in pairs.items()}, "corlab2026")
    assert e[0] == corlab.predict("corlab2026", sphere, other, float(pairs["velocity"][i]))
    info = next(m for m in corlab._core.models() if m["name"] == "corlab2026")
    flat = dataset.read(DATA / "dataset.csv")
    assert dataset.in_model_box(flat, info).all()
    box = dataset.in_model_box(pairs, info)
    expected = ((np.array(pairs["substrate_shape"]) == "flat")
                & np.isclose(pairs["density_ratio"], 1.0, rtol=1e-9, atol=0)
                & (pairs["modulus_ratio"] >= 0.2) & (pairs["modulus_ratio"] <= 5.0))
    assert np.array_equal(box, expected)
    assert corlab._core.dataset_box("flat")["density_ratio"] == [1.0, 1.0]
    with pytest.raises(ValueError, match="flat or pairs"):
        corlab._core.dataset_box("cubes")


def test_corlab2026p_is_accurate_to_the_damage_number_it_claims():
    """The shipped model's accurate_damage_number is measured, not chosen: up to it, the random
    held-out 20 % and both held-out corners are within 2 % RMS (corlab2026p_scores.py's second
    table); over the whole box the density corner is not."""
    limit = next(m for m in corlab.models() if m["name"] == "corlab2026p")[
        "accurate_damage_number"]
    table = model_fit.read_union([DATA / "dataset.csv", PAIRS / "dataset.csv"])
    e = model_fit.predict(model_fit.model_inputs(table, "corlab2026p"),
                          corlab.corlab2026p_fitted())
    rel = (e - table["e"]) / table["e"]
    _, random_out, _ = model_fit.split(table, "corlab2026p")
    held_out = {"random": random_out, **model_fit.corners(table, "corlab2026p")}
    low = table["damage_number"] <= limit
    for name, rows in held_out.items():
        assert np.sqrt(np.mean(rel[rows & low] ** 2)) <= 0.02, name
    density = held_out["corner holdout density_ratio > 5"]
    assert np.sqrt(np.mean(rel[density] ** 2)) > 0.02
