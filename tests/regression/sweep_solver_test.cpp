// End-to-end sweeps with the real impact solver on a tiny case (tests/data/sweeps/tiny.toml:
// R = 2.5 mm, coarse mesh, 6 runs of about 0.3 s): every case finishes, the rows are physical,
// the solver is deterministic across thread counts, and a cancelled sweep resumes to the same
// table.
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <filesystem>

#include "corlab/fem/solver/discretisation_error.hpp"
#include "corlab/study/results_table.hpp"
#include "corlab/study/sweep.hpp"
#include "support/scratch_files.hpp"

namespace corlab::study {
namespace {

namespace fs = std::filesystem;

const fs::path kSpec = CORLAB_SOURCE_DIR "/tests/data/sweeps/tiny.toml";

using test::fresh_path;

/// The table without the machine-dependent columns (timing_columns()), sorted by case id.
std::vector<std::vector<std::string>> comparable(const fs::path& csv) {
  const ResultsTable table = read_results(csv).sorted_by("case_id");
  const auto& timing = timing_columns();
  std::vector<std::vector<std::string>> rows(table.size());
  for (const auto& column : table.columns()) {
    if (std::find(timing.begin(), timing.end(), column) != timing.end()) continue;
    for (std::size_t r = 0; r < table.size(); ++r) rows[r].push_back(table.cell(r, column));
  }
  return rows;
}

SweepOptions options(int jobs) {
  SweepOptions o;
  o.jobs = jobs;
  o.progress = false;  // production runner: fem::simulate
  return o;
}

TEST(SweepSolver, TinySweepRunsEveryCaseWithPhysicalResults) {
  const SweepSpec spec = load_sweep_spec(kSpec);
  const fs::path out = fresh_path("two_threads");
  const SweepSummary summary = run_sweep(spec, out, options(2));
  EXPECT_EQ(summary.total, 6);
  EXPECT_EQ(summary.ran, 6);
  EXPECT_EQ(summary.failed, 0);
  const ResultsTable table = read_results(out / "results.csv");
  ASSERT_EQ(table.size(), 6u);
  const auto e = table.numbers("e");
  const auto balance = table.numbers("energy_balance_error");
  const auto plastic = table.numbers("energy_dissipated_plastic");
  const auto initial = table.numbers("energy_initial");
  const auto velocity = table.numbers("velocity");
  const auto rho = table.numbers("sphere_rho");
  const auto radius = 2.5e-3;
  const double mass = rho[0] * 4.0 / 3.0 * 3.141592653589793 * radius * radius * radius;
  for (std::size_t i = 0; i < table.size(); ++i) {
    SCOPED_TRACE(table.cell(i, "case_id"));
    EXPECT_EQ(table.cell(i, "status"), "ok") << table.cell(i, "error");
    EXPECT_GT(e[i], 0.0);
    EXPECT_LT(e[i], 1.0);
    EXPECT_LT(std::abs(balance[i]), 0.05);
    EXPECT_GT(plastic[i], 0.0);
    EXPECT_LT(plastic[i], initial[i]);
    EXPECT_NEAR(initial[i], 0.5 * mass * velocity[i] * velocity[i], 0.02 * initial[i]);
    EXPECT_EQ(velocity[i], table.numbers("impact.velocity")[i]);
  }
}

TEST(SweepSolver, OneThreadAndTwoThreadsGiveTheSameTable) {
  const SweepSpec spec = load_sweep_spec(kSpec);
  const fs::path one = fresh_path("one");
  const fs::path two = fresh_path("two");
  run_sweep(spec, one, options(1));
  run_sweep(spec, two, options(2));
  EXPECT_EQ(comparable(one / "results.csv"), comparable(two / "results.csv"));
}

TEST(SweepSolver, ErrorEstimatesOnTheTailsSpareThreadGiveTheSameTable) {
  // Two workers: the one that finds no case left lends its thread to the last cases' companions
  // (SimulationControl::spare_threads); the values must be those of one worker.
  SweepSpec spec = load_sweep_spec(kSpec);
  for (auto& [key, value] : spec.base) {
    if (key == "mesh.h_min") value = "0.0625e-3";  // R / 40: companions at sqrt 2 h and 2h
  }
  const auto with_estimate = [](int jobs) {
    SweepOptions o = options(jobs);
    o.only = {0, 1, 2};  // the 300 MPa cases
    o.runner = [](const fem::ImpactConfig& config, const fem::SimulationControl& control) {
      return fem::simulate_with_error_estimate(config, control);
    };
    return o;
  };
  const fs::path one = fresh_path("estimate_one");
  const fs::path two = fresh_path("estimate_two");
  run_sweep(spec, one, with_estimate(1));
  run_sweep(spec, two, with_estimate(2));
  const auto rows = comparable(one / "results.csv");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows, comparable(two / "results.csv"));
  const ResultsTable table = read_results(two / "results.csv");
  for (const double bar : table.numbers("e_error")) EXPECT_GT(bar, 0.0);  // companions ran
}

TEST(SweepSolver, CancelledSweepKeepsRowsAndResumesToTheSameTable) {
  const SweepSpec spec = load_sweep_spec(kSpec);
  const fs::path reference = fresh_path("reference");
  run_sweep(spec, reference, options(2));

  const fs::path out = fresh_path("cancelled");
  std::atomic<bool> cancel{false};
  std::atomic<int> finished{0};
  SweepOptions first = options(1);
  first.cancel = &cancel;
  first.runner = [&](const fem::ImpactConfig& config, const fem::SimulationControl& control) {
    auto result = fem::simulate(config, control);  // the real solver, cancelled via control
    if (++finished == 2) cancel.store(true);
    return result;
  };
  const SweepSummary interrupted = run_sweep(spec, out, first);
  EXPECT_TRUE(interrupted.interrupted);
  EXPECT_EQ(interrupted.ran, 2);
  EXPECT_EQ(read_results(out / "results.csv").size(), 2u);

  const SweepSummary resumed = run_sweep(spec, out, options(2));
  EXPECT_EQ(resumed.already_done, 2);
  EXPECT_EQ(resumed.ran, 4);
  EXPECT_EQ(comparable(out / "results.csv"), comparable(reference / "results.csv"));
}

}  // namespace
}  // namespace corlab::study
