"""The e(v) explorer's features in headless chromium (docs/user/explorer.md; the page, the
browser and their helpers are test_browser.py's): stale curves greyed on bad input, the e-axis
fitted to the verified models, readable colours, the DEM route quoted, the CSV download, the
state in the link, moduli in GPa and MPa, the material library (the CLI's), and where each model
is outside its accurate range with the FE command for it."""
# SPDX-License-Identifier: BSD-3-Clause
import csv
import io
import json
import shlex
import subprocess
import time

import pytest
from test_browser import artefacts, browser  # noqa: F401 (fixtures)
from test_browser import (TOLERANCE, assert_dem_is_clis, choose, console_errors, open_explorer,
                          page_state, set_field)

STALE = "#c8c8c8"


def plot_traces(driver):
    """The plot's traces: name, meta, line, marker, fillcolor, x, y."""
    return driver.execute_script(
        "return document.getElementById('plot').data.map(t => ({name: t.name || '', meta: t.meta,"
        " line: t.line || {}, marker: t.marker || {}, fillcolor: t.fillcolor || '', x: t.x,"
        " y: t.y}))")


def y_range(driver):
    return driver.execute_script("return document.getElementById('plot').layout.yaxis.range")


def rgb(colour):
    """#rrggbb or rgba(r,g,b,a) as (r, g, b)."""
    if colour.startswith("#"):
        return tuple(int(colour[i:i + 2], 16) for i in (1, 3, 5))
    return tuple(float(x) for x in colour[colour.index("(") + 1:-1].split(",")[:3])


def test_bad_input_greys_the_stale_curves_and_clears_what_belongs_to_them(browser):  # noqa: F811
    state = open_explorer(browser)
    assert not state["stale"] and state["csv"] and state["feCommand"] and state["dem"]
    set_field(browser, "sphere-nu", "0.7")
    state = page_state(browser)
    assert state["stale"] and state["error"].startswith("invalid sphere.nu = 0.7")
    assert browser.find_element("id", "sphere-source").text == "custom values"
    assert state["result"] is None and state["dem"] is None and state["csv"] is None
    traces = plot_traces(browser)
    assert traces, "the last curves stay, greyed"
    for t in traces:
        for colour in (t["line"].get("color"), t["marker"].get("color")):
            assert colour in (None, STALE), (t["name"], colour)
    assert browser.execute_script("return document.getElementById('dem').children.length") == 0
    assert browser.execute_script("return document.getElementById('fe-command').textContent") == ""
    assert browser.execute_script("return document.getElementById('download-csv').disabled")
    assert "stale" in browser.execute_script(
        "return document.getElementById('plot').layout.annotations[0].text")
    set_field(browser, "sphere-nu", "0.22")  # valid again: colours and sections back
    state = page_state(browser)
    assert not state["stale"] and state["error"] == "" and state["dem"]
    assert all(t["line"].get("color") != STALE for t in plot_traces(browser) if t["line"])
    assert console_errors(browser) == []


def test_y_axis_fits_the_verified_models_and_unverified_ones_are_dashed(browser):  # noqa: F811
    state = open_explorer(browser)
    low, high = y_range(browser)
    result = state["result"]
    verified = [m for m in result["models"] if m["status"].startswith("verified")]
    unverified = [m for m in result["models"] if not m["status"].startswith("verified")]
    assert verified and unverified
    shown = [e for m in verified for e in m["e"]] + result["prediction_interval"]["high"]
    assert low <= min(shown) and max(shown) <= high
    # an unverified model reaching above the verified ones is clipped, not fitted
    assert max(e for m in unverified for e in m["e"]) > high
    assert high < 1.2
    for t in plot_traces(browser):
        meta = t["meta"] or {}
        if meta.get("part") == "inside":
            assert t["line"]["dash"] == ("solid" if meta["verified"] else "dash"), t["name"]
        if meta.get("part") == "outside":
            assert t["line"]["dash"] == "dot", t["name"]


def test_colours_corlab2026_stands_out_from_its_band_and_the_other_models(browser):  # noqa: F811
    open_explorer(browser)
    traces = plot_traces(browser)
    band = next(t for t in traces if t["name"].endswith("95 % prediction interval"))
    lines = {t["meta"]["model"]: t["line"]["color"] for t in traces
             if (t["meta"] or {}).get("part") == "inside"}
    line = rgb(lines["corlab2026"])
    distance = sum((a - b) ** 2 for a, b in zip(line, rgb(band["fillcolor"]))) ** 0.5
    assert distance > 200, (lines["corlab2026"], band["fillcolor"])
    assert len(set(lines.values())) == len(lines), lines  # one colour per model


