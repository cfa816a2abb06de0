#!/usr/bin/env bash
# `corlab sweep` from the outside: a bad spec -> exit 2 with one error line; Ctrl-C (SIGINT) ->
# exit 130, finished rows kept, a rerun resumes and completes; --dry-run lists the cases.
# Usage: sweep_cli_test.sh CORLAB_BIN SPEC BAD_SPEC WORKDIR   (registered in tests/CMakeLists.txt)
# SPDX-License-Identifier: BSD-3-Clause
set -uo pipefail
corlab=$1 spec=$2 bad=$3 work=$4
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

# Bad spec: exit 2, exactly one line on stderr, nothing on stdout, nothing written.
"$corlab" sweep "$bad" --out "$work/bad" > "$work/bad.out" 2> "$work/bad.err"
rc=$?
cat "$work/bad.err"
[ $rc -eq 2 ] || fail "bad spec: exit $rc, expected 2"
[ "$(wc -l < "$work/bad.err")" -eq 1 ] || fail "bad spec: expected one error line"
grep -q "^corlab: error: invalid spec .*grid.\"impact.velocity\"\[2\] = -1: must be in (0, 1000\] \[m/s\] .*$" \
  "$work/bad.err" || fail "bad spec: unexpected message"
[ ! -s "$work/bad.out" ] && [ ! -e "$work/bad" ] || fail "bad spec: something was written"

# Dry run.
total=$("$corlab" sweep "$spec" --dry-run 2>/dev/null | tail -n +2 | wc -l)
[ "$total" -gt 2 ] || fail "dry run listed $total cases"

# Ctrl-C after the first finished row (one case at a time). The spec's cases must take long
# enough for the signal to land mid-sweep (fault.toml: 12 cases of ~0.1 s; tiny.toml's whole
# sweep took 0.3 s after the 2026-11-25 mesh changes and could end before the signal).
"$corlab" sweep "$spec" --out "$work/run" --jobs 1 2> "$work/int.err" &
pid=$!
for _ in $(seq 1 600); do
  [ -f "$work/run/results.csv" ] && [ "$(wc -l < "$work/run/results.csv")" -ge 2 ] && break
  sleep 0.05
done
kill -INT $pid
wait $pid
rc=$?
cat "$work/int.err"
[ $rc -eq 130 ] || fail "interrupt: exit $rc, expected 130"
grep -q "cases remain; run the same command again to resume" "$work/int.err" || fail "no resume hint"
done_rows=$(($(wc -l < "$work/run/results.csv") - 1))
[ "$done_rows" -ge 1 ] && [ "$done_rows" -lt "$total" ] || fail "interrupt kept $done_rows rows"

# Rerun: only the missing cases run.
"$corlab" sweep "$spec" --out "$work/run" --jobs 2 --quiet 2> "$work/resume.err"
rc=$?
cat "$work/resume.err"
[ $rc -eq 0 ] || fail "resume: exit $rc"
grep -q "$((total - done_rows)) ran (0 failed, 0 not separated), $done_rows already done" \
  "$work/resume.err" || fail "resume did not run exactly the $((total - done_rows)) missing cases"
"$corlab" sweep "$spec" --out "$work/fresh" --jobs 2 --quiet
/usr/bin/python3 "$here/sweep_compare.py" "$work/fresh/results.csv" "$work/run/results.csv" "$total" ||
  fail "interrupted + resumed sweep differs from an uninterrupted one"
echo "PASS"
