"""Figures with one series per case give every case its own look (issue 29: Fig. 6 drew 15 cases
in 10 colours, two cases to a colour)."""
import matplotlib

from corlab import figures


def test_case_styles_are_distinct_and_start_with_the_default_colours():
    styles = [figures.case_style(i) for i in range(10 * len(figures._CASE_MARKERS))]
    assert len(set(styles)) == len(styles)
    assert len({colour for colour, _ in styles[:20]}) == 20  # 20 cases: 20 colours
    tab10 = matplotlib.colormaps["tab10"].colors
    assert [colour for colour, _ in styles[:10]] == list(tab10)


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
