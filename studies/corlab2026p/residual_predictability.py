"""How much of corlab2026p's remaining error a flexible learner can explain (issue 26, item 5):
is the fully plastic scatter a missing term of the closed form, or out of reach of the data?

model_fit.py's protocol: corlab2026p fitted on the training rows of the union of the flat and
pair datasets (a random 20 % by case id and the corners E ratio > 10, density ratio > 5 held
out). Then a gradient-boosted tree ensemble (scikit-learn's HistGradientBoostingRegressor) learns
the fitted model's log residual ln(e_FE / e_model) on the training rows from every input the
model sees and more (both Poisson's ratios, the density and modulus ratios, k2), and corrects the
held-out rows. If the learner brings the fitted rows near the FE's own error bars but the
held-out rows stay far above them, the residual is a function of the inputs (dimensional
analysis) that this much data does not pin down. Prints a Markdown table: RMS / worst / bias in %
by set and by regime (corlab.dataset's regimes of v / v_y).

Exploration only (not run by the tests); needs Debian's python3-sklearn:

    apt-get install python3-sklearn
    PYTHONPATH=build/python /usr/bin/python3 studies/corlab2026p/residual_predictability.py \\
        data/fe_restitution/dataset.csv data/fe_restitution_pairs/dataset.csv
"""
# SPDX-License-Identifier: BSD-3-Clause
import argparse

import numpy as np
from sklearn.ensemble import HistGradientBoostingRegressor

from candidates import cell  # this folder's scorer: RMS / worst / bias (rows)
from corlab import dataset, model_fit


def features(table, inputs):
    """The learner's inputs: the model's (logarithms of the wide ones) and the raw ratios."""
    def log10(a):
        return np.log10(np.maximum(np.asarray(a, float), 1e-12))

    other = np.asarray(inputs["velocity_ratio_other"], float)
    columns = {
        "log x": log10(inputs["velocity_ratio"]),
        "log x_other": log10(np.where(np.isfinite(other), other, 0.0)),
        "h_first": inputs["hardening_first"], "h_other": inputs["hardening_other"],
        "log D_y": log10(inputs["damage_at_yield"]),
        "compliance share": inputs["compliance_share"],
        "log a_y/R*": log10(inputs["contact_radius_at_yield"]),
        "R1/R2": inputs["radius_ratio"], "other is sphere": inputs["other_is_sphere"] * 1.0,
        "log rho ratio": log10(table["density_ratio"]),
        "log E ratio": log10(table["modulus_ratio"]),
        "nu sphere": table["nu_sphere"], "nu substrate": table["nu_substrate"], "k2": table["k2"]}
    return list(columns), np.column_stack(list(columns.values()))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("datasets", nargs="+", help="dataset.csv files (corlab dataset export)")
    parser.add_argument("--seed", type=int, default=2026)
    args = parser.parse_args()
    table = model_fit.read_union(args.datasets)
    inputs = model_fit.model_inputs(table, "corlab2026p")
    train, random_out, _ = model_fit.split(table, "corlab2026p")
    coefficients = model_fit.fit(table, inputs, train)
    e_model = model_fit.predict(inputs, coefficients)
    residual = np.log(table["e"] / e_model)
    names, x = features(table, inputs)
    learner = HistGradientBoostingRegressor(max_iter=400, learning_rate=0.05, max_leaf_nodes=15,
                                            min_samples_leaf=20, random_state=args.seed)
    learner.fit(x[train], residual[train])
    e_corrected = e_model * np.exp(learner.predict(x))
    sets = {"fitted": train, "random 20 % held out": random_out,
            **model_fit.corners(table, "corlab2026p")}
    regimes = np.array(dataset.regime(table["velocity_ratio"]))
    bar = np.asarray(table["e_error"]) / table["e"]
    print(f"{train.sum()} training rows; {len(names)} learner inputs: {', '.join(names)}\n")
    print("| set | regime | FE error bar e_error/e: median / 95th pct | corlab2026p | "
          "corlab2026p x learned correction |\n|---|---|---|---|---|")
    for set_name, mask in sets.items():
        for regime in ("all",) + tuple(name for name, _ in dataset.REGIMES):
            m = mask & ((regimes == regime) | (regime == "all"))
            if not m.any():
                continue
            print(f"| {set_name} | {regime} | {100 * np.median(bar[m]):.2f} / "
                  f"{100 * np.quantile(bar[m], 0.95):.2f} | "
                  f"{cell((e_model - table['e']) / table['e'], m)} | "
                  f"{cell((e_corrected - table['e']) / table['e'], m)} |")


if __name__ == "__main__":
    main()
