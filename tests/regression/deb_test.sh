#!/usr/bin/env bash
# `make deb` and the package's life on this Debian machine: build it with CPack, check it with
# lintian, install it with dpkg (prefix /usr), use it from another directory with no CORLAB_*
# variable and no PYTHONPATH (the CLI, `import corlab, corlab.dem`, the README's C++ example with
# find_package), remove it, check that nothing it installed is left, and purge it (nothing left,
# the loader forgets its libraries). It changes /usr, so it runs only as root and only in CI (CI=true, as .ci/run sets) or with CORLAB_TEST_DEB=1; otherwise it is skipped
# (exit 77). The package's dependencies must be installed (`make` installs them).
# usage: deb_test.sh <build-dir> <source-dir> <work-dir>
# SPDX-License-Identifier: BSD-3-Clause
set -euo pipefail
build=$1 src=$2 work=$3
if [ "$(id -u)" -ne 0 ] || { [ "${CI:-}" != true ] && [ "${CORLAB_TEST_DEB:-}" != 1 ]; }; then
  echo "deb_test: skipped (changes /usr: runs as root with CI=true or CORLAB_TEST_DEB=1)"
  exit 77
fi
if dpkg-query -W -f='${Status}' corlab 2>/dev/null | grep -q "ok installed"; then
  echo "deb_test: a corlab package is installed already; remove it first (dpkg -r corlab)" >&2
  exit 1
fi
rm -rf "$work" && mkdir -p "$work"
(cd "$build" && cpack -G DEB -B "$work/package" >"$work/cpack.log") \
  || { cat "$work/cpack.log" >&2; exit 1; }
deb=$(ls "$work"/package/corlab_*.deb)
dpkg-deb -f "$deb" Depends
# lintian (Debian's package checker, `make deps-test` installs it): no error, and none of the
# warnings the package's layout fixes (packaging/debian/, cmake/CorlabPackage.cmake). The two
# warnings of shipping one package rather than a library, a -dev, ... are expected.
command -v lintian >/dev/null || { echo "deb_test: lintian is not installed (make deps-test)" >&2; exit 1; }
lintian --allow-root "$deb" >"$work/lintian.txt" 2>&1 || true
cat "$work/lintian.txt"
fixed='no-copyright-file|no-changelog|lacks-ldconfig-trigger|python-module-in-wrong-location'
fixed+='|no-manual-page|maintscript-calls-ldconfig|extended-description-line-too-long'
fixed+='|synopsis-too-long|pkg-config-unavailable-for-cross-compilation'
if grep -E "^E: |$fixed" "$work/lintian.txt"; then
  echo "deb_test: lintian found the above in $(basename "$deb")" >&2; exit 1
fi
unexpected=$(grep -E '^W: ' "$work/lintian.txt" \
  | grep -vE 'package-name-doesnt-match-sonames|link-to-shared-library-in-wrong-package' || true)
if [ -n "$unexpected" ]; then echo "deb_test: lintian warnings: $unexpected" >&2; exit 1; fi
# Every path of the package (files and folders) and whether it was there before.
dpkg-deb -c "$deb" | awk '{print substr($6, 2)}' | sed 's:/$::' | grep -v '^$' >"$work/paths"
while read -r p; do [ -e "$p" ] && echo "$p"; done <"$work/paths" >"$work/before"
cleanup() { dpkg -P corlab >/dev/null 2>&1 || true; }
trap cleanup EXIT
dpkg -i "$deb" >"$work/dpkg-i.log" || { cat "$work/dpkg-i.log" >&2; exit 1; }

cd "$work"
env -u PYTHONPATH -u CORLAB_DATA_DIR -u CORLAB_PYTHONPATH bash -c '
  set -euo pipefail
  test "$(command -v corlab)" = /usr/bin/corlab
  corlab materials | grep -c alumina_ma2023 >/dev/null  # -c: no SIGPIPE
  corlab predict --model corlab2026 --sphere alumina_ma2023 --substrate aluminium_ma2023 --velocity 2.5
  /usr/bin/python3 -c "import corlab, corlab.dem; assert corlab.__file__.startswith(\"/usr/lib/\"); print(\"python:\", corlab.__file__, len(corlab.dem.laws()), \"DEM laws\")"'
cmake -S "$src/examples/installed" -B "$work/cmake-build" >/dev/null
cmake --build "$work/cmake-build" >/dev/null
"$work/cmake-build/readme_example" | tee "$work/example.txt"
grep -qxF "data directory: /usr/share/corlab" "$work/example.txt"

trap - EXIT
dpkg -r corlab >"$work/dpkg-r.log" || { cat "$work/dpkg-r.log" >&2; exit 1; }
if grep -q "warning" "$work/dpkg-r.log"; then cat "$work/dpkg-r.log" >&2; exit 1; fi
check_nothing_left() {  # $1: the dpkg command just run
  left=$(while read -r p; do
    [ -e "$p" ] && ! grep -qxF "$p" "$work/before" && echo "$p"; done <"$work/paths" || true)
  if [ -n "$left" ]; then echo "deb_test: left after $1:" >&2; echo "$left" >&2; exit 1; fi
}
check_nothing_left "dpkg -r"
# No conffiles, but the maintainer scripts keep a config-files record until the purge.
dpkg -P corlab >/dev/null
if dpkg-query -W corlab >/dev/null 2>&1; then echo "deb_test: dpkg still knows corlab" >&2; exit 1; fi
check_nothing_left "dpkg -P"
# the library names are gone from the loader's cache (the ldconfig trigger ran on removal)
if /sbin/ldconfig -p | grep -c libcorlab >/dev/null; then
  echo "deb_test: ldconfig still lists libcorlab after the purge" >&2; exit 1
fi
echo "deb_test: $(basename "$deb") installed, used and removed cleanly ($(wc -l <"$work/paths") paths)"
