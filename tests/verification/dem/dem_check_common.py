"""Shared helpers of the DEM real-code checks (dem_{lammps,liggghts,yade}_check.py) and of
scripts/dem_time_step.py: exports, drop tests (a sphere on the wall, two spheres head-on, each of
its own type's radius and density, an oblique frictionless impact) in Debian's codes, and the
cases checked."""
# SPDX-License-Identifier: BSD-3-Clause
import json
import math
import os
import subprocess

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "data", "dem")
FE_TABLE = os.path.join(DATA, "fe_alumina_aluminium.csv")
# corlab's FE e(v) of the 2 mm glass sphere on a free 5 mm copper sphere (its .toml says how)
FE_PAIR_TABLE = os.path.join(DATA, "fe_glass_copper_spheres.csv")
GLASS = "glass=E=63e9,nu=0.22,rho=2500"
COPPER = "copper=E=120e9,nu=0.34,rho=8900,sy=200e6"

# The three pairs of issue 30, each with its e(v) range:
#   glass on copper, corlab2026 (and the elastic glass-glass pair, e = 1 by --pair);
#   alumina on aluminium alloy, thornton1997 (and corlab's FE e(v) of it);
#   aluminium spheres head-on, thornton1997 (a plastic particle-particle pair);
# and a pair of unequal types (issue 26): a 2 mm glass and a 5 mm copper sphere head-on, with
#   corlab2026 and with corlab's FE e(v) of that pair.
EV_CASES = (
    ("glass_copper", ["--type", GLASS + ":0.002", "--wall", COPPER, "--model", "corlab2026",
                      "--pair", "glass/glass=1", "--v-min", "0.5", "--v-max", "4"],
     (("1-wall", "wall"), ("1-1", "pair"))),
    ("alumina_aluminium", ["--type", "alumina_ma2023:0.005", "--wall", "aluminium_ma2023",
                           "--wall-only", "--model", "thornton1997", "--v-min", "0.3",
                           "--v-max", "3"], (("1-wall", "wall"),)),
    ("alumina_fe_table", ["--type", "alumina_ma2023:0.005", "--wall", "aluminium_ma2023",
                          "--wall-only", "--table", FE_TABLE, "--v-min", "0.3", "--v-max", "3"],
     (("1-wall", "wall"),)),
    ("aluminium_spheres", ["--type", "aluminium_ma2023:0.005", "--model", "thornton1997",
                           "--v-min", "0.3", "--v-max", "3"], (("1-1", "pair"),)),
    # two types of another radius, material and density: the 1-2 pair must run its own law
    ("glass_copper_spheres", ["--type", GLASS + ":0.002", "--type", COPPER + ":0.005",
                              "--model", "corlab2026", "--pair", "glass/glass=1",
                              "--v-min", "0.5", "--v-max", "4"], (("1-2", "pair"),)),
    # the same two types with corlab's FE e(v) of that pair (--pair-table) for the 1-2 pair
    ("glass_copper_fe_pair", ["--type", GLASS + ":0.002", "--type", COPPER + ":0.005",
                              "--model", "corlab2026", "--pair", "glass/glass=1",
                              "--pair-table", "glass/copper=" + FE_PAIR_TABLE,
                              "--v-min", "0.5", "--v-max", "4"], (("1-2", "pair"),)),
)
CONSTANT_TARGETS = (0.3, 0.9)
# Where in a step a drop test's contact starts (fraction of a step): the e of a code at a given
# step depends on it (LAMMPS tsuji, e = 0.5 at 115 steps per contact: 3.3e-4 off at 0, 1.6e-3 at
# 0.75); the checks take mid-step, scripts/dem_time_step.py the worst of several.
PHASE = 0.5


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


class Drop:
    """One drop test of a pair of the export `data` (its dem_export.json): a particle of the
    pair's first type at normal speed v [m/s] (tangential vt [m/s], frictionless) on the wall, or
    head-on along x against a particle of its second type (each type's own radius [m] and density
    [kg/m^3], approach speed v, zero total momentum); dt [s] the step. The export's R* and m* must
    be those of the two particles."""

    def __init__(self, data, pair, geometry, v, dt, vt=0.0, phase=PHASE):
        self.pair, self.geometry, self.v, self.dt, self.vt = pair, geometry, v, dt, vt
        self.ntypes = len(data["types"])
        ids = [pair["type_i"]] + ([pair["type_j"]] if geometry == "pair" else [])
        self.types = ids
        self.radii = [data["types"][t - 1]["radius_m"] for t in ids]
        self.densities = [data["types"][t - 1]["density_kg_per_m3"] for t in ids]
        masses = [4.0 / 3.0 * math.pi * r ** 3 * rho for r, rho in zip(self.radii, self.densities)]
        if geometry == "pair":
            r_star = self.radii[0] * self.radii[1] / (self.radii[0] + self.radii[1])
            m_star = masses[0] * masses[1] / (masses[0] + masses[1])
            # velocities [m/s] along x: particle 1 at -x moving +x, zero total momentum
            self.velocities = [v * masses[1] / sum(masses), -v * masses[0] / sum(masses)]
        else:
            r_star, m_star = self.radii[0], masses[0]
        for name, mine, key in (("R*", r_star, "effective_radius_m"),
                                ("m*", m_star, "effective_mass_kg")):
            if abs(mine - pair[key]) > 1e-12 * mine:
                raise AssertionError("%s %s: dem_export.json has %s = %.17g, the particles %.17g"
                                     % (pair["pair"], pair["label"], name, pair[key], mine))
        self.radius = max(self.radii)  # sizes the box
        tc = contact_time(pair, v)
        self.gap = (20 + phase) * v * dt  # contact starts `phase` of a step after step 20
        self.steps = int((self.gap / v + 2.0 * tc) / dt)


