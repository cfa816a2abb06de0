"""The e(v) explorer (`make explorer`: build/explorer/explorer.html) and the coarse reproduction's
report in a real browser: headless Debian chromium driven by selenium (docs/user/explorer.md).

The explorer opens from file:// with the network off and no console error, its e(v) for three
pairs equals `corlab predict` to 1e-12, its DEM fragments are `corlab dem`'s, bad input shows the
CLI's one-line message; the report opens with no console error and every image loaded. A
screenshot of each goes to $CORLAB_ARTEFACTS (`make test` sets build/browser/).

The page and the browser are `make test`'s: a missing one fails these tests, never skips them."""
# SPDX-License-Identifier: BSD-3-Clause
import csv
import json
import os
import pathlib
import shlex
import subprocess
import time

import pytest

CHROMIUM = "/usr/bin/chromium"
CHROMEDRIVER = "/usr/bin/chromedriver"
# Headless, no sandbox (CI runs as root), and nothing that talks to the network by itself.
CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                  "--disable-component-update", "--disable-sync", "--no-first-run",
                  "--disable-dev-shm-usage", "--window-size=1400,1000"]
TOLERANCE = 1e-12  # |e_page - e_cli| and the relative difference of the speeds [-]


def explorer_page():
    """$CORLAB_EXPLORER, else explorer/explorer.html of the build CORLAB_BIN is in; fails the
    test when the page is not there."""
    path = os.environ.get("CORLAB_EXPLORER", "")
    if not path and os.environ.get("CORLAB_BIN"):
        path = str(pathlib.Path(os.environ["CORLAB_BIN"]).parents[1] / "explorer" / "explorer.html")
    if not path or not os.path.isfile(path):
        pytest.fail(f"CORLAB_EXPLORER = {path!r} is not a file: the explorer page (`make explorer`"
                    " builds it)", pytrace=False)
    return pathlib.Path(path)


@pytest.fixture(scope="module")
def browser(tmp_path_factory):
    """Headless chromium with a fresh profile, its console kept (goog:loggingPrefs)."""
    try:
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
    except ImportError as err:
        pytest.fail(f"python3-selenium is missing ({err}): `make deps-test` installs it",
                    pytrace=False)
    for path in (CHROMIUM, CHROMEDRIVER):
        if not os.access(path, os.X_OK):
            pytest.fail(f"{path} is missing: `make deps-test` installs chromium and "
                        "chromium-driver", pytrace=False)
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for flag in CHROMIUM_FLAGS:
        options.add_argument(flag)
    options.add_argument(f"--user-data-dir={tmp_path_factory.mktemp('chromium-profile')}")
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    driver.set_page_load_timeout(60)
    yield driver
    driver.quit()


@pytest.fixture(scope="module")
def artefacts(tmp_path_factory):
    """Where the screenshots go: $CORLAB_ARTEFACTS, else a temporary directory."""
    path = pathlib.Path(os.environ.get("CORLAB_ARTEFACTS") or tmp_path_factory.mktemp("browser"))
    path.mkdir(parents=True, exist_ok=True)
    return path


def wait_for(driver, script, timeout=60.0):
    """Polls a JavaScript expression until it is truthy; its value."""
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        value = driver.execute_script(f"return {script}")
        if value:
            return value
        time.sleep(0.05)
    pytest.fail(f"timed out after {timeout} s waiting for {script}", pytrace=False)


def console_errors(driver):
    """The console's errors since the last call (chromium's SEVERE: errors, CSP violations, failed
    loads, uncaught exceptions)."""
    return [entry for entry in driver.get_log("browser") if entry["level"] == "SEVERE"]


def images(driver):
    """Every <img> of the page: its src and whether it loaded (complete, with a width)."""
    return driver.execute_script(
        "return Array.from(document.images).map(i => [i.src, i.complete && i.naturalWidth > 0])")


