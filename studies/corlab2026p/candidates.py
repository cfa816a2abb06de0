"""Candidate forms of corlab's CoR model over particle pairs (issue 26, item 5), scored with
model_fit.py's protocol on the union of the flat dataset and a pair dataset: a random 20 % by
case id and the corners E_sphere/E_other > 10 and rho_sphere/rho_other > 5 held out, the rest
fitted (scipy least_squares on relative errors, model_fit.py's start values and bounds).

An exploration tool: the kernel is re-implemented in numpy with switches for each candidate term
(the shipped kernel is the C++ one, corlab2026_restitution; `--check` compares the two at the
shipped form). Prints a Markdown table: RMS / worst / bias of the relative error in %.

    PYTHONPATH=build/python /usr/bin/python3 studies/corlab2026p/candidates.py \\
        data/fe_restitution_pairs/dataset.csv [--cells] [--check]
"""
# SPDX-License-Identifier: BSD-3-Clause
import argparse
import pathlib

import numpy as np
from scipy.optimize import least_squares

import corlab
from corlab import dataset, model_fit

ROOT = pathlib.Path(__file__).resolve().parents[2]
#: Issue 26's user case: sphere, flat, v [m/s], FE e.
USER_CASE = (dict(E1=600e9, nu1=0.24, rho1=15000.0, sy1=np.inf, H1=0.0, E2=70e9, nu2=0.33,
                  rho2=2700.0, sy2=100e6, H2=0.0), 20.0, 0.1486)


def c_nu(nu):
    """Jackson & Green's first-yield factor C(nu) [-]."""
    return 1.295 * np.exp(0.736 * nu)


def j_ratio(a_over_r):
    """Jackson & Green's flattened-sphere hardness over its a/R -> 0 value [-]."""
    with np.errstate(divide="ignore", over="ignore"):
        return np.where(a_over_r > 0, 1 - np.exp(-0.82 * np.maximum(a_over_r, 1e-300) ** -0.7),
                        1.0)


def thornton(r):
    r = np.minimum(r, 1.0)
    return (np.sqrt(6 * np.sqrt(3) / 5) * np.sqrt(1 - r ** 2 / 6)
            * (r / (r + 2 * np.sqrt(6 / 5 - r ** 2 / 5))) ** 0.25)


def flow(x, h, k):
    return (1 + k * h * x ** 0.4) / (1 + k * h)


def bodies(table):
    """Both bodies' constants (dict of arrays: E1, nu1, rho1, sy1, H1, E2, ...) [SI]."""
    out = {}
    for i, b in ((1, "sphere"), (2, "substrate")):
        for key, col in (("E", "E"), ("nu", "nu"), ("rho", "rho"), ("sy", "sigma_y"), ("H", "H")):
            out[f"{key}{i}"] = np.asarray(table[f"{b}_{col}"], float)
    return out


def inputs(b, v, r):
    """The model's inputs (numpy), rho* of the pair, both densities and r = R1/R2."""
    es = 1 / ((1 - b["nu1"] ** 2) / b["E1"] + (1 - b["nu2"] ** 2) / b["E2"])
    p1, p2 = c_nu(b["nu1"]) * b["sy1"], c_nu(b["nu2"]) * b["sy2"]
    sphere_first = p1 < p2
    py, po = np.minimum(p1, p2), np.maximum(p1, p2)
    rho_star = b["rho1"] * (1 + r) ** 3 / (1 + b["rho1"] / b["rho2"] * r ** 3)
    vy = np.sqrt(np.pi ** 4 / 40 * py ** 5 / (es ** 4 * rho_star))
    with np.errstate(invalid="ignore"):
        vyo = np.where(np.isfinite(po), np.sqrt(np.pi ** 4 / 40 * po ** 5 / (es ** 4 * rho_star)),
                       np.inf)
    h_other = np.where(sphere_first, b["H2"], b["H1"])
    return dict(x=v / vy, xo=v / vyo, hf=np.where(sphere_first, b["H1"], b["H2"]) / es,
                ho=np.where(np.isfinite(h_other), h_other, 0.0) / es, dy=rho_star * vy ** 2 / py,
                ls=(1 - b["nu1"] ** 2) / b["E1"] * es, ay=np.pi * py / (2 * es),
                nuf=np.where(sphere_first, b["nu1"], b["nu2"]), other=~sphere_first, r=r,
                rho_star=rho_star, rho_w=np.where(sphere_first, b["rho1"], b["rho2"]),
                rho_o=np.where(sphere_first, b["rho2"], b["rho1"]))


def pressure(x, h, cap, c1, k):
    c1 = np.minimum(c1, 0.39)
    kh = k["kappa_cavity"] * h
    xx = np.maximum(x, 1.0)
    cavity = 1 + c1 * np.log(xx) + (1 - c1 / 0.4) * kh / (1 + kh) * (xx ** 0.4 - 1)
    return np.where(x > 1, np.minimum(cavity, cap * flow(xx, h, k["kappa"])), 1.0)


def factor(x, phi):
    return np.where(x > 1, thornton(phi ** 2.5 / np.maximum(x, 1.0)), 1.0)


