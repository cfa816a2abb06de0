"""Shared fixtures of the Python tests."""
import os

import pytest


@pytest.fixture
def corlab_bin():
    """The path of the built `corlab` CLI, from $CORLAB_BIN (`make test-python` sets it).

    A test that runs the CLI fails, never skips, when it is missing: a skipped CLI test would
    leave the CLI untested without anyone seeing it."""
    path = os.environ.get("CORLAB_BIN", "")
    if not path:
        pytest.fail("CORLAB_BIN is not set: this test runs the corlab CLI; set CORLAB_BIN to the"
                    " built binary (make test-python sets it to build/bin/corlab)", pytrace=False)
    if not (os.path.isfile(path) and os.access(path, os.X_OK)):
        pytest.fail(f"CORLAB_BIN = {path!r} is not an executable file; build it (make build) or"
                    " point CORLAB_BIN at the built corlab binary", pytrace=False)
    return path
