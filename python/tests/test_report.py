"""The reproduction report: figures and HTML from a synthetic output directory, and `corlab
reproduce` end to end on a tiny spec (the CLI from CORLAB_BIN), including resuming."""
# SPDX-License-Identifier: BSD-3-Clause
import ast
import csv
import importlib
import importlib.util
import json
import math
import os
import pathlib
import re
import subprocess

import corlab
from corlab import report, report_dataset, report_oblique

ES = 210e9 / (2 * (1 - 0.3 ** 2))
ROOT = pathlib.Path(__file__).resolve().parents[2]
README = ROOT / "README.md"
_SPEC = importlib.util.spec_from_file_location("readme_numbers",
                                               ROOT / "scripts" / "readme_numbers.py")
readme_numbers = importlib.util.module_from_spec(_SPEC)  # the README's numbers from a fit.json
_SPEC.loader.exec_module(readme_numbers)


def synthetic_results(path):
    cols = ["case_id", "status", "e", "velocity", "sphere_rho", "E_star", "sigma_y", "k1", "k2"]
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(cols)
        k = 0
        for rho in (3925.0, 15700.0):
            for sy in (300e6, 700e6, 1300e6):
                for v in (1.0, 5.0, 30.0):
                    k1, k2 = ES / (rho * v * v), sy / ES
                    e = 1.16 + 0.253 * math.log(k2) + 0.056 * math.log(k1) + 0.003 * (k % 3 - 1)
                    w.writerow([f"c{k}", "ok", min(e, 1.0), v, rho, ES, sy, k1, k2])
                    k += 1


def synthetic_history_run(out, study, case_id, settings, sigma_y):
    run = out / study / "runs" / case_id
    run.mkdir(parents=True)
    t = [i * 1e-6 for i in range(50)]
    d = [max(0.0, 3e-4 * math.sin(math.pi * x / 40e-6)) for x in t]
    with open(run / "history.csv", "w") as f:
        f.write("time_s,contact_force_N,indentation_m,sphere_velocity_m_per_s,kinetic_energy_J,"
                "strain_energy_J,plastic_dissipation_J,hourglass_energy_J,viscous_dissipation_J,"
                "contact_energy_J,energy_balance_error\n")
        for x, y in zip(t, d):
            f.write(f"{x},{1e8 * y},{y},{5 * math.cos(math.pi * x / 40e-6)},10,1,0.5,0.01,0,0,0\n")
    cfg = {"impact": {"gap": 1e-4, "velocity": 5.0},
           "sphere": {"radius": 0.035, "material": {"E": 210e9, "nu": 0.3, "rho": 7850.0,
                                                    "sigma_y": None}},
           "substrate": {"material": {"E": 210e9, "nu": 0.3, "rho": 7850.0, "sigma_y": sigma_y}}}
    summary = {"config": cfg, "e": 0.53 if sigma_y else 0.998, "F_max": 1e5, "delta_max": 3.7e-4,
               "t_contact": 1.7e-4, "energy_sphere_loss": 12.5, "hysteresis_area": 12.52,
               "energy_hourglass": 0.02, "energy_initial": 17.6, "energy_balance_error": 1e-6,
               "elements": 1000, "steps": 5000, "wall_s": 1.0}
    (run / "summary.json").write_text(json.dumps(summary))
    cases = out / study / "cases.csv"
    new = not cases.exists()
    with open(cases, "a") as f:
        if new:
            f.write("case_id," + ",".join(settings) + "\n")
        f.write(case_id + "," + ",".join(settings.values()) + "\n")


