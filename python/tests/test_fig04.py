"""Fig. 4 of the report: field snapshots written by `corlab reproduce` (verification_hertz with
output.times) are read back by corlab.vtu.read_vtu and drawn by fig4_fields."""
# SPDX-License-Identifier: BSD-3-Clause
import json
import os
import subprocess

import numpy as np
import pytest

from corlab import figures, vtu

TINY_HERTZ = """[study]
name = "verification_hertz"
description = "tiny Figs. 3-5 for the test"
[base]
"impact.velocity" = 5.0
"mesh.h_min" = 1.5e-3
"mesh.contact_elements" = 3.0
"output.history_every" = 5
"output.times" = "70e-6, 110e-6, 170e-6"
[[cases]]
"substrate.sigma_y" = "none"
[[cases]]
"substrate.sigma_y" = 500.0e6
"""


def test_fig4_without_snapshots_is_missing(tmp_path):
    assert figures.fig4_fields(str(tmp_path), {}) is None
    assert vtu.field_snapshots(str(tmp_path / "nothing")) == []


def test_reproduce_writes_fields_and_fig4_reads_them(tmp_path, corlab_bin):
    studies = tmp_path / "studies" / "coarse"
    studies.mkdir(parents=True)
    (studies / "verification_hertz.toml").write_text(TINY_HERTZ)
    out = tmp_path / "out"
    cmd = [corlab_bin, "reproduce", "--preset", "coarse", "--out", str(out),
           "--studies", str(tmp_path / "studies"), "--only", "verification_hertz", "--jobs", "2",
           "--quiet"]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    runs = {}
    for row, h, s in figures.history_runs(str(out), "verification_hertz"):
        run_dir = out / "verification_hertz" / "runs" / row["case_id"]
        snaps = vtu.field_snapshots(str(run_dir))
        assert [round(t * 1e6) for t, _ in snaps] == [70, 110, 170], os.listdir(run_dir)
        elastic = s["config"]["substrate"]["material"]["sigma_y"] is None
        runs["elastic" if elastic else "plastic"] = (h, s, snaps)
    assert set(runs) == {"elastic", "plastic"}

    for kind, (h, s, snaps) in runs.items():
        for t, path in snaps:
            v = vtu.read_vtu(path)
            assert v["quads"].shape == (s["elements"], 4)
            assert v["points"].shape[1] == 3 and np.isfinite(v["points"]).all()
            assert v["quads"].min() >= 0 and v["quads"].max() < len(v["points"])
            body = v["cells"]["body"]
            assert set(np.unique(body)) == {0.0, 1.0}
            assert (v["cells"]["von_mises"] >= 0).all()
            assert v["point_data"]["displacement"].shape == (len(v["points"]), 3)
            eps = v["cells"]["plastic_strain"]
            if kind == "elastic":
                assert (eps == 0).all()
            if round(t * 1e6) == 110:
                # deformed configuration: in contact, the sphere's lowest node lies below the
                # undeformed substrate surface z = 0, and the substrate is loaded
                sphere_nodes = np.unique(v["quads"][body == 0])
                assert v["points"][sphere_nodes, 1].min() < 0
                assert v["cells"]["von_mises"][body == 1].max() > 100e6
        last = vtu.read_vtu(snaps[-1][1])
        if kind == "plastic":
            assert last["cells"]["plastic_strain"].max() > 0

    fit = json.loads((out / "fit.json").read_text())
    # the Hertz reference of each run, from the C++ (fem::hertz_reference), for the report
    hertz = {r["elastic"]: r for r in fit["verification"]["hertz"]}
    assert set(hertz) == {True, False}
    for r in hertz.values():
        assert r["hertz"]["contact_time_factor"] == pytest.approx(2.943275, abs=1e-6)
        assert r["contact_radius_fe"] > 0
    el = hertz[True]
    assert len(el["hertz_curve"]["delta"]) == 101
    assert el["hertz_curve"]["force"][-1] > 0
    assert el["F_max_vs_hertz"] == pytest.approx(el["F_max"] / el["hertz"]["max_force"] - 1)
    name = figures.fig4_fields(str(out), fit)
    assert name == "fig04_fields.png"
    png = out / "figures" / name
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    report = out / "report.html"
    assert report.exists()
    assert "figures/fig04_fields.png" in report.read_text()


def test_3d_snapshots_read_back_as_hexahedra(tmp_path, corlab_bin):
    """The 3-D model's fields_<t>.vtu: hexahedra, (x, y, z) vectors, the sphere moving at the
    impact velocity before the contact has slowed it."""
    out = tmp_path / "oblique"
    cmd = [corlab_bin, "simulate", "--quiet", "--out", str(out),
           "--set", "solver.model=3d", "--set", "substrate.shape=rigid",
           "--set", "impact.angle=60",
           "--set", "contact.friction=0.1", "--set", "sphere.sigma_y=none",
           "--set", "impact.velocity=1", "--set", "mesh.h_min=1.5e-3",
           "--set", "mesh.contact_elements=0", "--set", "output.times=2e-4"]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    summary = json.loads((out / "summary.json").read_text())
    (t, path), = vtu.field_snapshots(str(out))
    assert t == pytest.approx(2e-4, rel=1e-3)  # the release's gap is crossed at v cos 60 deg
    v = vtu.read_vtu(path)
    assert v["hexes"].shape == (summary["elements"], 8)
    assert v["hexes"].max() < len(v["points"])
    sphere = np.unique(v["hexes"][v["cells"]["body"] == 0.0])
    velocity = v["point_data"]["velocity"][sphere].mean(axis=0)
    assert velocity == pytest.approx([np.sin(np.pi / 3), 0.0, -np.cos(np.pi / 3)], abs=1e-3)
    assert (v["cells"]["plastic_strain"] == 0.0).all()
