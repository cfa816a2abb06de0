"""The package's type stubs (_core.pyi, dem.pyi, written by python/stubgen.py at build time) as a
type checker reads them: mypy accepts the README's Python example and rejects wrong calls."""
# SPDX-License-Identifier: BSD-3-Clause
import re
import subprocess
import sys
import textwrap
from pathlib import Path

import corlab

PACKAGE_PARENT = Path(corlab.__file__).resolve().parent.parent

README = Path(__file__).resolve().parents[2] / "README.md"

# Beyond the README's example: the DEM submodule and a few declared types.
MORE = """
    import corlab.dem
    from corlab.dem import laws
    one: float = corlab.predict("corlab2026", al, steel, 2.0)
    modulus: float = al.E + corlab.effective_modulus(al, steel)
    names: list[str] = corlab.material_names() + corlab.dem.chi_formulas()
    version: str = corlab.__version__
    print(e.mean(), r, fit, one, modulus, names, version, laws())
"""


def readme_example():
    return re.search(r"```python\n(.*?)```", README.read_text(), re.S).group(1)


BAD = """
    import corlab
    import corlab.dem
    corlab.material(3)
    corlab.dem.tsuji_alpha("e")
    x: str = corlab.k1(1.0, 2.0, 3.0)
"""


def mypy(tmp_path, source):
    file = tmp_path / "use.py"
    file.write_text(textwrap.dedent(source))
    return subprocess.run(
        [sys.executable, "-m", "mypy", "--no-incremental", "--cache-dir", str(tmp_path / "cache"),
         str(file)],
        capture_output=True, text=True, env={"MYPYPATH": str(PACKAGE_PARENT), "PATH": "/usr/bin"})


def test_stubs_and_marker_ship_with_the_package():
    for name in ("_core.pyi", "dem.pyi", "py.typed"):
        assert (PACKAGE_PARENT / "corlab" / name).is_file(), name


def test_mypy_accepts_the_readme_example(tmp_path):
    result = mypy(tmp_path, readme_example() + textwrap.dedent(MORE))
    assert result.returncode == 0, result.stdout + result.stderr


def test_mypy_rejects_wrong_calls(tmp_path):
    result = mypy(tmp_path, BAD)
    assert result.returncode == 1, result.stdout + result.stderr
    out = result.stdout
    assert 'Argument 1 to "material" has incompatible type "int"' in out, out
    assert 'Argument 1 to "tsuji_alpha" has incompatible type "str"' in out, out
    assert 'Incompatible types in assignment (expression has type "float"' in out, out
