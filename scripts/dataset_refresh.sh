#!/usr/bin/env bash
# Refreshes the published dataset and corlab's model from a dataset sweep directory:
#   scripts/dataset_refresh.sh out/dataset
# exports data/fe_restitution/ (corlab dataset export), refits corlab2026 (model_fit.json, which
# the build turns into the library's coefficients: the rebuild below picks them up) and writes the
# model scores (model_scores.json, docs/img/dataset_model_errors.png). Needs build/ (make build).
set -euo pipefail
sweep=${1:?usage: scripts/dataset_refresh.sh SWEEP_DIR}
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
export PYTHONPATH=$root/build/python
cmake --build build --target corlab _core >/dev/null
build/bin/corlab dataset export "$sweep" --out data/fe_restitution
/usr/bin/python3 -m corlab.model_fit data/fe_restitution/dataset.csv \
  --out data/fe_restitution/model_fit.json
cmake --build build --target corlab _core >/dev/null
/usr/bin/python3 -m corlab.dataset data/fe_restitution/dataset.csv \
  --out data/fe_restitution/model_scores.json --figure docs/img/dataset_model_errors.png \
  --markdown data/fe_restitution/model_scores.md
