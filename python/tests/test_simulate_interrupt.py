"""corlab.simulate() and corlab.dem.export(model="fe") stop on Ctrl-C: a SIGINT to a Python
process inside a long run raises KeyboardInterrupt promptly, for the 3-D model, the axisymmetric
one (issue 39 item 3) and the FE runs behind a DEM export (issue 40)."""
# SPDX-License-Identifier: BSD-3-Clause
import os
import signal
import subprocess
import sys
import time

import pytest

# A child that says when the run starts, then runs it (minutes undisturbed).
CHILD = """
import sys
import corlab
print("started", flush=True)
{call}
print("finished", flush=True)
"""

# A plain oblique run of the 3-D model on the rigid flat (its default mesh, 44,422 elements: a
# minute or two on one core) and the paper's case on a fine axisymmetric mesh (minutes too).
PLAIN_3D = {"solver.model": "3d", "impact.angle": 40, "contact.friction": 0.1,
            "substrate.shape": "rigid"}
FINE_AXISYMMETRIC = {"mesh.h_min": 0.05e-3, "mesh.contact_elements": 0}
# An elastic wall: the FE runs on a half-space at 9 fit speeds, uncached (tens of seconds).
DEM_FE = ("corlab.dem.export([('alumina_ma2023', 0.001)], wall='E=70e9,nu=0.22,rho=2500', "
          "wall_only=True, model='fe', cache=False)")


@pytest.mark.parametrize("call", ["corlab.simulate(%r)" % PLAIN_3D,
                                  "corlab.simulate(%r)" % FINE_AXISYMMETRIC, DEM_FE],
                         ids=["3d", "axisymmetric", "dem_export_fe"])
def test_sigint_stops_a_long_run_with_keyboard_interrupt(call):
    child = subprocess.Popen(
        [sys.executable, "-c", CHILD.format(call=call)],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=dict(os.environ))
    try:
        assert child.stdout.readline().strip() == "started"
        time.sleep(2.0)  # inside the run: the mesh is built and the time loop going
        assert child.poll() is None, "the run ended before the signal: " + child.stderr.read()
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=30)
        waited = time.monotonic() - sent
    finally:
        if child.poll() is None:
            child.kill()
            child.wait()
    assert child.returncode != 0
    assert "KeyboardInterrupt" in err, err
    assert "finished" not in out
    # The solver polls the flag every few steps and the binding every 0.1 s.
    assert waited < 10.0
