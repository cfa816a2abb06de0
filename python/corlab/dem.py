"""corlab.dem: DEM contact laws calibrated to e or e(v) (SI units), the DEM exports and the impact
integrator (docs/user/dem.md).

The functions are those of the compiled submodule ``corlab._core.dem``; this module makes them a
submodule of the package, so that ``import corlab.dem`` and ``from corlab.dem import laws`` work.
Types: ``dem.pyi`` next to this file.
"""
# SPDX-License-Identifier: BSD-3-Clause
from . import _core

__all__ = sorted(name for name in dir(_core.dem) if not name.startswith("_"))
globals().update({name: getattr(_core.dem, name) for name in __all__})
