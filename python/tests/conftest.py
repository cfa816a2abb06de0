"""Shared fixtures of the Python tests."""
# SPDX-License-Identifier: BSD-3-Clause
import os
import subprocess

import pytest

# A tiny Table 2 study for `corlab reproduce --preset coarse` (six runs on a coarse mesh).
TINY_TABLE2_SPEC = """[study]
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


@pytest.fixture
def corlab_bin():
    """The path of the built `corlab` CLI, from $CORLAB_BIN (`make test-python` sets it).

    A test that runs the CLI fails, never skips, when it is missing: a skipped CLI test would
    leave the CLI untested without anyone seeing it."""
    return corlab_bin_path()


@pytest.fixture(scope="session")
def tiny_reproduction(tmp_path_factory):
    """`corlab reproduce --preset coarse` of TINY_TABLE2_SPEC, run once per session and shared
    (test_report.py checks it and its resume, test_browser.py opens its report): the command, the
    first run's CompletedProcess and the output directory."""
    root = tmp_path_factory.mktemp("tiny_reproduction")
    studies = root / "studies" / "coarse"
    studies.mkdir(parents=True)
    (studies / "table2.toml").write_text(TINY_TABLE2_SPEC)
    out = root / "out"
    cmd = [corlab_bin_path(), "reproduce", "--preset", "coarse", "--out", str(out),
           "--studies", str(root / "studies"), "--only", "table2", "--jobs", "2", "--quiet"]
    first = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    return cmd, first, out


def corlab_bin_path():
    """$CORLAB_BIN, checked (the corlab_bin fixture); fails the test when it is not usable."""
    path = os.environ.get("CORLAB_BIN", "")
    if not path:
        pytest.fail("CORLAB_BIN is not set: this test runs the corlab CLI; set CORLAB_BIN to the"
                    " built binary (make test-python sets it to build/bin/corlab)", pytrace=False)
    if not (os.path.isfile(path) and os.access(path, os.X_OK)):
        pytest.fail(f"CORLAB_BIN = {path!r} is not an executable file; build it (make build) or"
                    " point CORLAB_BIN at the built corlab binary", pytrace=False)
    return path