def test_report_from_synthetic_directory(tmp_path):
    out = tmp_path / "out"
    (out / "table2").mkdir(parents=True)
    synthetic_results(out / "table2" / "results.csv")
    for h in ("1.0e-3", "0.5e-3"):
        synthetic_history_run(out, "verification_mesh", f"m{h}", {"mesh.h_min": h}, 500e6)
    synthetic_history_run(out, "verification_hertz", "el", {"substrate.sigma_y": "none"}, None)
    synthetic_history_run(out, "verification_hertz", "pl", {"substrate.sigma_y": "5e8"}, 500e6)
    fits = corlab.fit_paper(str(out / "table2" / "results.csv"))
    comparison = []
    with open(out / "table2" / "results.csv") as f:
        for r in csv.DictReader(f):
            comparison.append({"study": "table2", "case_id": r["case_id"],
                               "group": f"rho{float(r['sphere_rho']):g}_E{ES / 1e9:.4g}GPa_sy"
                                        f"{float(r['sigma_y']) / 1e6:g}MPa",  # as group_label()
                               "sphere_rho": float(r["sphere_rho"]), "E_star": ES,
                               "sigma_y": float(r["sigma_y"]), "velocity": float(r["velocity"]),
                               "k1": float(r["k1"]), "e_fe": float(r["e"]),
                               "e_paper": float(r["e"]) * 1.01, "e_ours": float(r["e"])})
    # What the C++ writes beside the fits (src/paper/reproduce_report.cpp), by hand here.
    error = {"groups": [{"study": "table2", "group": "g", "runs": 18, "mean_relative_error": 0.01,
                         "rms_relative_error": 0.01, "largest_relative_error": 0.01,
                         "largest_at_velocity": 5.0}],
             "overall": {"runs": 18, "rms_relative_error": 0.01, "largest_relative_error": 0.01}}
    fit = {"preset": "coarse", "command": "corlab reproduce --preset coarse --out x",
           "studies": {"table2": {"total": 18, "ran": 18, "already_done": 0, "failed": 0,
                                  "wall_s": 12.5, "description": "Table 2", "runs_on_disk": 18,
                                  "solver_s_on_disk": 11.0}},
           "studies_total": {"ran": 18, "wall_s": 12.5, "runs_on_disk": 18,
                             "solver_s_on_disk": 11.0},
           "fits": {"restitution_law": fits["restitution_law"], "comparison": comparison,
                    "yield_onset": [], "curves": {},
                    "model_error": {"e_paper": error, "e_ours": error}},
           "verification": SYNTHETIC_VERIFICATION,
           "figure_lines": {"fig7": {"e_fe": [0.5, 0.6], "e_eq9": [0.51, 0.59]},
                            "fig8": {"ln_k2": [-6, -4], "ours": [0.1, 0.2], "paper": [0.1, 0.2]}},
           "paper": PAPER}
    (out / "fit.json").write_text(json.dumps(fit))
    path = report.make_report(str(out))
    text = open(path).read()
    for fig in ("fig02_mesh.png", "fig03_force_indentation.png", "fig05_energy.png",
                "fig06_e_vs_lnk1.png", "fig07_fit_error.png", "fig08_a_vs_lnk2.png"):
        assert (out / "figures" / fig).exists(), fig
        assert f"figures/{fig}" in text
    slope = fits["restitution_law"]["slope"]["value"]
    assert f"{slope:.5g}" in text  # our coefficient is printed
    assert "No experimental points" in text
    assert "Coarse preset: a demo, NOT the reproduction" in text
    assert "1.00 %" in text  # the paper-model error we put in (e_paper = 1.01 e_fe)
    assert "Fig. 9: no data" in text  # missing studies are reported, not hidden


