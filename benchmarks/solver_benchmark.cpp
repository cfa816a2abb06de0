// Google Benchmark of the explicit impact solver.
//   BM_PaperCase: the paper's 5 m/s case (Ma et al. 2023, Table 1) on one core; counters
//     elements, steps, element_steps_per_s; the time per iteration is the wall time of one run.
//   BM_ImpactVelocity/v: the same case at v = 0.1 and 70 m/s (the slowest runs of the paper
//     study: a fine contact mesh at low speed, ~30,000 elements at high speed).
//   The context line "isa" names the hot loops' SIMD level (simd_level.hpp: the highest the CPU
//   has, or $CORLAB_SIMD).
//   BM_ElementThroughput/h: the same case cut to a fixed end time (solver.t_max), for the
//     element-loop throughput at several mesh sizes.
//   BM_Subcycling/v/levels: the case at v = 5 and 0.1 m/s (arg 50, 1: v x 10) with
//     solver.subcycling_levels = 0 (off) and 4 (docs/theory/solver.md section 11), mass scaling
//     off; compare the
//     times and the e labels of levels 0 and 4 (element_updates: the element updates done).
//   BM_MassScaling/v/F: the case at v = 0.1 and 0.02 m/s (arg: v in mm/s; 0.02 m/s is a
//     yield-onset probe's speed) with solver.mass_scaling_max = 1 (off) and 8 (the default;
//     docs/theory/solver.md section 12); compare the times and the e labels.
// element_steps_per_s counts elements x base steps (what a run without subcycling would update).
//   BM_HexThroughput/angle: the 3-D model (solver.model = 3d) on the Kharaz et al. (2001) case
//     (docs/theory/solver3d.md: alumina on glass, 3.9 m/s, mu 0.092, 3 elements across the
//     contact radius, h_max 0.5 mm; 43,500 elements) cut to its first 4 us of contact (about
//     2,400 steps, so that building the mesh and model is a small part), for the hex element
//     loop's throughput (element_steps_per_s, per CPU second: the machines are
//     shared). A run that ends before that time limit fails the benchmark (SkipWithError): it
//     would measure a few steps, not the kernel.
//   BM_HexKharaz/angle: the same case run to the rebound (one iteration: minutes); fails unless
//     it rebounds.
// Sample run: ./build-solver/bin/solver_benchmark --benchmark_filter=PaperCase
// SPDX-License-Identifier: BSD-3-Clause
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <string>
#include <utility>

#include "corlab/fem/mesh/mesh_generator.hpp"
#include "corlab/fem/solver/explicit_solver.hpp"
#include "corlab/fem/solver/simd_level.hpp"
#include "corlab/fem/solver/simulate.hpp"

