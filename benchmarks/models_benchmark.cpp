// Model evaluations per second of the analytic CoR models: Model::cor over 10^6 velocities
// (log-spaced 0.01-100 m/s, alumina sphere on aluminium alloy), one benchmark per model.
// Sample run:
//   build-models/bin/models_benchmark --benchmark_min_time=0.5
// SPDX-License-Identifier: BSD-3-Clause
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "corlab/materials/material_database.hpp"
#include "corlab/restitution/registry.hpp"

namespace {

constexpr std::size_t kVelocities = 1000000;

const std::vector<double>& velocities() {
  static const std::vector<double> v = [] {
    std::vector<double> out(kVelocities);
    for (std::size_t i = 0; i < kVelocities; ++i) {
      out[i] = 0.01 * std::pow(1e4, static_cast<double>(i) / (kVelocities - 1));
    }
    return out;
  }();
  return v;
}

void predict(benchmark::State& state, const std::string& name) {
  const auto& db = corlab::MaterialDatabase::builtin();
  const auto model =
      corlab::restitution::make_model(name, db.get("alumina_ma2023"), db.get("aluminium_ma2023"));
  const auto& v = velocities();
  std::vector<double> e(v.size());
  for (auto _ : state) {
    model.cor(v, e);
    benchmark::DoNotOptimize(e.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) *
                          static_cast<int64_t>(v.size()));
}

const bool kRegistered = [] {
  for (const auto& name : corlab::restitution::model_names()) {
    benchmark::RegisterBenchmark(("predict/" + name).c_str(),
                                 [name](benchmark::State& s) { predict(s, name); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