# fit.json's "verification" and "paper" with numbers no formula of the report could give: the
# report must print them as they are (it computes no Hertz reference and holds no constant).
SYNTHETIC_VERIFICATION = {
    "hertz": [{"case_id": "el", "elastic": True, "velocity": 5.0, "e": 0.998, "F_max": 1e5,
               "delta_max": 3.7e-4, "t_contact": 1.7e-4, "F_max_vs_hertz": 0.0123,
               "delta_max_vs_hertz": -0.0456, "t_contact_vs_hertz": 0.0789,
               "contact_radius_fe": 1e-3,
               "hertz": {"max_force": 98765.4, "max_overlap": 3.21098e-4,
                         "contact_time": 1.65432e-4},
               "hertz_curve": {"delta": [0.0, 1e-4, 3e-4], "force": [0.0, 1e4, 9e4]}},
              {"case_id": "pl", "elastic": False, "velocity": 5.0, "e": 0.53,
               "e_from_paper_energy_loss": 0.4321, "energy_sphere_loss": 12.5,
               "hysteresis_area": 12.52, "hysteresis_vs_energy_loss": 0.0016,
               "hourglass_fraction": 0.00111, "energy_balance_error": 1e-6,
               "contact_radius_fe": 1e-3, "hertz": {}}],
    "mesh": [{"case_id": "m1.0e-3", "h_min": 1e-3, "elements": 1000, "steps": 5000, "e": 0.53,
              "e_minus_finest": 0.0042, "F_max": 1e5, "wall_s": 1.0},
             {"case_id": "m0.5e-3", "h_min": 5e-4, "elements": 4000, "steps": 9000, "e": 0.5258,
              "e_minus_finest": 0.0, "F_max": 1e5, "wall_s": 2.0}]}
PAPER = {"slope": 0.0561, "alpha": 1.161, "beta": 0.2531, "n": 4.51, "m": -3.51, "c": 0.051,
         "K": 15.82, "sigma0": 100e6, "E0": 100e9, "energy_loss_5ms_J": 12.62,
         "hysteresis_area_5ms_J": 12.64, "hourglass_fraction": 0.000694,
         "hysteresis_difference": 0.0017, "fit_error_bound": 0.06}


def test_report_takes_hertz_and_paper_numbers_from_fit_json(tmp_path):
    """The report prints the Hertz reference, the errors and the paper's values of fit.json: it
    computes no Hertz reference and holds no published constant (both live in the C++)."""
    out = tmp_path / "out"
    synthetic_history_run(out, "verification_hertz", "el", {"substrate.sigma_y": "none"}, None)
    synthetic_history_run(out, "verification_hertz", "pl", {"substrate.sigma_y": "5e8"}, 500e6)
    fit = {"preset": "paper", "studies": {}, "fits": {}, "verification": SYNTHETIC_VERIFICATION,
           "paper": PAPER}
    (out / "fit.json").write_text(json.dumps(fit))
    text = open(report.make_report(str(out))).read()
    for expected in ("vs Hertz 98.765 kN (1.23 %)", "vs Hertz 0.3211 mm (-4.56 %)",
                     "vs Hertz 165.43 us (7.89 %)", "0.432 (from the paper's 12.62 J loss)",
                     "(paper 12.62 J)", "(paper 12.64 J)", "difference 0.16 % (paper 0.17 %)",
                     "hourglass 0.111 % of the initial energy (paper 0.0694 %)",
                     "e = 0.5300 at h_min = 1 mm, 0.5258 at h_min = 0.5 mm", "0.0042"):
        assert expected in text, expected
    assert (out / "figures" / "fig03_force_indentation.png").exists()
    # No formula or constant of the paper or of Hertz is left on the Python side (and none in any
    # module of the report: test_no_formula_or_constant_in_any_module_of_the_report).
    from corlab import figures
    for name in ("PAPER", "SIGMA0", "E0", "effective_modulus", "_hertz_force"):
        assert not hasattr(figures, name), name
    assert not hasattr(report, "overall_error")


def report_modules():
    """{name: file} of every corlab module the report imports, directly or through another one,
    found by reading their imports: a module the report starts to use is checked without an
    edit here."""
    found, todo = {}, ["corlab.report"]
    while todo:
        name = todo.pop()
        if name in found:
            continue
        try:
            module = importlib.import_module(name)
        except ModuleNotFoundError:  # `from .html_table import esc`: esc is no module
            continue
        found[name] = module.__file__
        if not module.__file__.endswith(".py"):
            continue  # corlab._core: the C++
        for node in ast.walk(ast.parse(open(module.__file__).read())):
            if isinstance(node, ast.Import):
                todo += [a.name for a in node.names if a.name.split(".")[0] == "corlab"]
            elif isinstance(node, ast.ImportFrom):
                base = (f"corlab.{node.module}" if node.module else "corlab") if node.level \
                    else node.module or ""
                if base.split(".")[0] == "corlab":
                    todo += [base] + [f"{base}.{a.name}" for a in node.names]
    return {n: f for n, f in found.items() if f.endswith(".py")}


