"""The reproduction report: figures and HTML from a synthetic output directory, and (with
CORLAB_BIN set) `corlab reproduce` end to end on a tiny spec, including resuming."""
import csv
import json
import math
import os
import subprocess

import pytest

import corlab
from corlab import report

ES = 210e9 / (2 * (1 - 0.3 ** 2))


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
                               "e_fe": float(r["e"]), "e_paper": float(r["e"]) * 1.01,
                               "e_ours": float(r["e"])})
    fit = {"preset": "coarse", "command": "corlab reproduce --preset coarse --out x",
           "studies": {"table2": {"total": 18, "ran": 18, "already_done": 0, "failed": 0,
                                  "wall_s": 12.5, "description": "Table 2"}},
           "fits": {"restitution_law": fits["restitution_law"], "comparison": comparison,
                    "yield_onset": [], "curves": {}},
           "paper": {"energy_loss_5ms_J": 12.61}}
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


def test_report_main_without_fit_json_fails_cleanly(tmp_path):
    assert report.main([str(tmp_path)]) == 2


TINY_SPEC = """[study]
name = "table2"
description = "tiny Table 2 for the test"
[base]
"mesh.h_min" = 1.5e-3
"mesh.contact_elements" = 3.0
"sphere.rho" = 7850.0
[grid]
"substrate.sigma_y" = [300.0e6, 700.0e6, 1300.0e6]
"impact.velocity" = [3.0, 20.0]
"""


@pytest.mark.skipif(not os.environ.get("CORLAB_BIN"), reason="CORLAB_BIN not set")
def test_reproduce_end_to_end_on_a_tiny_spec_and_resume(tmp_path):
    studies = tmp_path / "studies" / "coarse"
    studies.mkdir(parents=True)
    (studies / "table2.toml").write_text(TINY_SPEC)
    out = tmp_path / "out"
    cmd = [os.environ["CORLAB_BIN"], "reproduce", "--preset", "coarse", "--out", str(out),
           "--studies", str(tmp_path / "studies"), "--only", "table2", "--jobs", "2", "--quiet"]
    first = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    assert first.returncode == 0, first.stderr
    fit = json.loads((out / "fit.json").read_text())
    assert fit["studies"]["table2"]["ran"] == 6
    law = fit["fits"]["restitution_law"]
    assert 0.02 < law["slope"]["value"] < 0.1
    assert (out / "report.html").exists()
    assert (out / "figures" / "fig06_e_vs_lnk1.png").exists()
    second = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    assert second.returncode == 0, second.stderr
    fit2 = json.loads((out / "fit.json").read_text())
    assert fit2["studies"]["table2"]["ran"] == 0
    assert fit2["studies"]["table2"]["already_done"] == 6
    assert fit2["fits"]["restitution_law"]["slope"]["value"] == law["slope"]["value"]
