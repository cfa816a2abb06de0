#!/usr/bin/env bash
# Refreshes the published datasets and corlab's models from dataset sweep directories:
#   scripts/dataset_refresh.sh out/dataset [out/pairs]
# exports data/fe_restitution/ (corlab dataset export), refits corlab2026 (model_fit.json, which
# the build turns into the library's coefficients: the rebuilds below pick them up) and writes the
# model scores (model_scores.json, docs/img/dataset_model_errors.png). With a pair sweep it does
# the same for data/fe_restitution_pairs/ and corlab2026p (fitted to both datasets). Needs build/
# (make build).
# SPDX-License-Identifier: BSD-3-Clause
set -euo pipefail
sweep=${1:?usage: scripts/dataset_refresh.sh SWEEP_DIR [PAIR_SWEEP_DIR]}
pairs=${2:-}
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
export PYTHONPATH=$root/build/python
cmake --build build --target corlab _core >/dev/null
build/bin/corlab dataset export "$sweep" --out data/fe_restitution
/usr/bin/python3 -m corlab.model_fit data/fe_restitution/dataset.csv \
  --out data/fe_restitution/model_fit.json
if [[ -n $pairs ]]; then
  build/bin/corlab dataset export "$pairs" --out data/fe_restitution_pairs
  /usr/bin/python3 -m corlab.model_fit data/fe_restitution/dataset.csv \
    data/fe_restitution_pairs/dataset.csv --model corlab2026p \
    --out data/fe_restitution_pairs/model_fit.json
fi
cmake --build build --target corlab _core >/dev/null
/usr/bin/python3 -m corlab.dataset data/fe_restitution/dataset.csv \
  --out data/fe_restitution/model_scores.json --figure docs/img/dataset_model_errors.png \
  --markdown data/fe_restitution/model_scores.md
/usr/bin/python3 -m corlab.dataset data/fe_restitution_pairs/dataset.csv \
  --out data/fe_restitution_pairs/model_scores.json \
  --markdown data/fe_restitution_pairs/model_scores.md
