"""Fit of corlab's own CoR model (`corlab2026`, docs/theory/corlab_model.md) to the FE
restitution dataset, its confidence and prediction intervals, and its held-out scores.

    /usr/bin/python3 -m corlab.model_fit data/fe_restitution/dataset.csv \\
        --out data/fe_restitution/model_fit.json

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
#: Bootstrap resamples for the coefficients' confidence intervals.
BOOTSTRAP = 200


def model_inputs(table):
    """The model's dimensionless inputs of every row (dict of arrays, the keys of
    _core.corlab2026_inputs)."""
    rows = [_core.corlab2026_inputs(*dataset.material_specs(table, i), float(v))
            for i, v in enumerate(table["velocity"])]
    return {k: np.array([row[k] for row in rows]) for k in rows[0]}


def predict(inputs, coefficients, mask=None):
    """e of the model at the rows of `mask` (all rows if None)."""
    if mask is not None:
        inputs = {k: v[mask] for k, v in inputs.items()}
    return _core.corlab2026_restitution(inputs, coefficients)


def split(table):
    """Boolean masks (train, random held-out, corner held-out)."""
    random_out = np.array([int(cid[1:], 16) % 5 == 0 for cid in table["case_id"]])
    corner = table["modulus_ratio"] > CORNER_MODULUS_RATIO
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


def run(path, resamples=BOOTSTRAP, fixed=None):
    """The whole fit of dataset.csv at `path`: coefficients, intervals, held-out scores."""
    table = dataset.read(path)
    inputs = model_inputs(table)
    train, random_out, corner = split(table)
    coefficients = fit(table, inputs, train, fixed)
    e_model = predict(inputs, coefficients)
    rel = _core.relative_errors(e_model, table["e"])
    return {
        "model": "corlab2026",
        "dataset": str(path),
        "rows": int(table["e"].size),
        "rows_train": int(train.sum()),
        "rows_random_holdout": int(random_out.sum()),
        "rows_corner_holdout": int(corner.sum()),
        "corner": f"modulus_ratio > {CORNER_MODULUS_RATIO}",
        "coefficients": coefficients,
        "fixed": dict(fixed or {}),
        "confidence_95": bootstrap_intervals(table, inputs, train, resamples, fixed=fixed),
        # 95 % of the training rows' relative errors lie within +- this [-].
        "prediction_interval_95": float(np.percentile(np.abs(rel[train]), 95)),
        "scores": {"train": dataset.score(table, e_model, train),
                   "random holdout": dataset.score(table, e_model, random_out),
                   "corner holdout": dataset.score(table, e_model, corner),
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
    parser.add_argument("dataset", help="dataset.csv (corlab dataset export)")
    parser.add_argument("--out", required=True, help="model_fit.json to write")
    parser.add_argument("--bootstrap", type=int, default=BOOTSTRAP, help="resamples")
    parser.add_argument("--fix", action="append", default=[], metavar="NAME=VALUE",
                        help="pin a coefficient (an ablation; repeatable)")
    args = parser.parse_args(argv)
    result = run(args.dataset, args.bootstrap, parse_fixed(args.fix, parser))
    with open(args.out, "w") as f:
        json.dump(_finite(result), f, indent=2, sort_keys=True)
        f.write("\n")
    s = result["scores"]
    print(f"corlab2026: {result['rows_train']} rows fitted; RMS / worst relative error: train "
          f"{s['train']['all']['rms']:.4f} / {s['train']['all']['worst']:+.4f}, random holdout "
          f"{s['random holdout']['all']['rms']:.4f} / {s['random holdout']['all']['worst']:+.4f},"
          f" corner {s['corner holdout']['all']['rms']:.4f} -> {args.out}")


if __name__ == "__main__":
    main()
