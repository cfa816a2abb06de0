"""The FE restitution dataset (data/fe_restitution/, docs/theory/dataset.md): reading it,
its regimes, and scoring the registered CoR models against it.

    from corlab import dataset
    table = dataset.read("data/fe_restitution/dataset.csv")       # included rows only
    scores = dataset.score_models(table)                          # every registered model

All quantities SI; errors are relative to the FE value: (e_model - e_FE) / e_FE.
"""
# SPDX-License-Identifier: BSD-3-Clause
import math
import warnings

import numpy as np

from . import _core

#: Regimes by v / v_y (first yield of the pair), upper bounds. Near yield the plastic zone is
#: small and subsurface; by ~300 v_y (interference ~110 x the critical one, Jackson & Green
#: 2005's fully plastic limit, with delta ~ v^(4/5)) the contact is fully plastic.
REGIMES = (("near-yield", 3.0), ("elastic-plastic", 300.0), ("fully plastic", math.inf))

#: The pair dataset's corners, held out of corlab2026p's fit (issue 26): (column, rows above
#: this value [-]).
PAIR_CORNERS = (("modulus_ratio", 10.0), ("density_ratio", 5.0))
#: The design box (_core.dataset_box) each of corlab's own models was fitted over.
FITTED_BOX = {"corlab2026": "flat", "corlab2026p": "pairs"}
#: Perfect plasticity for the analytic models' own box: H / E below this [-].
PERFECTLY_PLASTIC = 0.005


def read(path, included_only=True):
    """dataset.csv as a dict of numpy arrays (numbers) and lists (text columns); with
    `included_only`, the rows of the fitting set only."""
    table = _core.read_results(str(path))
    if included_only:
        keep = np.array([flag == "true" for flag in table["included"]])
        table = {k: (v[keep] if isinstance(v, np.ndarray) else [x for x, f in zip(v, keep) if f])
                 for k, v in table.items()}
    return table


def regime(velocity_ratio):
    """Regime names of v / v_y values (numpy array in, list out)."""
    out = []
    for x in np.atleast_1d(velocity_ratio):
        out.append(next(name for name, upper in REGIMES if x <= upper))
    return out


def material_specs(table, i, reduced=False):
    """The sphere and substrate of row i as corlab material specs. reduced: for a row of a pair
    dataset, the sphere of the pair's density rho* (effective_density) that gives the pair's
    Hertz impact on a flat of the other body, which is how a sphere-on-flat model is scored on
    two spheres (R* and m*; the models depend on the radius only through v / v_y)."""
    def spec(body):
        rho = table[body + "_rho"][i]
        if reduced and body == "sphere" and "effective_density" in table:
            rho = table["effective_density"][i]
        text = (f"E={table[body + '_E'][i]!r},nu={table[body + '_nu'][i]!r},"
                f"rho={rho!r}")
        sy = table[body + "_sigma_y"][i]
        if math.isfinite(sy):
            text += f",sy={sy!r},H={table[body + '_H'][i]!r}"
        return text
    return spec("sphere"), spec("substrate")


def predict_rows(model, spheres, substrates, velocities, radius_ratios=None):
    """e of `model` for each (sphere spec, substrate spec, v, R1/R2: 0 or None a flat) (nan
    where it cannot be evaluated); unverified models and calibration warnings are scored all the
    same."""
    out = np.full(len(velocities), np.nan)
    if radius_ratios is None:
        radius_ratios = np.zeros(len(velocities))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        for i, (sphere, substrate, v, r) in enumerate(
                zip(spheres, substrates, velocities, radius_ratios)):
            try:
                out[i] = _core.predict(model, sphere, substrate, float(v),
                                       radius_ratio=float(r))
            except ValueError:
                pass
    return out


def predictions(table, model):
    """e of `model` at every row of a dataset table (nan where it cannot be evaluated); a pair
    row with its radius_ratio (a sphere-on-flat model sees the reduced sphere of material_specs,
    corlab2026p the pair)."""
    specs = [material_specs(table, i) for i in range(len(table["e"]))]
    return predict_rows(model, [s[0] for s in specs], [s[1] for s in specs], table["velocity"],
                        table.get("radius_ratio"))


def in_box(table, box):
    """Rows of a dataset table inside a design box (_core.dataset_box) in the ratios that tell
    the datasets apart: the modulus and density ratios and, for a box of flats only, a flat."""
    def inside(column, bounds, rtol=1e-9):
        low, high = bounds
        return (table[column] >= low * (1 - rtol)) & (table[column] <= high * (1 + rtol))
    ok = inside("modulus_ratio", box["modulus_ratio"])
    ok &= inside("density_ratio", box["density_ratio"])
    if box["flat_fraction"] >= 1.0 and "radius_ratio" in table:
        ok &= table["radius_ratio"] == 0.0
    return ok


def in_model_box(table, info):
    """Rows inside a model's own validity: for corlab's own model (status verified-dataset) the
    flat dataset's box it was fitted to; else an elastic sphere, a perfectly plastic substrate
    (H/E < PERFECTLY_PLASTIC) and, when the model has one, its calibration box in (k1, k2)."""
    if info["status"] == "verified-dataset":
        return in_box(table, _core.dataset_box(FITTED_BOX[info["name"]]))
    ok = ~np.isfinite(table["sphere_sigma_y"])
    ok &= table["hardening_ratio_substrate"] < PERFECTLY_PLASTIC
    box = info.get("calibrated")
    if box:
        ok &= (table["k1"] >= box["k1_min"]) & (table["k1"] <= box["k1_max"])
        ok &= (table["k2"] >= box["k2_min"]) & (table["k2"] <= box["k2_max"])
    return ok


