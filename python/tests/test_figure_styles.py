"""Figures with one series per case give every case its own look: Fig. 6 draws 15 cases, each in
its own colour and its own marker, and no two colours of the first 20 cases are near each
other."""
# SPDX-License-Identifier: BSD-3-Clause
import itertools
import math

import matplotlib

from corlab import figures


def test_case_styles_are_distinct_and_start_with_the_default_colours():
    styles = [figures.case_style(i) for i in range(60)]
    assert len(set(styles)) == len(styles)
    assert len({colour for colour, _ in styles[:20]}) == 20  # 20 cases: 20 colours
    assert len({marker for _, marker in styles[:15]}) == 15  # 15 cases: 15 markers
    tab10 = matplotlib.colormaps["tab10"].colors
    assert [colour for colour, _ in styles[:10]] == [matplotlib.colors.to_hex(c) for c in tab10]


def test_the_first_twenty_case_colours_are_far_apart():
    """tab20's light shades beside their dark ones read as pairs; every two of the first 20 case
    colours are at least 60 apart in RGB (0-255; tab10's closest pair is 67)."""
    rgb = [tuple(255 * x for x in matplotlib.colors.to_rgb(figures.case_style(i)[0]))
           for i in range(20)]
    closest = min(math.dist(a, b) for a, b in itertools.combinations(rgb, 2))
    assert closest >= 60, closest


def test_fig6_draws_fifteen_cases_in_fifteen_styles(tmp_path, monkeypatch):
    sigma_y = (300, 500, 700, 1000, 1300)
    groups = [f"rho{rho}_sy{sy}" for rho in (3925, 7850, 15700) for sy in sigma_y]
    comparison = [{"study": "table2", "group": g, "k1": 10.0 ** (5 + j), "e_fe": 0.5 + 0.01 * j,
                   "e_error": 0.001} for g in groups for j in range(3)]
    fit = {"fits": {"comparison": comparison,
                    "restitution_law": {"slope": {"value": 0.056}}}, "paper": {"slope": 0.056}}
    drawn = {}

    def keep(fig, out_dir, name):
        drawn[name] = fig
        return name

    monkeypatch.setattr(figures, "_save", keep)
    assert figures.fig6_e_vs_k1(str(tmp_path), fit) == "fig06_e_vs_lnk1.png"
    ax = drawn["fig06_e_vs_lnk1.png"].axes[0]
    points = [line for line in ax.lines  # the points, not the error bars' caps
              if line.get_linestyle() == "None" and line.get_marker() not in ("_", "|")]
    assert len(points) == 15
    looks = {(matplotlib.colors.to_hex(line.get_color()), line.get_marker()) for line in points}
    assert len(looks) == 15
    assert len({colour for colour, _ in looks}) == 15
    assert len({marker for _, marker in looks}) == 15
