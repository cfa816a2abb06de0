"""Writes the type stubs of the compiled module next to it: corlab/_core.pyi and corlab/dem.pyi
(PEP 561; the package carries py.typed). Run by the build after every link of corlab._core:

    /usr/bin/python3 python/stubgen.py build/python

The stubs come from the signatures pybind11 writes into every docstring, read by mypy's stubgen
(Debian python3-mypy), so they cannot drift from the bindings.
"""
# SPDX-License-Identifier: BSD-3-Clause
import re
import sys
from pathlib import Path

# pybind11 writes numpy arguments as numpy.ndarray[numpy.float64] or
# numpy.ndarray[numpy.float64[m,n]], which no type checker reads: numpy.typing.NDArray[dtype].
_NDARRAY = re.compile(r"numpy\.ndarray\[(numpy\.\w+)(?:\[[^\]]*\])?\]")


def _typed(stub: Path, extra: str) -> None:
    text = _NDARRAY.sub(r"numpy.typing.NDArray[\1]", stub.read_text())
    if "numpy.typing." in text:
        text = text.replace("import numpy\n", "import numpy\nimport numpy.typing\n", 1)
    stub.write_text(text + extra)


def main(package_parent: Path) -> None:
    sys.path.insert(0, str(package_parent))
    from mypy.stubgenc import (DocstringSignatureGenerator, FallbackSignatureGenerator,
                               generate_stub_for_c_module)
    import corlab._core  # noqa: F401 (pybind11 registers corlab._core.dem in sys.modules)
    generators = [DocstringSignatureGenerator(), FallbackSignatureGenerator()]
    out = package_parent / "corlab"
    # stubgen leaves out dunder attributes: the version string is part of the API.
    for module, stub, extra in (("corlab._core", "_core.pyi", "\n__version__: str\n"),
                                ("corlab._core.dem", "dem.pyi", "")):
        generate_stub_for_c_module(module, str(out / stub), generators)
        _typed(out / stub, extra)
    (out / "py.typed").touch()


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: stubgen.py <folder holding the built package corlab>")
    main(Path(sys.argv[1]))
