#!/usr/bin/env bash
# `make install` into a temporary prefix, then corlab used from outside the tree as a user would,
# from another directory, with no CORLAB_* variable and the source tree's data hidden behind a
# probe: the installed CLI, the README's C++ example built against the installed package
# (find_package and pkg-config) and `import corlab, corlab.dem` with only the prefix's site
# directory on PYTHONPATH. Every program must read the installed data: a probe material is added
# to the installed materials.toml only, and each of them must list it. Then `make uninstall`
# (scripts/install_prefix.sh) must leave the prefix as it was: the prefix starts with folders and
# files of its own (some of the folders the install writes into, empty or not), and its listing
# after the uninstall must equal the one before the install.
# usage: install_test.sh <build-dir> <source-dir> <work-dir> <python-dir> <lib-dir>
#        (the last two relative to the prefix)
# SPDX-License-Identifier: BSD-3-Clause
set -euo pipefail
build=$1 src=$2 work=$3 pydir=$4 libdir=$5
rm -rf "$work" && mkdir -p "$work/elsewhere"
prefix="$work/prefix"
mkdir -p "$prefix/bin" "$prefix/lib" "$prefix/share/doc/other" "$prefix/include"
echo other >"$prefix/bin/other-tool" && echo other >"$prefix/share/doc/other/README"
listing() { (cd "$prefix" && find . | LC_ALL=C sort); }
listing >"$work/before.txt"
"$src/scripts/install_prefix.sh" install "$build" "$prefix" >/dev/null
unset CORLAB_DATA_DIR CORLAB_PYTHONPATH PYTHONPATH
export LC_ALL=C.UTF-8
data="$prefix/share/corlab"
for f in bin/corlab include/corlab/restitution/registry.hpp include/corlab/corlab_dem.h \
  share/corlab/materials.toml share/corlab/fe_restitution/dataset.csv \
  share/corlab/fe_restitution_pairs/dataset.csv share/corlab/kharaz2001/fe_oblique.csv \
  share/corlab/oblique_studies/steel_pair.csv share/corlab/oblique_studies/alumina_aluminium.csv \
  share/corlab/studies/paper/table2.toml "$libdir/cmake/corlab/corlabConfig.cmake" \
  "$libdir/pkgconfig/corlab.pc" "$libdir/pkgconfig/corlab-cxx.pc" "$pydir/corlab/__init__.py" \
  "$pydir/corlab/dem.py" "$pydir/corlab/_core.pyi" "$pydir/corlab/dem.pyi" "$pydir/corlab/py.typed"; do
  test -e "$prefix/$f" || { echo "install_test: missing $prefix/$f" >&2; exit 1; }
done
printf '\n[install_probe]\nsource = "install_test.sh"\nE = 1.0e9\nnu = 0.3\nrho = 1000.0\n' >>"$data/materials.toml"
cd "$work/elsewhere"

# 1. The program: the same table as the build tree's, the probe listed.
corlab="$prefix/bin/corlab"
predict=(predict --model all --sphere alumina_ma2023 --substrate aluminium_ma2023 --velocity 0.5:8:4)
"$corlab" "${predict[@]}" >installed.txt 2>installed.err
"$build/bin/corlab" "${predict[@]}" >built.txt 2>built.err
cmp installed.txt built.txt && cmp installed.err built.err
"$corlab" materials | grep -c install_probe >/dev/null  # -c reads all: no SIGPIPE under pipefail
if "$build/bin/corlab" materials | grep -c install_probe >/dev/null; then
  echo "install_test: the build tree's corlab read the installed data" >&2; exit 1
fi
# A one-study reproduction: the installed study spec and dataset, the report by the installed
# Python package (found next to bin/, no PYTHONPATH).
"$corlab" reproduce --preset coarse --only verification_hertz --out reproduce --quiet >reproduce.out 2>reproduce.err \
  || { cat reproduce.err >&2; exit 1; }
test -s reproduce/report.html
# the oblique section's figure, from the installed data/kharaz2001
test -s reproduce/figures/kharaz2001.png \
  || { echo "install_test: no oblique figure from the installed data" >&2; exit 1; }
