#!/usr/bin/env bash
# Fault tests of `corlab sweep` (issue 12 item 6): kill -9 and Ctrl-C (SIGINT) at seeded random
# points, resume until done, and compare with an uninterrupted run: no lost, duplicated or torn
# rows. Also: a second sweep on a busy output directory and a different study into the same
# directory are each refused with one clear line (exit 2); an identical repeated row is dropped on
# resume with a one-line note.
# Usage: sweep_fault_test.sh CORLAB_BIN SPEC WORKDIR [SEED]   (registered in tests/CMakeLists.txt)
# SPDX-License-Identifier: BSD-3-Clause
set -uo pipefail
corlab=$1 spec=$2 work=$3
RANDOM=${4:-12}  # seeded: the kill times are the same on every run of the test
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

t0=$(date +%s%N)
"$corlab" sweep "$spec" --out "$work/ref" --jobs 2 --quiet 2> "$work/ref.err" ||
  fail "reference sweep: $(cat "$work/ref.err")"
ref_ms=$((($(date +%s%N) - t0) / 1000000))  # kill times are fractions of this (load-independent)
total=$(($(wc -l < "$work/ref/results.csv") - 1))
[ "$total" -ge 6 ] || fail "reference has $total rows"

# every_line_whole CSV: each complete line has the header's number of fields (no torn rows).
every_line_whole() {
  python3 - "$1" <<'PY' || fail "torn row in $1"
import csv, sys
with open(sys.argv[1], newline="") as f:
    text = f.read()
lines = text.split("\n")
complete = lines[:-1]  # the part after the last newline may be a partial line of a killed write
rows = list(csv.reader(complete))
assert all(len(r) == len(rows[0]) for r in rows), "field counts differ"
PY
}

# interrupt SIGNAL EXPECTED_RC DIR: start, wait a random 5-60 % of the reference run's time, send
# SIGNAL; repeat until a run finishes on its own (at most 25 tries), then finish, and compare with
# the reference.
interrupt() {
  local sig=$1 expected=$2 dir=$3 kills=0 rc=0 tries rows=0
  for tries in $(seq 1 25); do
    "$corlab" sweep "$spec" --out "$dir" --jobs 2 --quiet 2>> "$dir.err" &
    local pid=$!
    local ms=$((ref_ms * (5 + RANDOM % 56) / 100))
    sleep "$(printf '%d.%03d' $((ms / 1000)) $((ms % 1000)))"
    kill "-$sig" "$pid" 2> /dev/null && kills=$((kills + 1))
    wait "$pid"
    rc=$?
    [ $rc -eq 0 ] && break
    [ $rc -eq "$expected" ] || fail "$sig: exit $rc, expected $expected or 0: $(tail -2 "$dir.err")"
    [ -f "$dir/results.csv" ] && every_line_whole "$dir/results.csv" &&
      rows=$(($(wc -l < "$dir/results.csv") - 1))
  done
  [ "$rows" -ge 1 ] || fail "$sig: no interrupted run had finished a row (kills too early)"
  # Finish without interruption (whatever the kills left), then a rerun must find nothing to do.
  "$corlab" sweep "$spec" --out "$dir" --jobs 2 --quiet 2>> "$dir.err" ||
    fail "$sig: final resume failed: $(tail -2 "$dir.err")"
  "$corlab" sweep "$spec" --out "$dir" --jobs 2 --quiet 2> "$dir.last" ||
    fail "$sig: rerun failed: $(cat "$dir.last")"
  grep -q "0 ran (0 failed, 0 not separated), $total already done" "$dir.last" ||
    fail "$sig: a rerun after completion had work left: $(cat "$dir.last")"
  /usr/bin/python3 "$here/sweep_compare.py" "$dir/results.csv" "$work/ref/results.csv" "$total" ||
    fail "$sig: $kills interruptions + resume differ from an uninterrupted run"
  echo "$sig: $kills interruptions in $tries starts ($rows rows kept before the last resume), results" \
    "identical to the uninterrupted run (reference ${ref_ms} ms)"
}
# Job control on: without it bash starts background jobs with SIGINT ignored, and a Ctrl-C that
# lands before corlab installs its handler would be lost (a terminal's Ctrl-C is not).
set -m
interrupt KILL 137 "$work/kill"
interrupt INT 130 "$work/int"
set +m

# Two sweeps on one directory: the second is refused while the first runs.
rm -rf "$work/busy"
"$corlab" sweep "$spec" --out "$work/busy" --jobs 1 --quiet 2> /dev/null &
first=$!
for _ in $(seq 1 200); do [ -f "$work/busy/.sweep.lock" ] && break; sleep 0.01; done
"$corlab" sweep "$spec" --out "$work/busy" --jobs 1 --quiet 2> "$work/busy.err"
rc=$?
kill -KILL $first 2> /dev/null; wait $first 2> /dev/null
[ $rc -eq 2 ] || fail "second sweep on a busy directory: exit $rc, expected 2"
[ "$(wc -l < "$work/busy.err")" -eq 1 ] &&
  grep -q "must not be in use by another running sweep" "$work/busy.err" ||
  fail "second sweep: $(cat "$work/busy.err")"

# A different study ([base] changed) into the same directory: refused, nothing appended.
sed 's/"mesh.h_max" = 1e-3/"mesh.h_max" = 0.5e-3/' "$spec" > "$work/other_base.toml"
rows_before=$(wc -l < "$work/ref/results.csv")
"$corlab" sweep "$work/other_base.toml" --out "$work/ref" --quiet 2> "$work/other.err"
rc=$?
[ $rc -eq 2 ] && [ "$(wc -l < "$work/other.err")" -eq 1 ] &&
  grep -q "holds study 'fault' with another \[base\]" "$work/other.err" ||
  fail "different [base]: exit $rc: $(cat "$work/other.err")"
[ "$(wc -l < "$work/ref/results.csv")" -eq "$rows_before" ] || fail "rows were appended"
sed 's/^name = "fault"/name = "other"/' "$spec" > "$work/other_name.toml"
"$corlab" sweep "$work/other_name.toml" --out "$work/ref" --quiet 2> "$work/other.err"
[ $? -eq 2 ] && grep -q "holds study 'fault', not 'other'" "$work/other.err" ||
  fail "different study name: $(cat "$work/other.err")"

# A duplicated row noticed on resume: an identical repeat is dropped with a one-line note (the
# results-CSV reader's rule, results_table.hpp); the run goes on with nothing to redo.
tail -n 1 "$work/ref/results.csv" >> "$work/ref/results.csv"
"$corlab" sweep "$spec" --out "$work/ref" --quiet 2> "$work/dup.err"
rc=$?
[ $rc -eq 0 ] && grep -q "dropped 1 repeated row(s) of cases already recorded" "$work/dup.err" &&
  [ "$(tail -n +2 "$work/ref/results.csv" | cut -d, -f1 | sort | uniq -d | wc -l)" -eq 0 ] ||
  fail "duplicated row: exit $rc: $(cat "$work/dup.err")"
# (A repeat with other values is refused: ResultsTable.ARepeatedCaseIsCountedOnceWithANoteOrRefused.)
echo "PASS"
