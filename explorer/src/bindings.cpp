// embind: the explorer's C++ API (explorer_api.hpp) as functions of the WebAssembly module.
// SPDX-License-Identifier: BSD-3-Clause
#include <emscripten/bind.h>

#include "explorer_api.hpp"

EMSCRIPTEN_BINDINGS(corlab_explorer) {
  emscripten::function("catalog", &corlab::explorer::catalog);
  emscripten::function("evaluate", &corlab::explorer::evaluate);
  emscripten::function("demExport", &corlab::explorer::dem_export);
  emscripten::function("loadDataset", &corlab::explorer::load_dataset);
}
