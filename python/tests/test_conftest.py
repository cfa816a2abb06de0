"""The corlab_bin fixture (conftest.py): a test that needs the CLI fails, not skips, without it."""
# SPDX-License-Identifier: BSD-3-Clause
import os
import pathlib
import shutil
import subprocess
import sys

CONFTEST = pathlib.Path(__file__).with_name("conftest.py")


def run(tmp_path, value):
    """Runs a test that asks for corlab_bin in a child pytest, with CORLAB_BIN = value (None:
    unset); returns its exit status and output."""
    tests = tmp_path / "child"
    tests.mkdir()
    shutil.copy(CONFTEST, tests / "conftest.py")
    (tests / "test_cli.py").write_text(
        "def test_runs_the_cli(corlab_bin):\n    assert corlab_bin\n")
    env = {k: v for k, v in os.environ.items() if k != "CORLAB_BIN"}
    if value is not None:
        env["CORLAB_BIN"] = value
    done = subprocess.run([sys.executable, "-m", "pytest", "-q", "-rA", "-p", "no:cacheprovider",
                           str(tests)], capture_output=True, text=True, env=env, cwd=tmp_path)
    return done.returncode, done.stdout


def test_unset_fails_naming_corlab_bin(tmp_path):
    code, out = run(tmp_path, None)
    assert code == 1, out
    assert "1 error" in out and "skipped" not in out, out
    assert "CORLAB_BIN is not set" in out and "make test-python" in out, out


def test_a_path_that_is_not_an_executable_file_fails(tmp_path):
    text = tmp_path / "corlab"
    text.write_text("not a program")
    for value in (str(text), str(tmp_path), str(tmp_path / "missing")):
        shutil.rmtree(tmp_path / "child", ignore_errors=True)
        code, out = run(tmp_path, value)
        assert code == 1 and "1 error" in out, out
        assert f"CORLAB_BIN = '{value}' is not an executable file" in out, out


def test_an_executable_file_is_returned(tmp_path):
    program = tmp_path / "corlab"
    program.write_text("#!/bin/sh\n")
    program.chmod(0o755)
    code, out = run(tmp_path, str(program))
    assert code == 0 and "1 passed" in out, out
