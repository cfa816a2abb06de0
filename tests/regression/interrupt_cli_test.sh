#!/usr/bin/env bash
# SIGTERM and SIGHUP stop `corlab sweep` and `corlab simulate` like Ctrl-C: one line, finished rows
# kept, exit 128 + signal (143, 129), and a rerun resumes (issue 12: they used to kill silently).
# Usage: interrupt_cli_test.sh CORLAB_BIN SPEC WORKDIR   (registered in tests/CMakeLists.txt with
# fault.toml: 12 runs of a few seconds each, so the signal always finds the sweep running)
# SPDX-License-Identifier: BSD-3-Clause
set -uo pipefail
corlab=$1 spec=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

# Sends `sig` to a one-at-a-time sweep once its first row is on disk; checks exit status and message.
interrupt_sweep() {
  local sig=$1 status=$2 out="$work/$1"
  "$corlab" sweep "$spec" --out "$out" --jobs 1 --quiet 2> "$out.err" &
  local pid=$!
  for _ in $(seq 1 600); do
    [ -f "$out/results.csv" ] && [ "$(wc -l < "$out/results.csv")" -ge 2 ] && break
    sleep 0.05
  done
  kill -s "$sig" $pid
  wait $pid
  local rc=$?
  cat "$out.err"
  # A sweep that ended between two polls (tiny.toml did, on a fast machine) cannot test the signal.
  [ $rc -ne 0 ] || fail "$sig: the sweep ended before the signal (the spec is too fast)"
  [ $rc -eq "$status" ] || fail "$sig: exit $rc, expected $status"
  grep -q "cases remain; run the same command again to resume" "$out.err" || fail "$sig: no message"
  [ "$(wc -l < "$out/results.csv")" -ge 2 ] || fail "$sig: finished rows lost"
  "$corlab" sweep "$spec" --out "$out" --jobs 2 --quiet 2> "$out.resume.err" ||
    fail "$sig: resume failed: $(cat "$out.resume.err")"
}
interrupt_sweep TERM 143
interrupt_sweep HUP 129

# simulate: a run long enough to be interrupted (fine mesh), SIGTERM after it started.
"$corlab" simulate --set mesh.h_min=0.1e-3 --out "$work/sim" --quiet 2> "$work/sim.err" &
pid=$!
sleep 1
kill -TERM $pid
wait $pid
rc=$?
cat "$work/sim.err"
[ $rc -eq 143 ] || fail "simulate SIGTERM: exit $rc, expected 143"
grep -q "^corlab simulate: interrupted (SIGTERM), nothing written$" "$work/sim.err" ||
  fail "simulate SIGTERM: no one-line message"
[ ! -e "$work/sim/summary.json" ] || fail "simulate SIGTERM: summary.json written"
echo "interrupt_cli_test: ok"