def test_dem_section_quotes_the_recommended_lammps_route(browser, corlab_bin,  # noqa: F811
                                                         tmp_path):
    state = open_explorer(browser)
    routes = {r["code"]: r for r in state["dem"]["pairs"][0]["routes"]}
    assert "python/invoke hook" in routes["LAMMPS"]["route"]
    shown = browser.execute_script(
        "return document.querySelector('#dem-routes li[data-code=LAMMPS]').textContent")
    assert "python/invoke hook" in shown and "viscoelastic" not in shown
    # the same route and error as `corlab dem` writes in dem_export.json for the page's command
    cmd = shlex.split(state["dem"]["command"])
    done = subprocess.run([corlab_bin] + cmd[1:-1] + [str(tmp_path)], capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    written = json.loads((tmp_path / "dem_export.json").read_text())
    text = json.dumps(written)
    assert routes["LAMMPS"]["route"] in text
    assert repr(routes["LAMMPS"]["max_abs_error"])[:8] in text


def finished_download(folder, timeout=30.0):
    """The one file chromium downloaded into folder, once it is complete: the final name can be
    seen, empty, before chromium has written it (CI read 0 rows once, stop 53). Complete = no
    NAME.crdownload left, and the file non-empty with the same size on two looks 0.2 s apart."""
    end = time.monotonic() + timeout
    last = None
    while time.monotonic() < end:
        files = sorted(folder.iterdir())
        partial = [f for f in files if f.suffix == ".crdownload"]
        done = [f for f in files if f.suffix != ".crdownload"]
        if len(done) == 1 and not partial:
            size = done[0].stat().st_size
            if size > 0 and size == last:
                return done[0]
            last = size
        time.sleep(0.2)
    raise AssertionError(f"no finished download in {timeout} s: {list(folder.iterdir())}")


def test_csv_download_holds_every_model_at_every_speed(browser, corlab_bin,  # noqa: F811
                                                       tmp_path):
    state = open_explorer(browser)
    browser.execute_cdp_cmd("Page.setDownloadBehavior",
                            {"behavior": "allow", "downloadPath": str(tmp_path)})
    browser.find_element("id", "download-csv").click()
    downloaded = finished_download(tmp_path)
    assert downloaded.name == "corlab_e_v_alumina_ma2023_on_aluminium_ma2023.csv"
    rows = list(csv.DictReader(io.StringIO(downloaded.read_text())))
    result = state["result"]
    assert len(rows) == len(result["models"]) * len(result["velocity"])
    v = result["velocity"]
    done = subprocess.run([corlab_bin, "predict", "--model", "all", "--sphere", "alumina_ma2023",
                           "--substrate", "aluminium_ma2023", "--velocity",
                           f"{v[0]!r}:{v[-1]!r}:{len(v)}", "--spacing", "log", "--format",
                           "json"], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    cli = {m["model"]: m for m in json.loads(done.stdout)["models"]}
    for row in rows:
        ref = cli[row["model"]]
        i = v.index(float(row["velocity"]))
        assert abs(float(row["e"]) - ref["e"][i]) <= TOLERANCE, row
        assert float(row["k1"]) == pytest.approx(ref["k1"][i], rel=TOLERANCE)
        assert row["status"] == ref["status"]
        assert row["outside_accurate_range"] in ("true", "false")


def test_link_restores_every_input(browser):  # noqa: F811
    open_explorer(browser)
    choose(browser, "substrate-name", "copper_c11000")
    choose(browser, "sphere-E-unit", "MPa")
    set_field(browser, "sphere-nu", "0.25")  # the sphere becomes custom, E in MPa
    set_field(browser, "v-max", "12")
    choose(browser, "v-spacing", "lin")
    set_field(browser, "radius-ratio", "0.8")
    choose(browser, "dem-model", "thornton1997")
    before = page_state(browser)
    url = browser.current_url
    assert "#" in url and "radius-ratio=0.8" in url
    browser.find_element("id", "copy-link").click()  # shows (and copies) the link
    assert browser.find_element("id", "link").text == url
    ids = ["sphere-name", "sphere-E", "sphere-E-unit", "sphere-nu", "substrate-name",
           "substrate-E", "v-max", "v-spacing", "radius-ratio", "dem-model"]
    values = {i: browser.find_element("id", i).get_attribute("value") for i in ids}
    after = open_explorer(browser, url)
    assert after["request"] == before["request"]
    assert after["request"]["sphere"].startswith("E=370000e6,nu=0.25,")
    assert {i: browser.find_element("id", i).get_attribute("value") for i in ids} == values
    assert after["dem"] == before["dem"]
    assert console_errors(browser) == []


def test_moduli_in_gpa_mpa_or_pa_give_the_same_e(browser):  # noqa: F811
    state = open_explorer(browser)
    e_builtin = [m["e"] for m in state["result"]["models"]]
    assert browser.find_element("id", "sphere-E").get_attribute("value") == "370"  # GPa
    assert browser.find_element("id", "substrate-sy").get_attribute("value") == "380"  # MPa
    choose(browser, "substrate-sy-unit", "GPa")  # shown in another unit: still the built-in
    assert browser.find_element("id", "substrate-sy").get_attribute("value") == "0.38"
    choose(browser, "substrate-E-unit", "MPa")
    assert browser.find_element("id", "substrate-E").get_attribute("value") == "68000"
    choose(browser, "substrate-sy-unit", "Pa")
    assert browser.find_element("id", "substrate-sy").get_attribute("value") == "380000000"
    assert page_state(browser)["request"]["substrate"] == "aluminium_ma2023"
    set_field(browser, "substrate-nu", "0.33")  # the same values, typed: a custom material
    state = page_state(browser)
    assert state["request"]["substrate"] == "E=68000e6,nu=0.33,rho=2700,sy=380000000,H=0"
    assert [m["e"] for m in state["result"]["models"]] == e_builtin  # the same doubles


def test_material_library_is_the_clis_with_sources(browser, corlab_bin):  # noqa: F811
    state = open_explorer(browser)
    done = subprocess.run([corlab_bin, "materials"], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    listed = {}
    for line in done.stdout.splitlines()[1:]:
        name, rest = line.split(None, 1)
        listed[name] = rest
    catalog = state["catalog"]["materials"]
    assert sorted(m["name"] for m in catalog) == sorted(listed)
    for m in catalog:
        assert m["source"] and m["category"] and m["category"] in listed[m["name"]], m
    groups = browser.execute_script(
        "return [...document.querySelectorAll('#sphere-name optgroup')].map(g => g.label)")
    for category in ("glass", "ceramic", "steel", "copper alloy", "aluminium alloy", "titanium",
                     "polymer"):
        assert category in groups
    choose(browser, "sphere-name", "glass_soda_lime")
    source = browser.find_element("id", "sphere-source").text
    assert "EN 572-1" in source
    assert page_state(browser)["request"]["sphere"] == "glass_soda_lime"


def test_fe_command_covers_the_speeds_outside_corlab2026p_range(browser):  # noqa: F811
    open_explorer(browser)
    choose(browser, "substrate-name", "aluminium_1100_o")  # soft: a large damage number
    state = page_state(browser)
    result = state["result"]
    model = next(m for m in result["models"] if m["model"] == "corlab2026p")
    outside = [v for v, o in zip(result["velocity"], model["accuracy"]["outside"]) if o]
    assert 0 < len(outside) < len(result["velocity"])
    assert any("damage number" in r for r in model["accuracy"]["reasons"])
    words = shlex.split(state["feCommand"])
    assert words[:4] == ["corlab", "predict", "--model", "fe"]
    assert words[words.index("--sphere") + 1] == "alumina_ma2023"
    assert words[words.index("--substrate") + 1] == "aluminium_1100_o"
    lo, hi, n = words[words.index("--velocity") + 1].split(":")
    assert int(n) == 8 and len(lo) <= 5 and len(hi) <= 5  # 3 digits, covering the speeds
    inside = [v for v in result["velocity"] if v not in outside]
    assert max(v for v in inside if v < min(outside)) < float(lo) <= min(outside)
    assert max(outside) <= float(hi) <= 1.01 * max(outside)
    # the model's curve is dotted exactly there; the table says so
    dotted = next(t for t in plot_traces(browser)
                  if (t["meta"] or {}).get("model") == "corlab2026p" and
                  t["meta"]["part"] == "outside")
    assert min(x for x, y in zip(dotted["x"], dotted["y"]) if y is not None) <= min(outside)
    cell = browser.execute_script(
        "return document.querySelector('#models tr[data-model=corlab2026p] td:nth-child(6)')"
        ".textContent")
    assert cell.startswith(f"outside at {len(outside)} of ")


def test_dem_export_of_a_particle_pair_is_corlab_dems(browser, corlab_bin,  # noqa: F811
                                                      tmp_path):
    open_explorer(browser)
    choose(browser, "sphere-name", "steel_aisi_52100")
    choose(browser, "substrate-name", "aluminium_6061_t6")
    set_field(browser, "radius-ratio", "0.5")
    dem = page_state(browser)["dem"]
    cmd = assert_dem_is_clis(browser, corlab_bin, dem, tmp_path)
    assert "--type sphere=steel_aisi_52100:0.005 --type substrate=aluminium_6061_t6:0.01 " in \
        dem["command"] and "--wall" not in cmd
    assert len(dem["pairs"]) == 3  # sphere-sphere, sphere-substrate, substrate-substrate
    choose(browser, "sphere-name", "alumina_ma2023")  # elastic: its own pair has no model e
    dem = page_state(browser)["dem"]
    done = subprocess.run([corlab_bin, "dem", "--type", "sphere=alumina_ma2023:0.005", "--type",
                           "substrate=aluminium_6061_t6:0.01", "--model", "corlab2026",
                           "--out", str(tmp_path / "elastic")], capture_output=True, text=True,
                          timeout=60)
    assert done.returncode == 2
    assert dem["error"]["message"] == done.stderr.strip().removeprefix("corlab: error: ")


def test_dataset_runs_fade_with_their_distance(browser):  # noqa: F811
    state = open_explorer(browser)
    runs = next(t for t in plot_traces(browser) if t["name"] == "FE dataset, nearest runs")
    distances = [n["distance"] for n in state["result"]["nearest"]]
    opacity = runs["marker"]["opacity"]
    assert opacity == [min(1, max(0.15, 1 - 2 * d)) for d in distances]
    assert opacity == sorted(opacity, reverse=True) and opacity[0] > opacity[-1]
