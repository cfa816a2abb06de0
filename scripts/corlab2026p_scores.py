"""Scores of corlab's pair model (corlab2026p, fitted coefficients from
data/fe_restitution_pairs/model_fit.json through the library) next to corlab2026 at the pair's
rho* (its shipped coefficients, the sphere's density replaced by rho*), by subset: the flat
dataset, the pair dataset's flats and second spheres, the paper's corner (Table 2, and by its
density ratio), and issue 26's user case (a tungsten-carbide-like sphere on aluminium alloy
at 20 m/s, FE e = 0.1486); then corlab2026p's held-out sets (model_fit.split) up to a Johnson
damage number rho* v^2 / sigma_y,substrate (the dataset's `damage_number`), which sets how far
the impact deforms the bodies.
Relative errors (e_model - e_FE) / e_FE: RMS / worst / bias in %.

    PYTHONPATH=build/python /usr/bin/python3 scripts/corlab2026p_scores.py \\
        data/fe_restitution_pairs/dataset.csv
"""
# SPDX-License-Identifier: BSD-3-Clause
import argparse
import math
import pathlib

import numpy as np

import corlab
from corlab import dataset, model_fit

ROOT = pathlib.Path(__file__).resolve().parents[1]
USER_CASE = ("E=600e9,nu=0.24,rho=15000", "E=70e9,nu=0.33,rho=2700,sy=100e6,H=0", 20.0, 0.1486)
#: Upper bounds of the damage number for the held-out table [-] (0.26 bounds the design box).
DAMAGE_LIMITS = (0.003, 0.01, 0.05, math.inf)


def rho_star_inputs(table):
    """corlab2026's inputs with the sphere's density replaced by the pair's rho*."""
    rows = [corlab.corlab2026_inputs(*dataset.material_specs(table, i, reduced=True), float(v))
            for i, v in enumerate(table["velocity"])]
    return {k: np.array([row[k] for row in rows]) for k in rows[0]}


def cell(rel):
    return (f"{100 * np.sqrt(np.mean(rel ** 2)):.2f} / {100 * rel[np.argmax(abs(rel))]:+.1f} / "
            f"{100 * rel.mean():+.2f} ({rel.size})")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("pairs", help="the pair dataset.csv (corlab dataset export)")
    args = parser.parse_args()
    flat = ROOT / "data" / "fe_restitution"
    subsets = {"flat dataset": dataset.read(flat / "dataset.csv"),
               "paper corner (Table 2)": dataset.read(flat / "paper_corner" / "dataset.csv")}
    corner = subsets["paper corner (Table 2)"]
    for ratio in sorted(set(np.round(corner["density_ratio"], 3))):
        mask = np.round(corner["density_ratio"], 3) == ratio
        subsets[f"paper corner, density ratio {ratio:g}"] = {
            k: (v[mask] if isinstance(v, np.ndarray) else [x for x, m in zip(v, mask) if m])
            for k, v in corner.items()}
    pairs = dataset.read(args.pairs)
    shape = np.array(pairs["substrate_shape"])
    for name, mask in (("pair flats", shape == "flat"), ("pair second spheres", shape != "flat")):
        subsets[name] = {k: (v[mask] if isinstance(v, np.ndarray) else
                             [x for x, m in zip(v, mask) if m]) for k, v in pairs.items()}
    ours, old = corlab.corlab2026p_fitted(), corlab.corlab2026_fitted()
    print("| rows | corlab2026 at rho* | corlab2026p |\n|---|---|---|")
    for name, table in subsets.items():
        e_old = model_fit.predict(rho_star_inputs(table), old)
        e_new = model_fit.predict(model_fit.model_inputs(table, "corlab2026p"), ours)
        print(f"| {name} | {cell((e_old - table['e']) / table['e'])} | "
              f"{cell((e_new - table['e']) / table['e'])} |")
    sphere, other, v, e_fe = USER_CASE
    e_old = corlab.predict("corlab2026", sphere, other, v)
    e_new = corlab.predict("corlab2026p", sphere, other, v)
    print(f"| user case (FE e = {e_fe}) | {e_old:.4f} ({100 * (e_old / e_fe - 1):+.1f} %) | "
          f"{e_new:.4f} ({100 * (e_new / e_fe - 1):+.1f} %) |")
    by_damage(args.pairs)


def by_damage(pairs_path):
    """corlab2026p's held-out sets (and all rows) up to each damage number of DAMAGE_LIMITS."""
    table = model_fit.read_union([ROOT / "data" / "fe_restitution" / "dataset.csv", pairs_path])
    inputs = model_fit.model_inputs(table, "corlab2026p")
    rel = (model_fit.predict(inputs, corlab.corlab2026p_fitted()) - table["e"]) / table["e"]
    _, random_out, _ = model_fit.split(table, "corlab2026p")
    sets = {"random 20 %": random_out, **model_fit.corners(table, "corlab2026p"),
            "all rows": np.ones(rel.size, dtype=bool)}
    depth = np.log(table["delta_max"] / table["sphere_radius"])
    print(f"\nln(delta_max / R1) against ln(damage number), correlation "
          f"{np.corrcoef(depth, np.log(table['damage_number']))[0, 1]:.3f}")
    print("\n| damage number <= | " + " | ".join(sets) + " |\n" + "|---" * (len(sets) + 1) + "|")
    for limit in DAMAGE_LIMITS:
        low = table["damage_number"] <= limit
        print(f"| {limit:g} | " + " | ".join(cell(rel[mask & low]) for mask in sets.values())
              + " |")


if __name__ == "__main__":
    main()