def score(table, e_model, mask=None):
    """Relative-error statistics (n, rms, worst, bias: corlab.relative_error_stats) of
    predictions e_model against the FE e, overall and per regime."""
    e = table["e"]
    mask = np.ones(e.size, dtype=bool) if mask is None else mask
    names = np.array(regime(table["velocity_ratio"]))
    out = {"all": _core.relative_error_stats(e_model[mask], e[mask])}
    for name, _ in REGIMES:
        rows = mask & (names == name)
        out[name] = _core.relative_error_stats(e_model[rows], e[rows])
    return out


def corner_masks(table):
    """{name: rows} of the pair dataset's corners (PAIR_CORNERS); none for the flat dataset."""
    if "radius_ratio" not in table:
        return {}
    return {f"{column} > {bound:g}": table[column] > bound for column, bound in PAIR_CORNERS}


def score_models(table, names=None):
    """{model: {"all cases": score, "own box": score, "corners": {name: score}}} for the
    registered models (or `names`); corners only on a pair dataset (corner_masks)."""
    infos = {m["name"]: m for m in _core.models()}
    corners = corner_masks(table)
    out = {}
    for name in names or list(infos):
        e = predictions(table, name)
        own = in_model_box(table, infos[name])
        out[name] = {"all cases": score(table, e), "own box": score(table, e, own)}
        if corners:
            out[name]["corners"] = {c: score(table, e, rows) for c, rows in corners.items()}
    return out


def error_figure(table, path):
    """Relative error of every registered model against k1 and k2 (one row of panels each)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    names = [m["name"] for m in _core.models()]
    fig, axes = plt.subplots(len(names), 2, figsize=(8, 1.6 * len(names)), sharex="col",
                             sharey=True, squeeze=False)
    for row, name in enumerate(names):
        rel = _core.relative_errors(predictions(table, name), table["e"])
        for col, key in enumerate(("k1", "k2")):
            ax = axes[row][col]
            ax.axhline(0.0, color="0.6", lw=0.8)
            ax.scatter(table[key], 100.0 * rel, s=5, c=np.log10(table["velocity_ratio"]),
                       cmap="viridis")
            ax.set_xscale("log")
            ax.set_ylim(-60, 60)
            if col == 0:
                ax.set_ylabel(f"{name}\n% error", fontsize=7)
        axes[row][0].tick_params(labelsize=7)
        axes[row][1].tick_params(labelsize=7)
    axes[-1][0].set_xlabel("k1 = E*/(rho v^2)")
    axes[-1][1].set_xlabel("k2 = sigma_y/E*")
    fig.suptitle("Error of each model against corlab's FE dataset (colour: log10 v/v_y)",
                 fontsize=9)
    fig.tight_layout(rect=(0, 0, 1, 0.985))
    fig.savefig(path, dpi=110)
    plt.close(fig)


def markdown_table(scores):
    """Markdown rows: each model's RMS / worst / bias on all cases and per regime, and on its own
    box (percent of e)."""
    def cell(s):
        if s["n"] == 0:
            return "-"
        return f"{100 * s['rms']:.1f} / {100 * s['worst']:+.0f} / {100 * s['bias']:+.1f}"
    regimes = [name for name, _ in REGIMES]
    corners = list(next(iter(scores.values())).get("corners", {}))
    lines = ["| model | all cases (n) | " + " | ".join(regimes) + " | own box (n) |"
             + "".join(f" {c} (n) |" for c in corners),
             "|---" * (3 + len(regimes) + len(corners)) + "|"]
    for name, s in scores.items():
        a, own = s["all cases"], s["own box"]["all"]
        lines.append(f"| `{name}` | {cell(a['all'])} ({a['all']['n']}) | "
                     + " | ".join(cell(a[r]) for r in regimes)
                     + f" | {cell(own)} ({own['n']}) |"
                     + "".join(f" {cell(s['corners'][c]['all'])} ({s['corners'][c]['all']['n']}) |"
                               for c in corners))
    return "\n".join(lines) + "\n"


def main(argv=None):
    import argparse
    import json
    parser = argparse.ArgumentParser(
        description="Scores every registered CoR model against the FE dataset")
    parser.add_argument("dataset", help="dataset.csv (corlab dataset export)")
    parser.add_argument("--out", required=True, help="model_scores.json to write")
    parser.add_argument("--figure", help="PNG of the errors against k1 and k2")
    parser.add_argument("--markdown", help="the scores as a Markdown table (for the README)")
    args = parser.parse_args(argv)
    table = read(args.dataset)
    scores = score_models(table)

    def safe(obj):
        if isinstance(obj, dict):
            return {k: safe(v) for k, v in obj.items()}
        return None if isinstance(obj, float) and not math.isfinite(obj) else obj
    with open(args.out, "w") as f:
        json.dump({"dataset": args.dataset, "rows": int(table["e"].size), "regimes": {
            name: upper if math.isfinite(upper) else None for name, upper in REGIMES},
            "scores": safe(scores)}, f, indent=2, sort_keys=True)
        f.write("\n")
    if args.figure:
        error_figure(table, args.figure)
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(markdown_table(scores))
    for name, s in scores.items():
        a = s["all cases"]["all"]
        print(f"{name:<15} RMS {a['rms']:.3f} worst {a['worst']:+.3f} bias {a['bias']:+.3f} "
              f"(n {a['n']}); own box n {s['own box']['all']['n']}")


if __name__ == "__main__":
    main()
