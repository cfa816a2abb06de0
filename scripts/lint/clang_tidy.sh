#!/usr/bin/env bash
# clang-tidy (.clang-tidy: bugprone, performance, modernize, function size <= 80 lines; warnings
# are errors) on every .cpp under src/, apps/ and python/src/ except those listed in
# clang_tidy_exclude.txt. Needs BUILD_DIR/compile_commands.json (cmake exports it).
# Usage: clang_tidy.sh BUILD_DIR [JOBS]          (`make lint-cpp`)
# SPDX-License-Identifier: BSD-3-Clause
set -euo pipefail
build=${1:?usage: clang_tidy.sh BUILD_DIR [JOBS]} jobs=${2:-2}
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
excluded=$(sed -e 's/#.*//' -e 's/[[:space:]]*$//' scripts/lint/clang_tidy_exclude.txt | grep -v '^$' || true)
files=$(git ls-files 'src/*.cpp' 'apps/*.cpp' 'python/src/*.cpp' | grep -vxF "$excluded" || true)
# Optional targets not configured here (corlab-lammps without liblammps-dev) have no compile
# command: their files are skipped, named.
unbuilt=$(for f in $files; do grep -qF "\"$root/$f\"" "$build/compile_commands.json" || echo "$f"; done)
if [ -n "$unbuilt" ]; then
  echo "clang-tidy: not configured, skipped:" $unbuilt
  files=$(grep -vxF "$unbuilt" <<< "$files" || true)
fi
count=$(wc -w <<< "$files")
echo "clang-tidy: $count files ($(grep -c . <<< "$excluded" || true) excluded, see scripts/lint/clang_tidy_exclude.txt)"
start=$(date +%s)
# The compile commands without GCC's precompiled headers (CORLAB_PRECOMPILE_HEADERS), which clang
# cannot read: each file is checked as it stands, with its own includes.
db=$(mktemp -d)
trap 'rm -rf "$db"' EXIT
sed -E 's# -Winvalid-pch##g; s# -include [^ ]*/cmake_pch\.hxx##g' "$build/compile_commands.json" \
  > "$db/compile_commands.json"
# One clang-tidy per file, JOBS at a time; any warning fails (WarningsAsErrors in .clang-tidy).
printf '%s\n' $files | xargs -P "$jobs" -n 1 clang-tidy -p "$db" --quiet \
  --extra-arg=-Wno-ignored-optimization-argument --extra-arg=-Wno-unknown-pragmas 2>/dev/null
echo "clang-tidy: clean, $(( $(date +%s) - start )) s"