#: The paper's published constants and Hertz's formula (fit.json's "paper", fem::hertz_reference).
PUBLISHED = ("0.056", "1.16", "0.253", "15.81", "12.61", "12.63", "2.94", "0.0693", "4 / 3",
             "4.0 / 3.0", "math.pi")
#: Material constants of the studies (each run's config holds them): steel's rho, E and nu^2.
MATERIAL_NUMBERS = (7850.0, 210e9, 0.09)
#: A material spec with a typed-in property ("E=...,nu=0.3,rho=7850"): materials re-derived.
TYPED_SPEC = re.compile(r"\b(?:E|nu|rho|sy|H)=[-+.\d]")


def _is_number(node, value=None):
    return (isinstance(node, ast.Constant) and type(node.value) in (int, float)
            and (value is None or node.value == value))


def _mentions_e_star(node):
    return any(isinstance(n, ast.Constant) and n.value == "E_star"
               or isinstance(n, ast.Name) and n.id.lower() == "e_star" for n in ast.walk(node))


def formula_findings(source):
    """Where `source` holds a material constant, a typed-in material spec, arithmetic on E*
    beyond a unit (E from E*, k1, ...) or a factor 1 - nu^2, and the paper's or Hertz's
    constants: (line, what) pairs."""
    out = [(0, f"published constant {c!r}") for c in PUBLISHED if c in source]
    for node in ast.walk(ast.parse(source)):
        line = getattr(node, "lineno", 0)
        if _is_number(node) and node.value in MATERIAL_NUMBERS:
            out.append((line, f"material constant {node.value!r}"))
        elif isinstance(node, ast.Constant) and isinstance(node.value, str) \
                and TYPED_SPEC.search(node.value):
            out.append((line, f"material spec {node.value!r}"))
        elif isinstance(node, ast.BinOp) and _mentions_e_star(node) and not (
                isinstance(node.op, ast.Div) and _is_number(node.right)
                and math.log10(node.right.value).is_integer()):  # E* in GPa is formatting
            out.append((line, "arithmetic on E*"))
        elif isinstance(node, ast.BinOp) and isinstance(node.op, ast.Sub) \
                and _is_number(node.left, 1) and (_is_number(node.right) or (
                    isinstance(node.right, ast.BinOp) and isinstance(node.right.op, ast.Pow))):
            out.append((line, "1 - nu^2"))
    return out


def test_no_formula_or_constant_in_any_module_of_the_report():
    """Every number of the report comes from fit.json, model_fit.json, model_scores.json or the
    C++ (corlab._core): no module it imports holds a formula or a material or published
    constant."""
    modules = report_modules()
    assert {"corlab.report", "corlab.figures", "corlab.report_dataset", "corlab.report_oblique",
            "corlab.dataset", "corlab.html_table", "corlab.vtu"} <= set(modules), sorted(modules)
    for name, path in modules.items():
        findings = formula_findings(open(path).read())
        assert findings == [], (name, findings)


def test_table2_against_eq19_is_fit_jsons(tmp_path):
    """corlab2026 against eq. 19 on Table 2: the numbers of fit.json as they are (the C++
    computes them for each run's own materials; there is no table2/results.csv to compute from
    here), and no table without them."""
    data = tmp_path / "data"
    data.mkdir()
    shipped = os.path.join(os.path.dirname(__file__), "..", "..", "data", "fe_restitution")
    for name in ("model_fit.json", "model_scores.json"):
        (data / name).write_text(open(os.path.join(shipped, name)).read())
    versus = {"study": "table2", "cases": 9, "corlab2026_at_least_as_close": 7,
              "corlab2026": {"n": 9, "rms": 0.01234, "worst": 0.04567, "bias": -0.00789},
              "ma2023": {"n": 9, "rms": 0.09876, "worst": -0.32109, "bias": 0.01111}}
    fit = {"dataset_dir": str(data), "fits": {"corlab2026_versus_eq19": versus}}
    html = report_dataset.dataset_section(fit, str(tmp_path / "out"))
    assert "in 7 of 9 cases" in html
    for row in ("<td>corlab2026</td><td>9</td><td>1.2 %</td><td>4.6 %</td><td>-0.8 %</td>",
                "<td>ma2023 (eq. 19)</td><td>9</td><td>9.9 %</td><td>-32.1 %</td><td>1.1 %</td>"):
        assert row in html, row
    del fit["fits"]["corlab2026_versus_eq19"]
    assert "The paper's corner" not in report_dataset.dataset_section(fit, str(tmp_path / "out"))