/usr/bin/python3 - reproduce/fit.json "$data" <<'PY'
import json, sys
fit, data = json.load(open(sys.argv[1])), sys.argv[2]
spec = fit["studies"]["verification_hertz"]["spec"]
assert spec == f"{data}/studies/coarse/verification_hertz.toml", spec
assert fit["dataset_dir"] == f"{data}/fe_restitution", fit["dataset_dir"]
PY
grep -qF "PYTHONPATH=$prefix/$pydir " reproduce.err || { cat reproduce.err >&2; exit 1; }

# 2. The README's C++ example, with find_package(corlab) and with pkg-config.
/usr/bin/python3 - "$src/README.md" "$src/examples/installed/main.cpp" <<'PY'
import re, sys
readme, main = (open(p).read() for p in sys.argv[1:])
block = re.search(r"```cpp\n(.*?)```", readme, re.S).group(1)
norm = lambda s: " ".join(s.split())
have = {norm(line) for line in main.splitlines()}
missing = [line for line in block.splitlines() if line.strip() and norm(line) not in have]
sys.exit(f"install_test: README C++ lines not in examples/installed/main.cpp: {missing}" if missing else 0)
PY
cmake -S "$src/examples/installed" -B cmake-build -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build cmake-build >/dev/null
LD_LIBRARY_PATH="$prefix/$libdir" ./cmake-build/readme_example >cmake_example.txt
export PKG_CONFIG_PATH="$prefix/$libdir/pkgconfig"
flags=$(pkg-config --cflags --libs corlab-cxx)
g++ -std=c++20 "$src/examples/installed/main.cpp" $flags -Wl,-rpath,"$prefix/$libdir" -o pkgconfig_example
./pkgconfig_example >pkgconfig_example.txt
cmp cmake_example.txt pkgconfig_example.txt
grep -qxF "data directory: $data" cmake_example.txt \
  || { echo "install_test: the C++ example did not read $data:" >&2; cat cmake_example.txt >&2; exit 1; }
e_cli=$("$corlab" predict --model corlab2026 --sphere alumina_ma2023 --substrate aluminium_ma2023 \
  --velocity 2.5 --format json | /usr/bin/python3 -c "import json,sys; print(repr(json.load(sys.stdin)['models'][0]['e'][0]))")
e_cpp=$(sed -n 's/^e(2.5 m\/s) = //p' cmake_example.txt)
/usr/bin/python3 -c "import sys; a, b = float(sys.argv[1]), float(sys.argv[2]); sys.exit(0 if a == b else f'install_test: C++ e {a} != CLI e {b}')" "$e_cpp" "$e_cli"

# 3. Python with only the prefix's site directory added.
PYTHONPATH="$prefix/$pydir" /usr/bin/python3 - "$prefix" <<'PY'
import sys
import corlab, corlab.dem
from corlab.dem import laws
prefix = sys.argv[1]
assert corlab.__file__.startswith(prefix), corlab.__file__
assert corlab.dem.__file__.startswith(prefix), corlab.dem.__file__
assert "install_probe" in corlab.material_names(), "Python did not read the installed data"
assert laws() and corlab.dem.laws() == laws()
print(f"python: corlab {corlab.__version__} from {corlab.__file__}")
PY

# 4. `make uninstall`: the prefix as it was, also after Python wrote byte-code into the package.
/usr/bin/python3 -m compileall -q "$prefix/$pydir/corlab"
"$src/scripts/install_prefix.sh" uninstall "$build" "$prefix" >/dev/null
listing >"$work/after.txt"
if ! diff "$work/before.txt" "$work/after.txt" >"$work/uninstall.diff"; then
  echo "install_test: the prefix after uninstall differs from before the install:" >&2
  cat "$work/uninstall.diff" >&2; exit 1
fi
echo "install_test: CLI, C++ (find_package, pkg-config: $flags) and Python from $prefix passed;" \
  "uninstall left the prefix as it was ($(wc -l <"$work/before.txt") paths)"
