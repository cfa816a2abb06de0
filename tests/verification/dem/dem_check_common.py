"""Shared helpers of the DEM real-code checks (dem_lammps_check.py, dem_liggghts_check.py)."""
import json
import os
import subprocess

STEPS_PER_CONTACT = 4000
FE_TABLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "data", "dem",
                        "fe_alumina_aluminium.csv")


def run(cmd, **kw):
    return subprocess.run(cmd, check=True, capture_output=True, text=True, **kw)


def export(corlab, out, args):
    """Runs `corlab dem` into `out` and returns its dem_export.json."""
    run([corlab, "dem", "--out", out, *args])
    with open(os.path.join(out, "dem_export.json")) as f:
        return json.load(f)


def contact_time(pair, v):
    """Hertz contact time 2.9432 delta_max / v [s] of the pair at impact speed v."""
    k, m = pair["hertz_stiffness_N_per_m1.5"], pair["effective_mass_kg"]
    delta = (5.0 * m * v * v / (4.0 * k)) ** 0.4
    return 2.9432 * delta / v


def parse_e(out):
    for line in out.splitlines():
        if line.startswith("CORLAB_E"):
            return float(line.split()[1])
    raise RuntimeError("no CORLAB_E in the code's output:\n" + out[-2000:])


def check_cases(simulate, corlab, work, fit_key, radius=0.005, exact=False):
    """Runs the constant-e and e(v) cases; `simulate(out, pair, density, v, geometry)` returns the
    code's measured e. exact=True: the code's e(v) route is exact (YADE hook), so e must be within
    1 % of the target itself. Returns (report rows, number of failures)."""
    import math
    rows, failures = [], 0
    volume = 4.0 / 3.0 * math.pi * radius ** 3
    for target in (0.3, 0.5, 0.7, 0.9):
        out = os.path.join(work, "const_%g" % target)
        data = export(corlab, out, ["--type", "steel_ma2023:%g" % radius, "--wall", "steel_ma2023",
                                    "--restitution", str(target)])
        pairs = {p["pair"]: p for p in data["pairs"]}
        rho = pairs["1-wall"]["effective_mass_kg"] / volume
        for geometry, key in (("wall", "1-wall"), ("pair", "1-1")):
            for v in (0.1, 1.0, 10.0):
                e = simulate(out, pairs[key], rho, v, geometry)
                err = abs(e - target) / target
                ok = err <= 0.01
                failures += not ok
                rows.append("constant  %-5s e=%.2f v=%6.2f m/s  measured e=%.5f  rel.err=%.2e %s"
                            % (geometry, target, v, e, err, "ok" if ok else "FAIL"))
    # e(v) of the paper pair alumina on aluminium alloy: thornton1997 (wall; and aluminium spheres
    # head-on) and corlab's own FE e(v) (tests/data/dem/fe_alumina_aluminium.csv, sphere on wall).
    wall = ["--type", "alumina_ma2023:%g" % radius, "--wall", "aluminium_ma2023", "--wall-only"]
    cases = (("thornton1997", "wall", wall + ["--model", "thornton1997"], "1-wall"),
             ("thornton1997", "pair",
              ["--type", "aluminium_ma2023:%g" % radius, "--model", "thornton1997"], "1-1"),
             ("FE table", "wall", wall + ["--table", FE_TABLE], "1-wall"))
    for source, geometry, args, key in cases:
        out = os.path.join(work, "ev_%s_%s" % (source.split()[0], geometry))
        data = export(corlab, out, args + ["--v-min", "0.3", "--v-max", "3"])
        pair = {p["pair"]: p for p in data["pairs"]}[key]
        fit = pair[fit_key]
        rho = pair["effective_mass_kg"] * (1 if geometry == "wall" else 2) / volume
        for i in (0, len(fit["velocities"]) // 2, len(fit["velocities"]) - 1):
            v, law_e, target = fit["velocities"][i], fit["fitted"][i], fit["target"][i]
            e = simulate(out, pair, rho, v, geometry)
            if exact:
                law_e = target
            err_law = abs(e - law_e) / law_e
            tolerance = (0.0 if exact else fit["max_abs_error"]) + 0.01 * target
            ok = err_law <= 0.01 and abs(e - target) <= tolerance
            failures += not ok
            rows.append("e(v)      %-5s v=%6.3f m/s  target(%s)=%.5f  fitted law=%.5f  "
                        "measured e=%.5f  "
                        "rel.err vs law=%.2e  |e-target|=%.3f (stated fit error %.3f) %s"
                        % (geometry, v, source, target, law_e, e, err_law, abs(e - target),
                           0.0 if exact else fit["max_abs_error"],
                           "ok" if ok else "FAIL"))
    return rows, failures


def finish(name, rows, failures, report):
    text = "\n".join(rows) + "\n"
    print(text, end="")
    if report:
        with open(report, "w") as f:
            f.write(text)
    print("%s: %d failure(s)" % (name, failures))
    return 1 if failures else 0
