"""issue 31 item 9: a signal during `corlab reproduce`'s report step (the Python child) ends it
with 128 + signal, one line and no traceback, the studies kept (SIGTERM was ignored and the report
written with exit 0, SIGHUP exited 0, Ctrl-C exited 1 with a traceback)."""
# SPDX-License-Identifier: BSD-3-Clause
import json
import os
import signal
import subprocess
import time

import pytest

from conftest import TINY_TABLE2_SPEC as TINY_SPEC


@pytest.fixture(scope="module")
def finished_studies(tmp_path_factory):
    """A reproduction whose studies are done (--no-report), and the command that writes its
    report."""
    corlab_bin = os.environ.get("CORLAB_BIN", "")
    if not os.access(corlab_bin, os.X_OK):
        pytest.fail(f"CORLAB_BIN = {corlab_bin!r} is not an executable (conftest.py, corlab_bin)",
                    pytrace=False)
    tmp = tmp_path_factory.mktemp("signals")
    studies = tmp / "studies" / "coarse"
    studies.mkdir(parents=True)
    (studies / "table2.toml").write_text(TINY_SPEC)
    cmd = [corlab_bin, "reproduce", "--preset", "coarse", "--out", str(tmp / "out"),
           "--studies", str(tmp / "studies"), "--only", "table2", "--jobs", "2", "--quiet",
           "--no-error-estimate"]
    done = subprocess.run(cmd + ["--no-report"], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return tmp / "out", cmd


@pytest.mark.parametrize("sig, to_group", [
    (signal.SIGTERM, False), (signal.SIGHUP, False), (signal.SIGINT, True)])
def test_a_signal_during_the_report_ends_with_128_plus_it(finished_studies, sig, to_group):
    out, cmd = finished_studies
    fit_before = json.loads((out / "fit.json").read_text())["studies"]["table2"]
    # A Ctrl-C at a terminal reaches the whole process group: the child too.
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                            start_new_session=True)
    lines = []
    for line in proc.stderr:
        lines.append(line)
        if line.startswith("corlab: report: "):  # the Python child is starting
            break
    time.sleep(0.3)
    if to_group:
        os.killpg(proc.pid, sig)
    else:
        proc.send_signal(sig)
    _, rest = proc.communicate(timeout=60)
    err = "".join(lines) + rest
    assert proc.returncode == 128 + sig, err
    assert "Traceback" not in err and "KeyboardInterrupt" not in err, err
    name = signal.Signals(sig).name
    assert (f"corlab: interrupted ({name}) while writing the report; the studies are kept, rerun "
            "the same command to write it\n") in err
    assert "report written" not in err
    fit_after = json.loads((out / "fit.json").read_text())["studies"]["table2"]
    assert fit_after["runs_on_disk"] == fit_before["runs_on_disk"] == 6
    assert not (out / "report.html.tmp").exists()
