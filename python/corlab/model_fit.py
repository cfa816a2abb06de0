"""Fit of corlab's own CoR model (`corlab2026`, docs/theory/corlab_model.md) to the FE
restitution dataset, its confidence and prediction intervals, and its held-out scores.

    /usr/bin/python3 -m corlab.model_fit data/fe_restitution/dataset.csv \\
        --out data/fe_restitution/model_fit.json

The pair model (`corlab2026p`, corlab2026p.hpp: the same kernel and coefficients' names over
particle pairs) is fitted to the union of the flat and pair datasets, with issue 26's corners
held out (E_sphere / E_other > 10, rho_sphere / rho_other > 5):

    /usr/bin/python3 -m corlab.model_fit data/fe_restitution/dataset.csv \\
        data/fe_restitution_pairs/dataset.csv --model corlab2026p \\
        --out data/fe_restitution_pairs/model_fit.json

Held out of the fit (never used in it): a random 20 % of the rows (those whose case id, a hash,
is 0 mod 5) and a corner, the largest modulus ratios (E_sphere / E_substrate > 4). The
coefficients minimise the sum of squared relative errors (e_model - e_FE) / e_FE over the rest
(scipy least_squares, trust-region reflective within physical bounds, from a fixed start: the
same data give the same coefficients). The model is evaluated by the C++ kernel
(corlab._core.corlab2026_restitution), the one the library, the CLI and DEM exports use. The
build generates the library's coefficients from data/fe_restitution/model_fit.json (a configure
dependency, cmake/Corlab2026Coefficients.cmake): a refit written there reaches
corlab2026_fitted() at the next build.
"""
# SPDX-License-Identifier: BSD-3-Clause
import argparse
import json
import math

import numpy as np
from scipy.optimize import least_squares

from . import _core, dataset

#: Coefficient names, start values and bounds (corlab2026.hpp). c1 < 0.4 keeps e decreasing.
PARAMETERS = (
    ("c1", 0.25, 0.0, 0.39),
    ("phi_max", 2.8, 1.0, 10.0),
    ("kappa", 2.8, 0.0, 30.0),
    ("kappa_cavity", 2.8, 0.0, 30.0),
    ("b", 2.0, 0.0, 100.0),
    ("c", 0.55, 0.05, 3.0),
    ("gamma_sphere", 0.15, 0.0, 3.0),
    ("gamma_substrate", 0.2, 0.0, 3.0),
    ("compliance_first", 0.0, -5.0, 5.0),
    ("compliance_other", 0.0, -5.0, 5.0),
    ("flattening", 1.0, 0.01, 30.0),
)
NAMES = tuple(p[0] for p in PARAMETERS)

#: The held-out corner: modulus ratios above this [-].
CORNER_MODULUS_RATIO = 4.0
#: corlab2026p's held-out corners (issue 26): (name, column, rows above this value [-]).
PAIR_CORNERS = tuple((f"corner holdout {column} > {bound:g}", column, bound)
                     for column, bound in dataset.PAIR_CORNERS)
MODELS = ("corlab2026", "corlab2026p")
#: Bootstrap resamples for the coefficients' confidence intervals.
BOOTSTRAP = 200


def model_inputs(table, model="corlab2026"):
    """The model's dimensionless inputs of every row (dict of arrays, the keys of
    _core.corlab2026_inputs); corlab2026p reads the rows' radius_ratio (0, a flat, if absent)."""
    if model == "corlab2026p":
        ratios = table.get("radius_ratio", np.zeros(len(table["velocity"])))
        rows = [_core.corlab2026p_inputs(*dataset.material_specs(table, i), float(v),
                                         float(ratios[i]))
                for i, v in enumerate(table["velocity"])]
    else:
        rows = [_core.corlab2026_inputs(*dataset.material_specs(table, i), float(v))
                for i, v in enumerate(table["velocity"])]
    return {k: np.array([row[k] for row in rows]) for k in rows[0]}


def read_union(paths):
    """The included rows of several dataset.csv files, one after the other: the columns they all
    have, and radius_ratio (0 for a file without it: the flat dataset)."""
    tables = [dataset.read(p) for p in paths]
    for t in tables:
        if "radius_ratio" not in t:
            t["radius_ratio"] = np.zeros(len(t["e"]))
    keys = [k for k in tables[0] if all(k in t for t in tables)]
    return {k: (np.concatenate([t[k] for t in tables]) if isinstance(tables[0][k], np.ndarray)
                else [x for t in tables for x in t[k]]) for k in keys}


def predict(inputs, coefficients, mask=None):
    """e of the model at the rows of `mask` (all rows if None)."""
    if mask is not None:
        inputs = {k: v[mask] for k, v in inputs.items()}
    return _core.corlab2026_restitution(inputs, coefficients)


def corners(table, model="corlab2026"):
    """{score name: boolean mask} of the model's held-out corners."""
    if model == "corlab2026p":
        return {name: table[column] > bound for name, column, bound in PAIR_CORNERS}
    return {"corner holdout": table["modulus_ratio"] > CORNER_MODULUS_RATIO}


def split(table, model="corlab2026"):
    """Boolean masks (train, random held-out, corner held-out: any of the model's corners)."""
    random_out = np.array([int(cid[1:], 16) % 5 == 0 for cid in table["case_id"]])
    corner = np.logical_or.reduce(list(corners(table, model).values()))
    return ~random_out & ~corner, random_out & ~corner, corner