def screenshot(driver, path):
    """The whole page (the window grown to its height) as PNG."""
    height = driver.execute_script("return document.documentElement.scrollHeight")
    driver.set_window_size(1400, min(max(height, 1000), 8000))
    assert driver.save_screenshot(str(path)), path
    driver.set_window_size(1400, 1000)


def open_explorer(driver, url=None):
    """Loads the page (or `url`, the page with a fragment) from file:// with the network emulated
    offline, from a blank page (a fresh load even where only the fragment differs); its state
    once ready."""
    page = explorer_page()
    driver.execute_cdp_cmd("Network.enable", {})
    driver.execute_cdp_cmd("Network.emulateNetworkConditions", {
        "offline": True, "latency": 0, "downloadThroughput": -1, "uploadThroughput": -1})
    driver.get("about:blank")
    console_errors(driver)  # start from an empty console
    driver.get(url or page.as_uri())
    wait_for(driver, "window.corlabExplorer && window.corlabExplorer.ready")
    return page_state(driver)


def page_state(driver):
    """window.corlabExplorer: what the page asked the C++ and what it answered."""
    return driver.execute_script("return window.corlabExplorer")


def predict(corlab_bin, request, spacing):
    """`corlab predict --model all` over the page's speed range and radius ratio, as JSON."""
    v = request["velocity"]
    cmd = [corlab_bin, "predict", "--model", "all", "--sphere", request["sphere"], "--substrate",
           request["substrate"], "--velocity", f"{v[0]!r}:{v[-1]!r}:{len(v)}", "--spacing",
           spacing, "--radius-ratio", repr(float(request["radius_ratio"])), "--format", "json"]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def set_field(driver, element_id, text):
    """Types into an input and leaves it (its change event runs the page's update)."""
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys
    field = driver.find_element(By.ID, element_id)
    field.clear()
    field.send_keys(text, Keys.TAB)


def choose(driver, element_id, value):
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import Select
    Select(driver.find_element(By.ID, element_id)).select_by_value(value)


def test_explorer_opens_offline_without_console_errors(browser, artefacts):
    state = open_explorer(browser)
    assert state["error"] in (None, ""), state["error"]
    assert console_errors(browser) == []
    # nothing but the page itself and data: URLs was asked for
    resources = browser.execute_script(
        "return performance.getEntriesByType('resource').map(r => r.name)")
    assert [r for r in resources if not r.startswith(("data:", "blob:"))] == []
    assert all(ok for _, ok in images(browser)), images(browser)
    # the plot is drawn: one trace per model at least, the band and the dataset's runs
    traces = browser.execute_script(  # a model's traces carry its name in meta
        "return document.getElementById('plot').data.map(t => t.meta ? t.meta.model : t.name)")
    names = [m["name"] for m in state["catalog"]["models"]]
    assert set(names) <= set(traces)
    assert "FE dataset, nearest runs" in traces
    assert "corlab2026 95 % prediction interval" in traces
    assert len(state["result"]["nearest"]) == 12
    screenshot(browser, artefacts / "explorer.png")
    assert console_errors(browser) == []


# Four pairs, each set through the page's own inputs: built-in names, a built-in pair with lin
# spacing, custom values in every field (moduli in the page's default units, GPa and MPa), a
# particle pair (radius ratio 0.5: corlab2026p's case).
PAIRS = [
    ({}, {"v-min": "0.1", "v-max": "20", "v-count": "200", "v-spacing": "log"}),
    ({"sphere-name": "steel_ma2023", "substrate-name": "steel_jackson2010"},
     {"v-min": "0.5", "v-max": "50", "v-count": "37", "v-spacing": "lin"}),
    ({"sphere-name": "custom", "sphere-E": "115", "sphere-nu": "0.31", "sphere-rho": "8900",
      "sphere-sy": "250", "sphere-H": "1000", "substrate-name": "custom", "substrate-E": "70",
      "substrate-nu": "0.33", "substrate-rho": "2700", "substrate-sy": "2.75e2",
      "substrate-H": "500"},
     {"v-min": "0.05", "v-max": "100", "v-count": "101", "v-spacing": "log"}),
    ({"sphere-name": "steel_aisi_52100", "substrate-name": "aluminium_6061_t6"},
     {"v-min": "0.2", "v-max": "15", "v-count": "40", "v-spacing": "log", "radius-ratio": "0.5"}),
]
SPECS = [("alumina_ma2023", "aluminium_ma2023"), ("steel_ma2023", "steel_jackson2010"),
         ("E=115e9,nu=0.31,rho=8900,sy=250e6,H=1000e6",
          "E=70e9,nu=0.33,rho=2700,sy=2.75e8,H=500e6"),
         ("steel_aisi_52100", "aluminium_6061_t6")]


