"""`make explorer` needs only what the page is built from (docs/user/explorer.md): emscripten,
plotly.js, the header-only libraries and GSL's source; no DEM code and no browser (those are
`make test`'s). Read from `make -n`, which prints what the target would run without running it."""
# SPDX-License-Identifier: BSD-3-Clause
import pathlib
import subprocess

ROOT = pathlib.Path(__file__).resolve().parents[2]


def dry_run(target, build_dir):
    done = subprocess.run(["make", "-n", "--no-print-directory", "-C", str(ROOT), target,
                           f"BUILD_DIR={build_dir}"], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_make_explorer_installs_no_dem_code_and_no_browser(tmp_path):
    commands = dry_run("explorer", tmp_path / "build")
    for needed in ("emscripten", "python3-plotly", "source gsl", "emcmake cmake -S explorer"):
        assert needed in commands, needed
    for unneeded in ("lammps", "liggghts", "yade", "chromium", "selenium", "lintian"):
        assert unneeded not in commands, unneeded


def test_make_test_still_installs_the_browser_for_the_browser_tests(tmp_path):
    commands = dry_run("deps-test", tmp_path / "build")
    for needed in ("chromium", "chromium-driver", "python3-selenium", "emscripten"):
        assert needed in commands, needed
