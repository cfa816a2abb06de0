"""The 3-D model's error bars on the six stored seeded samples (data/error_bar_coverage/
3d_seed<SEED>/runs.csv, made by scripts/error_bar_coverage_3d.py; 20261129-31 with 0.9.0's
contact, 20261132 with the friction at the contact points that followed it, 20261133-34 with
0.11.0), re-scored by the script's own score() with corlab's compiled estimators (its
--score-only, no FE run): per quantity, the cases whose h / sqrt 2 value lies inside the bar and
the median relative bar over the median relative change, held at what they measured, for
corlab's bars and for issue 39's candidate scatter_3d on e_t and omega. Issue 39 asks >= 23 of 24
inside at a width <= 3: neither meets both on every sample (on the fifth, corlab's meet the
counts and omega's width; docs/theory/error_bars.md, "The 3-D model", says why). The live end-to-end
pair stays in C++ (tests/verification/error_bar_coverage_3d_test.cpp)."""
# SPDX-License-Identifier: BSD-3-Clause
import importlib.util
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
SPEC = importlib.util.spec_from_file_location("error_bar_coverage_3d",
                                              ROOT / "scripts" / "error_bar_coverage_3d.py")
coverage = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(coverage)

# Per sample, estimator and quantity: the fewest cases inside and the widest median bar / median
# change, as measured (the width 0.01 above it).
BOUNDS = {
    20261129: {"corlab": {"e_n": (23, 5.47), "e_t": (21, 1.86), "omega": (23, 2.18)},
               "scatter_3d": {"e_t": (23, 2.27), "omega": (23, 2.66)}},
    20261130: {"corlab": {"e_n": (23, 21.38), "e_t": (22, 3.24), "omega": (24, 3.16)},
               "scatter_3d": {"e_t": (24, 3.95), "omega": (24, 4.44)}},
    20261131: {"corlab": {"e_n": (22, 6.46), "e_t": (24, 4.02), "omega": (23, 3.31)},
               "scatter_3d": {"e_t": (24, 4.98), "omega": (23, 4.62)}},
    20261132: {"corlab": {"e_n": (24, 4.27), "e_t": (21, 8.85), "omega": (23, 4.0)},
               "scatter_3d": {"e_t": (23, 10.8), "omega": (23, 5.25)}},
    20261133: {"corlab": {"e_n": (23, 3.30), "e_t": (24, 3.29), "omega": (24, 2.90)},
               "scatter_3d": {"e_t": (24, 4.36), "omega": (24, 3.56)}},
    20261134: {"corlab": {"e_n": (22, 35.36), "e_t": (24, 3.44), "omega": (23, 3.46)},
               "scatter_3d": {"e_t": (24, 4.20), "omega": (24, 4.22)}},
}


@pytest.mark.parametrize("seed", sorted(BOUNDS))
def test_stored_sample_per_quantity(seed):
    cases = coverage.sample_cases(24, seed)
    runs = coverage.load_runs(
        ROOT / "data" / "error_bar_coverage" / f"3d_seed{seed}" / "runs.csv", cases)
    table = coverage.score(cases, runs, list(BOUNDS[seed]))
    for name, quantities in BOUNDS[seed].items():
        for quantity, (inside, width) in quantities.items():
            t = table[f"{name}:{quantity}"]
            label = f"seed {seed} {name}:{quantity}"
            assert t["cases"] == 24, label
            assert t["covered"] >= inside, f"{label}: {t['covered']} of 24 inside"
            assert t["width_ratio"] <= width, f"{label}: width {t['width_ratio']:.3f}"


# The candidate written down before the sixth sample (docs/theory/error_bars.md, "A candidate
# for 0.11.0's bars"): every 3-D factor x 0.9. Per seed and quantity: cases inside and the width,
# as measured (the width 0.01 above it). Adopted only where the sixth sample gives >= 23 and <= 3.
CANDIDATE = {
    20261133: {"e_n": (23, 2.97), "e_t": (23, 2.96), "omega": (24, 2.61)},
    20261134: {"e_n": (22, 31.82), "e_t": (24, 3.09), "omega": (23, 3.11)},
}


@pytest.mark.parametrize("seed", sorted(CANDIDATE))
def test_the_narrower_candidate_as_scored(seed):
    cases = coverage.sample_cases(24, seed)
    runs = coverage.load_runs(
        ROOT / "data" / "error_bar_coverage" / f"3d_seed{seed}" / "runs.csv", cases)
    table = coverage.score(cases, runs, ["corlab"], bar_scale=0.9)
    for quantity, (inside, width) in CANDIDATE[seed].items():
        t = table[f"corlab:{quantity}"]
        assert t["covered"] == inside, f"seed {seed} {quantity}: {t['covered']} of 24 inside"
        assert width - 0.01 <= t["width_ratio"] <= width, f"seed {seed} {quantity}"
    if seed == 20261134:  # the rule: rejected for every quantity (width above 3)
        assert all(table[f"corlab:{q}"]["width_ratio"] > 3.0 for q in CANDIDATE[seed])


def test_score_counts_a_bar_that_misses():
    """score() itself: a case whose finer value lies outside its bar is a miss, one inside is
    covered (the bar of the `scatter` estimator from two companions, computed here by hand)."""
    cases = coverage.sample_cases(2, 1)
    runs = {}
    for case, shift in zip(cases, (0.001, 1.0)):
        for q, e in ((1.0, 0.5), (2.0 ** 0.5, 0.501), (2.0 ** 0.75, 0.502), (2.0, 0.503),
                     (coverage.REFERENCE, 0.5 - shift)):
            runs[(case["case"], round(q, 6))] = {
                "status": "separated", "a_over_h": "4", "e_n": str(e), "e_t": str(e),
                "omega": str(e)}
    t = coverage.score(cases, runs, ["scatter"])["scatter:e_n"]
    assert (t["cases"], t["covered"]) == (2, 1)
    assert t["misses"][0].startswith(cases[1]["case"][-2:])