@pytest.mark.parametrize("pair", range(len(PAIRS)))
def test_explorer_e_equals_corlab_predict(browser, corlab_bin, pair):
    open_explorer(browser)
    materials, speeds = PAIRS[pair]
    for element_id, value in materials.items():
        if element_id.endswith("-name"):
            choose(browser, element_id, value)
        else:
            set_field(browser, element_id, value)
    for element_id, value in speeds.items():
        if element_id == "v-spacing":
            choose(browser, element_id, value)
        else:
            set_field(browser, element_id, value)
    state = page_state(browser)
    request, result = state["request"], state["result"]
    assert (request["sphere"], request["substrate"]) == SPECS[pair]
    assert len(request["velocity"]) == int(speeds["v-count"])
    assert state["error"] in (None, ""), state["error"]
    assert request["radius_ratio"] == float(speeds.get("radius-ratio", 0))
    cli = predict(corlab_bin, request, speeds["v-spacing"])
    assert cli["radius_ratio"] == request["radius_ratio"]
    assert [m["model"] for m in result["models"]] == [m["model"] for m in cli["models"]]
    assert result["effective_modulus"] == pytest.approx(cli["effective_modulus"], rel=TOLERANCE)
    for page, ref in zip(result["models"], cli["models"]):
        assert page["v_y"] == pytest.approx(ref["v_y"], rel=TOLERANCE), page["model"]
        for v_page, v_cli in zip(result["velocity"], ref["velocity"]):
            assert abs(v_page - v_cli) <= TOLERANCE * v_cli, (page["model"], v_page, v_cli)
        worst = max(abs(a - b) for a, b in zip(page["e"], ref["e"]))
        assert worst <= TOLERANCE, (page["model"], worst)
    assert console_errors(browser) == []


