#!/usr/bin/env bash
# A 2-rank MPI sweep gives the same results.csv as a local one (rows sorted by case_id, timing
# columns excluded), and an MPI sweep resumes after a kill without rerunning finished cases.
# Usage: sweep_mpi_test.sh CORLAB_BIN SPEC WORKDIR   (registered in tests/CMakeLists.txt)
# SPDX-License-Identifier: BSD-3-Clause
set -euo pipefail
corlab=$1 spec=$2 work=$3
here=$(cd "$(dirname "$0")" && pwd)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
rm -rf "$work" && mkdir -p "$work"
total=$("$corlab" sweep "$spec" --dry-run 2>/dev/null | tail -n +2 | wc -l)

"$corlab" sweep "$spec" --out "$work/local" --jobs 2 --quiet
mpirun -n 2 --oversubscribe "$corlab" sweep "$spec" --out "$work/mpi" --quiet 2> "$work/mpi.log"
cat "$work/mpi.log"
grep -q "2 MPI ranks" "$work/mpi.log" || { echo "FAIL: the sweep did not run over 2 ranks"; exit 1; }
/usr/bin/python3 "$here/sweep_compare.py" "$work/local/results.csv" "$work/mpi/results.csv" "$total"

# Kill simulation: keep the header and 2 rows plus half a row, rerun under MPI.
csv=$work/mpi/results.csv
{ head -n 3 "$csv"; sed -n 4p "$csv" | head -c 40; } > "$work/killed.csv"
mv "$work/killed.csv" "$csv"
mpirun -n 2 --oversubscribe "$corlab" sweep "$spec" --out "$work/mpi" --quiet 2> "$work/resume.log"
cat "$work/resume.log"
grep -q "$((total - 2)) ran (0 failed, 0 not separated), 2 already done" "$work/resume.log" ||
  { echo "FAIL: the resumed MPI sweep did not run exactly the $((total - 2)) missing cases"; exit 1; }
/usr/bin/python3 "$here/sweep_compare.py" "$work/local/results.csv" "$csv" "$total"
echo "PASS"
