"""The report's first screen (corlab.report_summary): every key number of fit.json it is given
appears, formatted, and every link lands on a section of the report (make_report on a fit.json
that holds only those numbers; the figures and tables then say "no data")."""
# SPDX-License-Identifier: BSD-3-Clause
import json
import re

from corlab import report, report_summary


def coefficient(value, paper, inside):
    return {"value": value, "ci_lower": value * 0.9, "ci_upper": value * 1.1, "paper": paper,
            "relative_difference": value / paper - 1, "paper_in_ci": inside}


FIT = {
    "preset": "paper",
    "studies_total": {"runs_on_disk": 1234, "solver_s_on_disk": 5678.9},
    "fits": {
        "versus_paper": {"slope": coefficient(0.0604, 0.056, False),
                         "alpha": coefficient(1.30, 1.25, True),
                         "beta": coefficient(0.081, 0.08, True),
                         "crossing_velocity_ratio": 1.234},
        "model_error": {"e_paper": {"groups": [], "overall": {
                            "runs": 150, "rms_relative_error": 0.0321,
                            "largest_relative_error": 0.0912}},
                        "e_ours": {"groups": [], "overall": {
                            "runs": 150, "rms_relative_error": 0.0123,
                            "largest_relative_error": 0.0456}}},
        "corlab2026_versus_eq19": {"cases": 150, "corlab2026_at_least_as_close": 101,
                                   "corlab2026": {"rms": 0.0211}, "ma2023": {"rms": 0.0321}},
        "discretisation_error": {"all": {
            "median": 0.0031, "max": 0.0123, "count": 150, "max_relative": 0.02,
            "max_case": {"e": 0.6, "study": "table2", "group": "g", "velocity": 5.0}}},
    },
}


def test_summary_holds_every_key_number():
    text = " ".join(report_summary.glance_items(FIT))
    for expected in ("1234 finished runs", "94.6 min of solver time",
                     "slope = 0.0604 against the paper's 0.056", "(7.9 %, outside our 95 % CI)",
                     "alpha = 1.3", "beta = 0.081",
                     "over 150 runs: RMS 3.21 %, largest 9.12 %",
                     "refitted: RMS 1.23 %, largest 4.56 %", "RMS 2.11 % against eq. 19's 3.21 %",
                     "101 of 150 runs", "1.23 x the paper's eq. 18", "median 0.0031"):
        assert expected in text, expected


def test_summary_links_land_on_the_reports_sections(tmp_path):
    (tmp_path / "fit.json").write_text(json.dumps(FIT))
    page = open(report.make_report(str(tmp_path))).read()
    glance = page[page.index('<div class="glance"'):page.index("</div>")]
    links = re.findall(r'href="#([^"]+)"', glance)
    ids = set(re.findall(r'<h2 id="([^"]+)"', page))
    assert len(links) == 10  # 4 + law + eq. 19 + corlab2026 + yield + 2
    assert set(links) <= ids, set(links) - ids
    assert page.index('<div class="glance"') < page.index('<nav class="toc">')