def law_e(pair, key, i):
    """e [-] of the law that fragment `key` runs for the pair, at its i-th fit speed (ODE)."""
    route = pair["delivered"][key]["route"]
    if pair["delivered"][key]["law_e"]:
        return pair["delivered"][key]["law_e"][i]
    if "viscoelastic" in route:
        return pair["viscoelastic_damping_N_s_per_m1.5"]["fitted"][i]
    if "thornton_ning" in route:
        return pair["liggghts_as_written"]["fitted"][i]
    if "closest constant" in route:
        return pair["best_constant_e"]["parameter"]
    return pair["best_constant_e"]["target"][i]


def case_rows(corlab, work, code, simulate, fragments, time_step_key, steps_per_contact=None,
              phase=PHASE, cases=None):
    """Runs every case through `simulate(out, fragment, drop)` (returns e) for each fragment
    (file name, key of "delivered" in dem_export.json), at the export's recommended step (or,
    given steps_per_contact, at the shortest contact time at v_max over it); checks |e - e_law|
    <= the time-step error and |e - target| <= the stated max |de| of that fragment + the
    time-step error. `phase`: where in a step the contacts start; `cases`: names of EV_CASES
    to run (None: all). Returns (report rows, failures, worst |e - e_law| per law)."""
    rows, failures, worst = [], 0, {}

    def step(data, key):
        if steps_per_contact is None:
            return data["time_step_s"][time_step_key(key)]
        return min(p["contact_time_at_v_max_s"] for p in data["pairs"]) / steps_per_contact

    def check(label, e, target, law, stated, promise, law_name):
        nonlocal failures
        worst[law_name] = max(worst.get(law_name, 0.0), abs(e - law))
        ok = abs(e - law) <= promise and abs(e - target) <= stated + promise
        failures += not ok
        rows.append("%-52s e=%.6f law=%.6f target=%.6f |e-law|=%.1e (<= %.0e) |e-target|=%.2e "
                    "(<= stated %.2e + %.0e) %s" % (label, e, law, target, abs(e - law), promise,
                                                    abs(e - target), stated, promise,
                                                    "ok" if ok else "FAIL"))

    for target in CONSTANT_TARGETS:
        out = os.path.join(work, "const_%g" % target)
        data = export(corlab, out, ["--type", "steel_ma2023:0.005", "--wall", "steel_ma2023",
                                    "--restitution", str(target)])
        pairs = {p["pair"]: p for p in data["pairs"]}
        for fragment, key in fragments[:1]:
            dt = step(data, key)
            for geometry, pair_key in (("wall", "1-wall"), ("pair", "1-1")):
                for v in (0.1, 10.0):
                    pair = pairs[pair_key]
                    e = simulate(out, fragment, Drop(data, pair, geometry, v, dt, phase=phase))
                    check("%s e=%.1f %s v=%g" % (fragment, target, geometry, v), e, target,
                          law_e(pair, key, 0), pair["delivered"][key]["max_abs_error"],
                          data["time_step_error"], pair["delivered"][key]["law"])
    for name, args, checked in EV_CASES:
        if cases is not None and name not in cases:
            continue
        out = os.path.join(work, name)
        data = export(corlab, out, args)
        pairs = {p["pair"]: p for p in data["pairs"]}
        for fragment, key in fragments:
            dt = step(data, key)
            for pair_key, geometry in checked:
                pair = pairs[pair_key]
                fit = pair["best_constant_e"]
                last = len(fit["velocities"]) - 1
                picks = (0, last // 2, last)
                for i in picks:
                    v, target = fit["velocities"][i], fit["target"][i]
                    e = simulate(out, fragment, Drop(data, pair, geometry, v, dt, phase=phase))
                    check("%s %s %s v=%.3g" % (fragment, name, pair["label"], v), e, target,
                          law_e(pair, key, i), pair["delivered"][key]["max_abs_error"],
                          data["time_step_error"], pair["delivered"][key]["law"])
    return rows, failures, worst


def finish(name, rows, failures, report):
    text = "\n".join(rows) + "\n"
    print(text, end="")
    if report:
        with open(report, "w") as f:
            f.write(text)
    print("%s: %d failure(s)" % (name, failures))
    return 1 if failures else 0
