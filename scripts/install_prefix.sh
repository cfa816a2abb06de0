#!/usr/bin/env bash
# `make install` and `make uninstall`: cmake --install into a prefix, and its exact undoing.
#   install_prefix.sh install BUILD_DIR PREFIX    installs, and records under
#       BUILD_DIR/install-records/<prefix>/ what it wrote (manifest.txt, cmake's
#       install_manifest.txt) and the folders it created (dirs.txt: those that did not exist)
#   install_prefix.sh uninstall BUILD_DIR PREFIX  removes the files of manifest.txt and the Python
#       byte-code beside them, then the folders of dirs.txt that are left empty, deepest first
# As root, both rerun ldconfig when they installed or removed a shared library. The prefix is left
# as it was before the install (tests/regression/install_test.sh compares its listing).
# SPDX-License-Identifier: BSD-3-Clause
set -euo pipefail
usage="usage: install_prefix.sh install|uninstall BUILD_DIR PREFIX"
action=${1:?$usage} build=${2:?$usage} prefix=${3:?$usage}
prefix=$(realpath -m "$prefix")
records="$build/install-records/$(printf '%s' "$prefix" | tr '/' '%')"
manifest="$records/manifest.txt" dirs="$records/dirs.txt"

refresh_loader() {  # $1: a file list; ldconfig when it names a shared library and we are root
  if grep -q '\.so\(\.[0-9.]*\)\?$' "$1" && [ "$(id -u)" -eq 0 ] && command -v ldconfig >/dev/null
  then ldconfig; fi
}

case "$action" in
  install)
    mkdir -p "$records"
    # The folders a staged install holds, then those of them missing under the prefix.
    stage=$(mktemp -d)
    trap 'rm -rf "$stage"' EXIT
    DESTDIR="$stage" cmake --install "$build" --prefix "$prefix" >/dev/null
    {
      (cd "$stage$prefix" && find . -mindepth 1 -type d | sed 's:^\./::') | while read -r d; do
        [ -e "$prefix/$d" ] || echo "$prefix/$d"
      done
      up=$prefix  # the prefix itself and its parents, where missing
      while [ ! -e "$up" ]; do echo "$up"; up=$(dirname "$up"); done
    } | sort >"$dirs.new"
    # A second install into the same prefix keeps the folders the first one created.
    if [ -f "$dirs" ]; then sort -u "$dirs" "$dirs.new" -o "$dirs.new"; fi
    mv "$dirs.new" "$dirs"
    cmake --install "$build" --prefix "$prefix"
    cp "$build/install_manifest.txt" "$manifest"
    refresh_loader "$manifest"
    ;;
  uninstall)
    [ -f "$manifest" ] || { echo "uninstall: nothing of $build is installed in $prefix" >&2; exit 1; }
    removed=0
    while IFS= read -r f || [ -n "$f" ]; do
      [ -n "$f" ] || continue
      if [ -e "$f" ] || [ -L "$f" ]; then rm -f -- "$f" && removed=$((removed + 1)); fi
      # byte-code Python wrote for an installed module: __pycache__/<name>.*.pyc
      case "$f" in
        *.py) rm -f -- "$(dirname "$f")/__pycache__/$(basename "$f" .py)".*.pyc ;;
      esac
    done <"$manifest"
    if [ -f "$dirs" ]; then
      # deepest first; a folder created by the install goes when only its byte-code cache is left
      sort -r "$dirs" | while IFS= read -r d; do
        if [ -d "$d/__pycache__" ]; then rmdir -- "$d/__pycache__" 2>/dev/null || true; fi
        if [ -d "$d" ] && ! rmdir -- "$d" 2>/dev/null; then
          echo "uninstall: kept $d (not empty)" >&2
        fi
      done
    fi
    refresh_loader "$manifest"
    echo "uninstall: removed $removed files from $prefix"
    rm -rf "$records"
    ;;
  *) echo "install_prefix.sh: unknown action '$action'; $usage" >&2; exit 2 ;;
esac
