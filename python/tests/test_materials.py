"""Tests of the material bindings (corlab.Material, corlab.material, effective_modulus, k1, k2)."""
# SPDX-License-Identifier: BSD-3-Clause
import pytest

import corlab


def test_material_names_contain_seed_materials():
    names = corlab.material_names()
    for n in ("alumina_ma2023", "aluminium_ma2023", "steel_jackson2010", "steel_ma2023"):
        assert n in names


def test_material_from_database():
    m = corlab.material("aluminium_ma2023")
    assert m.name == "aluminium_ma2023"
    assert m.E == 68e9
    assert m.nu == 0.33
    assert m.sigma_y == 380e6
    assert "Ma et al. 2023" in m.source
    assert corlab.material("alumina_ma2023").sigma_y is None


def test_inline_and_override_specs():
    m = corlab.material("E=370e9,nu=0.22,rho=3958,sy=1e9")
    assert (m.name, m.E, m.nu, m.rho, m.sigma_y) == ("inline", 370e9, 0.22, 3958.0, 1e9)
    o = corlab.material("steel_ma2023,sy=700e6")
    assert o.sigma_y == 700e6
    assert o.name == "steel_ma2023 (modified)"


def test_material_constructor_validates():
    m = corlab.Material(E=200e9, nu=0.3, rho=7850.0)
    assert m.sigma_y is None and m.H == 0.0
    with pytest.raises(ValueError, match=r"^invalid material.E = -1: must be > 0 \[Pa\]$"):
        corlab.Material(E=-1.0, nu=0.3, rho=7850.0)
    with pytest.raises(ValueError, match=r"invalid material.nu = 0.5: must be in \(-1, 0.5\)"):
        corlab.Material(E=1e9, nu=0.5, rho=1.0)


@pytest.mark.parametrize("spec, message", [
    ("unobtainium", r"invalid material = 'unobtainium': must be one of \["),
    ("E=1e9,nu=0.3", r"invalid material = .E=1e9,nu=0.3.: must be a database name or an inline "
                     r"material with E, nu and rho \(it lacks rho; "),
    ("E=abc,nu=0.3,rho=1", r"invalid material.E = 'abc': must be a finite number"),
    ("E=1e9,nu=0.3,rho=1,foo=2", r"invalid material key = 'foo': must be one of E, nu, rho"),
    ("E=1e9,nu=0.3,rho=1,sy=2e9",
     r"invalid material.sigma_y = 2000000000: must be in \(0, 0.1 E\) \[Pa\]"),
    ("steel_ma2023,oops", r"invalid material = 'oops': must be a key=value pair"),
])
def test_bad_specs(spec, message):
    with pytest.raises(ValueError, match=message):
        corlab.material(spec)


def test_effective_modulus_and_groups():
    a = corlab.material("alumina_ma2023")
    al = corlab.material("aluminium_ma2023")
    es = corlab.effective_modulus(a, al)
    assert es == pytest.approx(63.7905e9, abs=1e5)
    assert corlab.k1(es, a.rho, 1.0) == pytest.approx(es / a.rho)
    assert corlab.k2(380e6, es) == pytest.approx(380e6 / es)