def damage_scale(i, k, form):
    """The damage number's density over rho* (and the candidates' extra factors)."""
    dens = form.get("density", "star")
    f = {"star": 1.0, "first": i["rho_w"] / i["rho_star"],
         "mix": (i["rho_w"] / i["rho_star"]) ** k.get("dens_mix", 1.0),
         "ab": (i["rho_w"] / i["rho_star"]) ** k.get("da", 1.0)
         * (i["rho_o"] / i["rho_star"]) ** k.get("db", 0.0),
         "sum": (i["rho_w"] + k.get("beta", 0.0) * i["rho_star"])
         / ((1 + k.get("beta", 0.0)) * i["rho_star"])}[dens]
    if form.get("curvature"):
        f = f * (1 + i["r"]) ** -k["curv"]
    if form.get("poisson_damage"):
        f = f * (c_nu(0.3) / c_nu(i["nuf"])) ** k["dpois"]
    return f


def model(i, k, form):
    """e of a candidate `form` (dict of switches) with coefficients k (numpy)."""
    x, other = i["x"], i["other"]
    sf = np.where(other, 1 - i["ls"], i["ls"])
    xw = 1 + np.exp(k["compliance_first"] * (sf - 0.5)) * (x - 1)
    n = c_nu(0.3) / c_nu(i["nuf"])
    share = (np.where(other, i["r"], 1.0) / (1 + i["r"]) if form.get("flatten_pairs")
             else np.where(other, 0.0, 1.0))
    jw = j_ratio(k["flattening"] * i["ay"] * share * xw ** 0.4)
    cap_scale = n ** k["pois_cap"] if form.get("poisson_cap") else n
    hs = (2 * sf) ** k["hshare"] if form.get("hardening_share") else 1.0
    ho_s = (2 * (1 - sf)) ** k["hshare"] if form.get("hardening_share") else 1.0
    phiw = pressure(xw, i["hf"] * hs, np.maximum(1.0, cap_scale * k["phi_max"] * jw),
                    k["c1"] * n, k)
    xo = phiw ** 2.5 * i["xo"] / x
    wo = (np.where(other, k["gamma_sphere"], k["gamma_substrate"])
          * np.exp(k["compliance_other"] * (1 - 2 * sf)))
    dmg = damage_scale(i, k, form) * i["dy"] * (x * x - 1) / flow(x, i["hf"] * hs, k["kappa"])
    tw = factor(xw, phiw)
    if form.get("first_weight"):
        tw = tw ** np.exp(k["tsh"] * (sf - 0.5))
    to = factor(xo, pressure(xo, i["ho"] * ho_s, k["phi_max"], k["c1"], k))
    return np.where(x > 1, tw * to ** wo / (1 + k["b"] * np.maximum(dmg, 0) ** k["c"]), 1.0)


#: (name, switches, extra coefficients (name, start, low, high)).
CANDIDATES = (
    ("corlab2026 refitted on the union, rho*", {}, ()),
    ("A: damage on the first-yielding body's density", {"density": "first"}, ()),
    ("B = corlab2026p: A + a curved first body flattened (J at a/R_w)",
     {"density": "first", "flatten_pairs": True}, ()),
    ("B + damage density rho*^(1-a) rho_w^a", {"density": "mix", "flatten_pairs": True},
     (("dens_mix", 0.5, -1.0, 2.0),)),
    ("B + damage density rho_w^a rho_o^b / rho*^(a+b-1)", {"density": "ab", "flatten_pairs": True},
     (("da", 1.0, -2.0, 3.0), ("db", 0.0, -2.0, 3.0))),
    ("B + damage density (rho_w + beta rho*) / (1 + beta)",
     {"density": "sum", "flatten_pairs": True}, (("beta", 0.1, 0.0, 10.0),)),
    ("B + damage x (1+R1/R2)^-m", {"density": "first", "flatten_pairs": True, "curvature": True},
     (("curv", 1.0, -2.0, 8.0),)),
    ("B + hardening h (2 l)^p", {"density": "first", "flatten_pairs": True,
                                 "hardening_share": True}, (("hshare", 1.0, -1.0, 4.0),)),
    ("B + Poisson cap n^p", {"density": "first", "flatten_pairs": True, "poisson_cap": True},
     (("pois_cap", 1.0, -5.0, 10.0),)),
    ("B + Poisson cap n^p + damage n^q", {"density": "first", "flatten_pairs": True,
                                          "poisson_cap": True, "poisson_damage": True},
     (("pois_cap", 1.0, -5.0, 10.0), ("dpois", 0.0, -10.0, 10.0))),
    ("B + first body's Thornton weight exp(t (l_w - 1/2))",
     {"density": "first", "flatten_pairs": True, "first_weight": True}, (("tsh", 0.0, -3.0, 3.0),)),
)


def fit(i, e, mask, form, extra):
    params = list(model_fit.PARAMETERS) + list(extra)
    sub = {key: (v[mask] if isinstance(v, np.ndarray) else v) for key, v in i.items()}

    def residuals(p):
        k = dict(zip((q[0] for q in params), p))
        return (model(sub, k, form) - e[mask]) / e[mask]
    res = least_squares(residuals, [q[1] for q in params],
                        bounds=([q[2] for q in params], [q[3] for q in params]), x_scale="jac")
    return dict(zip((q[0] for q in params), res.x)), len(params)


