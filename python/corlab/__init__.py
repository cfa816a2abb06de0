"""corlab: coefficient of restitution (CoR) of elastic-plastic impacts, SI units.

The compiled core (`corlab._core`) holds the materials, the analytic CoR models, the explicit
impact solver and the study tools; this package re-exports them. `corlab.dem` (DEM contact laws
and exports) is a submodule, imported with the package. Types: the stubs `_core.pyi`, `dem.pyi`.
"""
# SPDX-License-Identifier: BSD-3-Clause
from ._core import *  # noqa: F401,F403
from ._core import __version__  # noqa: F401
from . import dem  # noqa: F401