def test_oblique_section_shows_the_shipped_kharaz_tables(tmp_path):
    """The oblique section reads data/kharaz2001's tables as shipped: one row per FE angle with
    its error bars, and the figure; without the tables, a note instead of an error."""
    data = os.path.join(os.path.dirname(__file__), "..", "..", "data")
    html = report_oblique.oblique_section(data, str(tmp_path))
    with open(os.path.join(data, "kharaz2001", "fe_oblique.csv")) as f:
        angles = [line.split(",")[0] for line in f.read().splitlines()[1:]]
    assert html.count("<tr>") == len(angles) + 1
    assert (tmp_path / "figures" / "kharaz2001.png").stat().st_size > 10000
    empty = report_oblique.oblique_section(str(tmp_path), str(tmp_path))
    assert "No oblique-impact tables" in empty


def test_oblique_studies_give_one_figure_per_table(tmp_path):
    """Each table of data/oblique_studies gets its figure (e_n, e_t, omega against the angle, a
    line per speed); no tables, a note."""
    folder = tmp_path / "oblique_studies"
    folder.mkdir()
    head = ("impact_velocity,impact_angle_deg,e_n,e_n_error,e_t,e_t_error,omega,omega_error,"
            "rebound_angle_com")
    # a normal impact has no e_t: an empty cell (as corlab writes it) or "nan" (older tables)
    rows = ["1,0,0.72,0.01,,,0,,0", "3,0,0.58,0.01,nan,nan,0,nan,0",
            "1,30,0.74,0.01,0.70,0.01,10.7,0.3,28.7", "3,30,0.60,0.01,0.65,0.01,30.1,0.5,25.0"]
    (folder / "pair.csv").write_text("\n".join([head] + rows) + "\n")
    (tmp_path / "out" / "figures").mkdir(parents=True)
    html = report_oblique.studies_section(str(tmp_path), str(tmp_path / "out"))
    assert 'src="figures/oblique_pair.png"' in html
    assert (tmp_path / "out" / "figures" / "oblique_pair.png").stat().st_size > 10000
    empty = tmp_path / "empty"
    empty.mkdir()
    assert "No elastic-plastic" in report_oblique.studies_section(str(empty), str(tmp_path))


def test_the_guard_finds_what_the_report_used_to_compute():
    """The lines that derived Table 2's materials in the report (E from E*, nu, rho) and Hertz's
    force, as they were: each is found."""
    before = (
        'e_mod = t["E_star"][ok] * 2 * (1 - 0.09)\n'
        'spheres = [f"E={e!r},nu=0.3,rho={r!r}" for e, r in zip(e_mod, t["sphere_rho"][ok])]\n'
        'substrates = [f"E={e!r},nu={nu!r},rho=7850,sy={y!r}" for e, y in zip(e_mod, sy)]\n'
        'es = 210e9 / (2 * (1 - nu ** 2))\n'
        'force = 4 / 3 * es * math.sqrt(r) * d ** 1.5\n')
    found = formula_findings(before)
    for what in ("arithmetic on E*", "1 - nu^2", "material constant 0.09",
                 "material constant 210000000000.0", "rho=7850",
                 "published constant '4 / 3'"):
        assert any(what in w for _, w in found), (what, found)
    assert {line for line, _ in found} >= {1, 2, 3, 4}