def assert_dem_is_clis(driver, corlab_bin, dem, out):
    """The page's DEM fragments (and those it shows) are what `corlab dem` writes into `out` for
    the command the page shows."""
    assert "error" not in dem, dem
    cmd = shlex.split(dem["command"])
    assert cmd[:2] == ["corlab", "dem"] and cmd[-2:] == ["--out", "dem_export"], cmd
    done = subprocess.run([corlab_bin] + cmd[1:-1] + [str(out)], capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    for name, file in (("LAMMPS", "lammps.in"), ("LIGGGHTS", "liggghts.in"),
                       ("YADE", "yade_fragment.py")):
        assert dem["fragments"][name] == (out / file).read_text(), name
        shown = driver.execute_script(f"return document.getElementById('dem-{name}').textContent")
        assert shown == dem["fragments"][name]
    return cmd


def test_explorer_dem_fragments_are_corlab_dems(browser, corlab_bin, tmp_path):
    state = open_explorer(browser)
    cmd = assert_dem_is_clis(browser, corlab_bin, state["dem"], tmp_path)
    assert "--wall-only" in cmd


def test_explorer_shows_the_clis_message_for_bad_input(browser, corlab_bin):
    open_explorer(browser)
    choose(browser, "sphere-name", "alumina_ma2023")
    set_field(browser, "sphere-nu", "0.7")  # switches the sphere to custom
    state = page_state(browser)
    assert state["request"]["sphere"] == "E=370e9,nu=0.7,rho=3958.226,H=0"
    done = subprocess.run([corlab_bin, "predict", "--model", "all", "--sphere",
                           state["request"]["sphere"], "--substrate", "aluminium_ma2023",
                           "--velocity", "1"], capture_output=True, text=True, timeout=60)
    assert done.returncode == 2
    message = done.stderr.strip().removeprefix("corlab: error: ")
    assert state["error"] == message
    assert browser.execute_script("return document.getElementById('error').textContent") == \
        f"error: {message}"
    assert console_errors(browser) == []


def test_report_opens_with_every_image_loaded(browser, artefacts, tiny_reproduction):
    cmd, first, out = tiny_reproduction
    assert first.returncode == 0, first.stderr
    report = out / "report.html"
    console_errors(browser)
    browser.get(report.as_uri())
    wait_for(browser, "document.readyState === 'complete'")
    found = images(browser)
    figures = sorted((out / "figures").glob("*.png"))
    assert figures and len(found) >= len(figures) > 0
    assert [src for src, ok in found if not ok] == []
    # the summary: right under the title, before the contents, inside the first screen (1000 px),
    # every link landing on a section; it names the runs fit.json counts
    fit = json.loads((out / "fit.json").read_text())
    top, bottom, links, before_toc, text = browser.execute_script(
        "window.scrollTo(0, 0); const g = document.getElementById('at-a-glance');"
        " const r = g.getBoundingClientRect(); return [r.top, r.bottom,"
        " [...g.querySelectorAll('a')].map(a => !!document.getElementById(a.hash.slice(1))),"
        " !!(g.compareDocumentPosition(document.querySelector('nav.toc')) & 4), g.textContent]")
    assert 0 < top < bottom <= 1000, (top, bottom)
    assert len(links) >= 6 and all(links), links
    assert before_toc
    assert f"{fit['studies_total']['runs_on_disk']} finished runs" in text
    # the table of contents: an entry per section, each link landing on its heading
    toc = browser.execute_script(
        "return [...document.querySelectorAll('nav.toc a')].map(a => [a.hash.slice(1),"
        " !!document.getElementById(a.hash.slice(1))]);")
    assert len(toc) == len(browser.find_elements("css selector", "h2")) >= 8
    assert all(ok for _, ok in toc), toc
    browser.find_element("css selector", f'nav.toc a[href="#{toc[-1][0]}"]').click()
    wait_for(browser, f"location.hash === '#{toc[-1][0]}'")
    assert console_errors(browser) == []
    browser.execute_script("window.scrollTo(0, 0)")
    screenshot(browser, artefacts / "report.png")


def test_explorer_nearest_run_of_a_dataset_runs_own_pair_is_that_run(browser):
    """A run's own materials give that run first, at distance 0 and at its own speed (e depends
    on the dimensionless inputs only: the pair's speed of equal k1 is the run's)."""
    data = pathlib.Path(__file__).resolve().parents[2] / "data"
    with open(data / "fe_restitution" / "dataset.csv", newline="") as f:
        run = next(r for r in csv.DictReader(f) if r["sphere_sigma_y"] != "inf")
    open_explorer(browser)
    choose(browser, "sphere-name", "custom")
    choose(browser, "substrate-name", "custom")
    for body in ("sphere", "substrate"):
        for key in ("E", "sy", "H"):  # the dataset's values are in Pa
            choose(browser, f"{body}-{key}-unit", "Pa")
        for key, column in (("E", "E"), ("nu", "nu"), ("rho", "rho"), ("sy", "sigma_y"),
                            ("H", "H")):
            set_field(browser, f"{body}-{key}", run[f"{body}_{column}"])
    set_field(browser, "v-min", "0.01")
    set_field(browser, "v-max", "100")
    state = page_state(browser)
    assert state["error"] in (None, ""), state["error"]
    first = state["result"]["nearest"][0]
    assert first["design_index"] == int(run["design_index"])
    assert first["distance"] <= 1e-12
    assert first["velocity_pair"] == pytest.approx(float(run["velocity"]), rel=1e-12)
    assert first["e"] == float(run["e"]) and first["e_error"] == float(run["e_error"])