def cell(rel, mask):
    if not mask.any():
        return "-"
    r = rel[mask]
    return f"{100 * np.sqrt(np.mean(r ** 2)):.2f} / {100 * r[np.argmax(abs(r))]:+.1f} / " \
           f"{100 * r.mean():+.2f}"


def load(pairs_path):
    table = model_fit.read_union([ROOT / "data" / "fe_restitution" / "dataset.csv", pairs_path])
    b = bodies(table)
    i = inputs(b, np.asarray(table["velocity"], float), np.asarray(table["radius_ratio"], float))
    n_flat = len(dataset.read(ROOT / "data" / "fe_restitution" / "dataset.csv")["e"])
    return table, i, np.arange(len(table["e"])) >= n_flat


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("pairs", help="the pair dataset.csv (corlab dataset export)")
    parser.add_argument("--cells", action="store_true",
                        help="B's largest biases over tertile cells of two inputs (pair rows, "
                             "fully plastic)")
    parser.add_argument("--check", action="store_true",
                        help="B against the C++ kernel at corlab2026p's fitted coefficients")
    args = parser.parse_args()
    table, i, pairs = load(args.pairs)
    e = np.asarray(table["e"], float)
    train, random_out, _ = model_fit.split(table, "corlab2026p")
    corner = model_fit.corners(table, "corlab2026p")
    wc_body, wc_v, wc_e = USER_CASE
    wc = inputs({key: np.array([val]) for key, val in wc_body.items()}, wc_v, np.array([0.0]))
    flat = np.asarray(table["radius_ratio"], float) == 0
    if args.check:
        k = corlab.corlab2026p_fitted()
        ours = model(i, k, CANDIDATES[2][1])
        core = model_fit.predict(model_fit.model_inputs(table, "corlab2026p"), k)
        print(f"max |numpy - C++| / e: {np.max(np.abs(ours - core) / core):.2e}")
    x = i["x"]
    fp, ep = x > 300, (x > 3) & (x <= 300)
    print("| form | coefficients | fitted | random 20 % | corner E>10 | corner rho>5 | random EP "
          "| random FP | flat dataset | pair flats | pair spheres | user case e (FE 0.1486) | "
          "extra |\n" + "|---" * 13 + "|")
    for name, form, extra in (("corlab2026 as shipped at rho* (not refitted)", None, ()),
                              *CANDIDATES):
        if form is None:
            form, k, n = {}, corlab.corlab2026_fitted(), 0
        else:
            k, n = fit(i, e, train, form, extra)
        rel = (model(i, k, form) - e) / e
        e_wc = model(wc, k, form)[0]
        print(f"| {name} | {n} | {cell(rel, train)} | {cell(rel, random_out)} | "
              f"{cell(rel, list(corner.values())[0])} | {cell(rel, list(corner.values())[1])} | "
              f"{cell(rel, random_out & ep)} | {cell(rel, random_out & fp)} | {cell(rel, ~pairs)} "
              f"| {cell(rel, pairs & flat)} | {cell(rel, pairs & ~flat)} | {e_wc:.4f} "
              f"({100 * (e_wc / wc_e - 1):+.1f} %) | "
              + ", ".join(f"{q[0]} = {k[q[0]]:.3f}" for q in extra) + " |")
        if args.cells and name.startswith("B ="):
            cells(i, rel, pairs & fp, table)


def cells(i, rel, m0, table):
    """Prints the 8 largest |bias| among tertile cells (>= 10 rows) of two inputs."""
    sf = np.where(i["other"], 1 - i["ls"], i["ls"])
    feats = {"ln E ratio": np.log(table["modulus_ratio"]), "ln rho ratio":
             np.log(table["density_ratio"]), "R1/R2": i["r"], "h_w": i["hf"], "share l_w": sf,
             "ln x": np.log(i["x"]), "nu_w": i["nuf"], "h_o": i["ho"],
             "ln damage": np.log(i["dy"] * i["x"] ** 2 * i["rho_w"] / i["rho_star"]),
             "sphere yields first": (~i["other"]) * 1.0}
    found = []
    names = list(feats)
    for a_i, a in enumerate(names):
        for b in names[a_i + 1:]:
            qa, qb = (np.quantile(feats[f][m0], [0, 1 / 3, 2 / 3, 1]) for f in (a, b))
            for ia in range(3):
                for ib in range(3):
                    m = (m0 & (feats[a] >= qa[ia]) & (feats[a] <= qa[ia + 1])
                         & (feats[b] >= qb[ib]) & (feats[b] <= qb[ib + 1]))
                    if m.sum() >= 10:
                        found.append((abs(rel[m].mean()), f"{a} {ia + 1}/3, {b} {ib + 1}/3",
                                      int(m.sum()), cell(rel, m)))
    for _, where, n, text in sorted(found, reverse=True)[:8]:
        print(f"    cell {where} (n {n}): {text}")


if __name__ == "__main__":
    main()