def test_report_main_without_fit_json_fails_cleanly(tmp_path):
    assert report.main([str(tmp_path)]) == 2


def test_reproduce_end_to_end_on_a_tiny_spec_and_resume(tiny_reproduction):
    cmd, first, out = tiny_reproduction  # conftest.py: TINY_TABLE2_SPEC, run once per session
    assert first.returncode == 0, first.stderr
    fit = json.loads((out / "fit.json").read_text())
    assert fit["studies"]["table2"]["ran"] == 6
    law = fit["fits"]["restitution_law"]
    assert 0.02 < law["slope"]["value"] < 0.1
    # the numbers the report prints, computed by the C++ (src/paper/reproduce_report.cpp)
    assert fit["fits"]["versus_paper"]["slope"]["paper"] == fit["paper"]["slope"] == 0.056
    error = fit["fits"]["model_error"]["e_paper"]
    overall = error["overall"]
    assert overall["runs"] == sum(g["runs"] for g in error["groups"])
    assert fit["studies"]["table2"]["runs_on_disk"] == 6
    assert fit["studies_total"]["ran"] == 6
    assert "fig6" in fit["figure_lines"] and "fig8" in fit["figure_lines"]
    assert all(c["k1"] > 0 for c in fit["fits"]["comparison"])
    # corlab2026 for each run's own materials (the spec's defaults: steel_ma2023, E = 210 GPa,
    # nu = 0.3, rho = 7850), and against eq. 19 over the six runs
    for c in fit["fits"]["comparison"]:
        assert c["e_corlab2026"] == corlab.predict(
            "corlab2026", "E=210e9,nu=0.3,rho=7850", f"E=210e9,nu=0.3,rho=7850,sy={c['sigma_y']!r}",
            c["velocity"])
    t2 = fit["fits"]["corlab2026_versus_eq19"]
    assert t2["cases"] == 6 and t2["corlab2026"]["n"] == t2["ma2023"]["n"] == 6
    # the README's refit table against this (coarse) fit.json, where they can be compared: the
    # paper's constants (the rest is checked against a paper run, README "What the reproduction
    # finds"; python/tests/test_readme.py)
    assert readme_numbers.check(fit, README.read_text()) == []
    assert (out / "report.html").exists()
    html_text = (out / "report.html").read_text()
    assert f"RMS relative error {100 * overall['rms_relative_error']:.2f} %" in html_text
    assert f"in {t2['corlab2026_at_least_as_close']} of 6 cases" in html_text
    assert (out / "figures" / "fig06_e_vs_lnk1.png").exists()
    second = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    assert second.returncode == 0, second.stderr
    fit2 = json.loads((out / "fit.json").read_text())
    assert fit2["studies"]["table2"]["ran"] == 0
    assert fit2["studies"]["table2"]["already_done"] == 6
    assert fit2["fits"]["restitution_law"]["slope"]["value"] == law["slope"]["value"]


def test_pairs_section_scores_every_model_on_the_pair_dataset(tmp_path):
    """The particle-pair part of "beyond the paper": each registered model on all pair rows and
    on both corners (model_scores.json as shipped), corlab2026p's held-out sets by regime; without
    the dataset, a note."""
    folder = os.path.join(os.path.dirname(__file__), "..", "..", "data", "fe_restitution_pairs")
    with open(os.path.join(folder, "model_scores.json")) as f:
        scores = json.load(f)
    html = report_dataset.pairs_section(folder)
    assert html.count("<tr>") == 2 + 3 * len(scores["scores"]) + 3 * 4
    cell = scores["scores"]["corlab2026p"]["corners"]["density_ratio > 5"]["all"]
    assert (f"<td>corlab2026p (density_ratio &gt; 5)</td><td>{cell['n']}</td>"
            f"<td>{100 * cell['rms']:.1f} %</td>") in html
    assert "<td>random holdout: fully plastic</td>" in html
    assert "No particle-pair dataset" in report_dataset.pairs_section(str(tmp_path))