namespace {

using corlab::fem::ImpactConfig;
using corlab::fem::ImpactResult;

/// The elements, steps and element-steps/s counters of a run of `elements` x `steps`.
void step_counters(benchmark::State& state, int elements, long long steps) {
  state.counters["elements"] = elements;
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["element_steps_per_s"] =
      benchmark::Counter(static_cast<double>(elements) * static_cast<double>(steps) *
                             static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}

/// Counters of one run; e goes into the label (a user counter is shown with SI prefixes).
void report(benchmark::State& state, const ImpactResult& r) {
  step_counters(state, r.elements, r.steps);
  state.counters["element_updates"] = r.element_steps_per_s * r.wall_s;
  state.SetLabel(fmt::format("e={:.6f}", r.e));
}

/// Times run_impact on `config` (the mesh is built once, not timed) and reports the last run.
/// The loop keeps r alive with DoNotOptimize on a const reference, which only reads it: with the
/// non-const overload of Google Benchmark 1.7.1 ("+m,r" asm operand) r.e read 0 after the loop in
/// this build (GCC 12, -O3, LTO) while every other field was right.
void time_runs(benchmark::State& state, const ImpactConfig& config) {
  const corlab::fem::Mesh mesh = corlab::fem::build_impact_mesh(config);
  ImpactResult r;
  for (auto _ : state) {
    r = corlab::fem::run_impact(config, mesh);
    benchmark::DoNotOptimize(std::as_const(r).e);
  }
  report(state, r);
}

void BM_PaperCase(benchmark::State& state) {
  const ImpactConfig config;
  time_runs(state, config);
}
BENCHMARK(BM_PaperCase)->Unit(benchmark::kSecond)->Iterations(3)->UseRealTime();

void BM_ImpactVelocity(benchmark::State& state) {
  ImpactConfig config;
  config.impact.velocity = static_cast<double>(state.range(0)) / 10.0;
  time_runs(state, config);
}
BENCHMARK(BM_ImpactVelocity)
    ->Arg(1)
    ->Arg(700)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();

void BM_ElementThroughput(benchmark::State& state) {
  ImpactConfig config;
  config.mesh.h_min = static_cast<double>(state.range(0)) * 1e-6;
  config.mesh.contact_elements = 0.0;
  config.solver.t_max = config.impact.gap / config.impact.velocity + 2e-5;
  time_runs(state, config);
}
BENCHMARK(BM_ElementThroughput)->Arg(500)->Arg(250)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Subcycling(benchmark::State& state) {
  ImpactConfig config;
  config.impact.velocity = static_cast<double>(state.range(0)) / 10.0;
  config.solver.subcycling_levels = static_cast<int>(state.range(1));
  config.solver.mass_scaling_max = 1.0;  // subcycling alone (BM_MassScaling: with it)
  time_runs(state, config);
}
BENCHMARK(BM_Subcycling)
    ->Args({50, 0})
    ->Args({50, 4})
    ->Args({1, 0})
    ->Args({1, 4})
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();

void BM_MassScaling(benchmark::State& state) {
  ImpactConfig config;
  config.impact.velocity = static_cast<double>(state.range(0)) / 1000.0;
  config.solver.mass_scaling_max = static_cast<double>(state.range(1));
  time_runs(state, config);
}
BENCHMARK(BM_MassScaling)
    ->Args({100, 1})
    ->Args({100, 8})
    ->Args({20, 1})
    ->Args({20, 8})
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();

/// The Kharaz et al. (2001) oblique case at `angle` [deg] (docs/theory/solver3d.md).
ImpactConfig kharaz_case(double angle) {
  ImpactConfig config;
  config.sphere.material = corlab::Material{};
  config.sphere.material.youngs_modulus = 380e9;
  config.sphere.material.poisson_ratio = 0.23;
  config.sphere.material.density = 4000.0;
  config.sphere.radius = 2.5e-3;
  config.substrate.material = corlab::Material{};
  config.substrate.material.youngs_modulus = 70e9;
  config.substrate.material.poisson_ratio = 0.25;
  config.substrate.material.density = 2500.0;
  config.substrate.radius = 5e-3;
  config.substrate.depth = 5e-3;
  config.impact.velocity = 3.9;
  config.solver.model = corlab::fem::SolverModel::kThreeD;
  config.impact.angle = corlab::fem::PlaneAngle::degrees(angle);
  config.contact.friction = 0.092;
  config.mesh.contact_elements = 3.0;
  config.mesh.h_max = 0.5e-3;
  return config;
}

/// Times simulate() of the 3-D model on `config` (mesh generation included: it is a small part);
/// fails the benchmark when a run ends with another status than `expected`.
void time_hex_runs(benchmark::State& state,
                   const ImpactConfig& config,
                   corlab::fem::RunStatus expected) {
  corlab::fem::ImpactResult r;
  for (auto _ : state) {
    r = corlab::fem::simulate(config);
    benchmark::DoNotOptimize(std::as_const(r).e_n);
    // A run stopped by the time limit must have reached it.
    if (r.status != expected || r.end_time < config.solver.t_max) {
      state.SkipWithError(fmt::format("the case ended early: {} ({}) after {} steps",
                                      corlab::fem::to_string(r.status), r.status_detail, r.steps)
                              .c_str());
      return;
    }
  }
  step_counters(state, r.elements, r.steps);
  state.SetLabel(fmt::format("e_n={:.6f} e_t={:.6f} omega={:.2f}", r.e_n, r.e_t, r.omega));
}

void BM_HexThroughput(benchmark::State& state) {
  ImpactConfig config = kharaz_case(static_cast<double>(state.range(0)));
  // solver.t_max counts from the release: the first 4 us of contact, stopped by the time limit.
  config.solver.t_max = corlab::fem::contact_start_time(config) + 4e-6;
  time_hex_runs(state, config, corlab::fem::RunStatus::kNotSeparated);
}
BENCHMARK(BM_HexThroughput)->Arg(30)->Unit(benchmark::kSecond);

void BM_HexKharaz(benchmark::State& state) {
  time_hex_runs(state, kharaz_case(static_cast<double>(state.range(0))),
                corlab::fem::RunStatus::kSeparated);
}
BENCHMARK(BM_HexKharaz)->Arg(30)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace

int main(int argc, char** argv) {
  benchmark::AddCustomContext("isa",
                              std::string(corlab::fem::to_string(corlab::fem::simd_level())));
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
