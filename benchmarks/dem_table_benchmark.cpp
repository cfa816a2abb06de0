// Evaluations per second of the DEM lookup tables (dem/uniform_table.hpp): e(v) of thornton1997
// (alumina on aluminium, 1024 points on 0.1-10 m/s) and chi(e) (4096 points on 0.05-0.99), each
// over 10^6 query points, and chi(e(v)) chained as corlab_dem_force uses it. Target: >= 1e8/s.
// Sample run:
//   build/bin/dem_table_benchmark --benchmark_min_time=0.5
// SPDX-License-Identifier: BSD-3-Clause
#include <benchmark/benchmark.h>

#include <vector>

#include "corlab/dem/hysteresis_chi.hpp"
#include "corlab/dem/uniform_table.hpp"
#include "corlab/materials/material_database.hpp"
#include "corlab/restitution/registry.hpp"

namespace {

constexpr std::size_t kQueries = 1000000;

std::vector<double> queries(double lo, double hi) {
  std::vector<double> out(kQueries);
  for (std::size_t i = 0; i < kQueries; ++i) {
    // a scrambled order, so that the table index is not predictable
    const std::size_t j = (i * 7919) % kQueries;
    out[i] = lo + (hi - lo) * static_cast<double>(j) / (kQueries - 1);
  }
  return out;
}

corlab::dem::UniformTable restitution_table() {
  const auto& db = corlab::MaterialDatabase::builtin();
  const auto model = corlab::restitution::make_model("thornton1997", db.get("alumina_ma2023"),
                                                     db.get("aluminium_ma2023"));
  return corlab::dem::tabulate([&](double v) { return model.cor(v); }, 0.1, 10.0, 1024);
}

corlab::dem::UniformTable chi_table() {
  return corlab::dem::tabulate([](double e) { return corlab::dem::exact_chi(e); }, 0.05, 0.99,
                               4096);
}

void run(benchmark::State& state, const corlab::dem::UniformTable& table, double lo, double hi) {
  const auto x = queries(lo, hi);
  std::vector<double> y(x.size());
  for (auto _ : state) {
    for (std::size_t i = 0; i < x.size(); ++i) y[i] = table(x[i]);
    benchmark::DoNotOptimize(y.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) *
                          static_cast<int64_t>(x.size()));
}

void BM_RestitutionTable(benchmark::State& state) { run(state, restitution_table(), 0.1, 10.0); }
void BM_ChiTable(benchmark::State& state) { run(state, chi_table(), 0.05, 0.99); }

void BM_ChiOfRestitutionOfSpeed(benchmark::State& state) {
  const auto e_of_v = restitution_table();
  const auto chi_of_e = chi_table();
  const auto x = queries(0.1, 10.0);
  std::vector<double> y(x.size());
  for (auto _ : state) {
    for (std::size_t i = 0; i < x.size(); ++i) y[i] = chi_of_e(e_of_v(x[i]));
    benchmark::DoNotOptimize(y.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) *
                          static_cast<int64_t>(x.size()));
}

BENCHMARK(BM_RestitutionTable)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ChiTable)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ChiOfRestitutionOfSpeed)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
