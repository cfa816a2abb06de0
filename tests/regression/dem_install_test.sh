#!/usr/bin/env bash
# Installs the DEM component to a temporary prefix, then builds examples/dem_c from outside the
# tree twice: with find_package(corlab) and with pkg-config; both programs must run and pass.
# usage: dem_install_test.sh <build-dir> <source-dir> <work-dir> <lib-dir relative to the prefix>
# SPDX-License-Identifier: BSD-3-Clause
set -euo pipefail
build=$1 src=$2 work=$3 libdir=$4
rm -rf "$work" && mkdir -p "$work"
prefix="$work/prefix"
cmake --install "$build" --prefix "$prefix" --component dem >/dev/null
test -f "$prefix/include/corlab/corlab_dem.h"
cmake -S "$src/examples/dem_c" -B "$work/cmake-build" -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$work/cmake-build" >/dev/null
LD_LIBRARY_PATH="$prefix/$libdir:${LD_LIBRARY_PATH:-}" "$work/cmake-build/dem_c_example"
export PKG_CONFIG_PATH="$prefix/$libdir/pkgconfig"
flags=$(pkg-config --cflags --libs corlab)
cc "$src/examples/dem_c/main.c" $flags -lm -Wl,-rpath,"$prefix/$libdir" -o "$work/pkgconfig_example"
"$work/pkgconfig_example" >/dev/null
echo "dem_install_test: find_package and pkg-config builds passed ($flags)"