def fit(table, inputs, mask, fixed=None):
    """Least-squares coefficients (dict) on the rows of `mask`; `fixed` pins some {name: value}
    (an ablation: what a term is worth on the held-out rows)."""
    fixed = fixed or {}
    free = [p for p in PARAMETERS if p[0] not in fixed]
    e = table["e"][mask]
    sub = {k: v[mask] for k, v in inputs.items()}

    def coefficients(p):
        return {**fixed, **dict(zip((f[0] for f in free), p))}

    def residuals(p):
        return _core.relative_errors(_core.corlab2026_restitution(sub, coefficients(p)), e)

    start = [p[1] for p in free]
    bounds = ([p[2] for p in free], [p[3] for p in free])
    result = least_squares(residuals, start, bounds=bounds, x_scale="jac")
    k = coefficients(float(v) for v in result.x)
    return {n: float(k[n]) for n in NAMES}


def bootstrap_intervals(table, inputs, mask, resamples=BOOTSTRAP, seed=2026, fixed=None):
    """95 % bootstrap intervals {name: [low, high]} (rows resampled with replacement; none for
    0 resamples)."""
    if resamples <= 0:
        return {}
    rng = np.random.default_rng(seed)
    rows = np.flatnonzero(mask)
    samples = []
    for _ in range(resamples):
        pick = np.zeros(mask.size, dtype=int)
        np.add.at(pick, rng.choice(rows, rows.size), 1)
        expanded = np.repeat(np.arange(mask.size), pick)
        sub_table = {"e": table["e"][expanded]}
        sub_inputs = {k: v[expanded] for k, v in inputs.items()}
        samples.append([fit(sub_table, sub_inputs, np.ones(expanded.size, bool), fixed)[n]
                        for n in NAMES])
    samples = np.array(samples)
    return {n: [float(np.percentile(samples[:, j], 2.5)), float(np.percentile(samples[:, j], 97.5))]
            for j, n in enumerate(NAMES)}


def run(path, resamples=BOOTSTRAP, fixed=None, model="corlab2026"):
    """The whole fit of dataset.csv at `path` (a list of paths: their union): coefficients,
    intervals, held-out scores."""
    paths = path if isinstance(path, (list, tuple)) else [path]
    table = read_union(paths) if len(paths) > 1 else dataset.read(paths[0])
    inputs = model_inputs(table, model)
    train, random_out, corner = split(table, model)
    coefficients = fit(table, inputs, train, fixed)
    e_model = predict(inputs, coefficients)
    rel = _core.relative_errors(e_model, table["e"])
    corner_scores = {}
    if model == "corlab2026p":
        corner_scores = {name: dataset.score(table, e_model, mask)
                         for name, mask in corners(table, model).items()}
    return {
        "model": model,
        "dataset": str(paths[0]) if len(paths) == 1 else [str(p) for p in paths],
        "rows": int(table["e"].size),
        "rows_train": int(train.sum()),
        "rows_random_holdout": int(random_out.sum()),
        "rows_corner_holdout": int(corner.sum()),
        "corner": (f"modulus_ratio > {CORNER_MODULUS_RATIO}" if model == "corlab2026" else
                   " or ".join(f"{c} > {b}" for _, c, b in PAIR_CORNERS)),
        "coefficients": coefficients,
        "fixed": dict(fixed or {}),
        "confidence_95": bootstrap_intervals(table, inputs, train, resamples, fixed=fixed),
        # 95 % of the training rows' relative errors lie within +- this [-].
        "prediction_interval_95": float(np.percentile(np.abs(rel[train]), 95)),
        "scores": {"train": dataset.score(table, e_model, train),
                   "random holdout": dataset.score(table, e_model, random_out),
                   "corner holdout": dataset.score(table, e_model, corner),
                   **corner_scores,
                   "all": dataset.score(table, e_model)},
    }


def _finite(obj):
    """JSON-safe copy: nan -> None."""
    if isinstance(obj, dict):
        return {k: _finite(v) for k, v in obj.items()}
    if isinstance(obj, list):
        return [_finite(v) for v in obj]
    if isinstance(obj, float) and not math.isfinite(obj):
        return None
    return obj


def parse_fixed(items, parser):
    """{name: value} of --fix NAME=VALUE items (a clear error for an unknown name or value)."""
    fixed = {}
    for item in items:
        name, _, value = item.partition("=")
        if name not in NAMES:
            parser.error(f"--fix: unknown coefficient '{name}' (one of {', '.join(NAMES)})")
        try:
            fixed[name] = float(value)
        except ValueError:
            parser.error(f"--fix {name}: value '{value}' is not a number")
    return fixed


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dataset", nargs="+",
                        help="dataset.csv (corlab dataset export); several: their union")
    parser.add_argument("--model", choices=MODELS, default="corlab2026",
                        help="corlab2026 (flat) or corlab2026p (pairs: fit the union)")
    parser.add_argument("--out", required=True, help="model_fit.json to write")
    parser.add_argument("--bootstrap", type=int, default=BOOTSTRAP, help="resamples")
    parser.add_argument("--fix", action="append", default=[], metavar="NAME=VALUE",
                        help="pin a coefficient (an ablation; repeatable)")
    args = parser.parse_args(argv)
    result = run(args.dataset, args.bootstrap, parse_fixed(args.fix, parser), args.model)
    with open(args.out, "w") as f:
        json.dump(_finite(result), f, indent=2, sort_keys=True)
        f.write("\n")
    s = result["scores"]
    print(f"{args.model}: {result['rows_train']} rows fitted; RMS / worst relative error: train "
          f"{s['train']['all']['rms']:.4f} / {s['train']['all']['worst']:+.4f}, random holdout "
          f"{s['random holdout']['all']['rms']:.4f} / {s['random holdout']['all']['worst']:+.4f},"
          f" corner {s['corner holdout']['all']['rms']:.4f} -> {args.out}")


if __name__ == "__main__":
    main()
