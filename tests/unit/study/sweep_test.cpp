// run_sweep machinery with injected runners (no solver): rows, resume, interruption, failures,
// threads. The end-to-end run with the real solver is tests/regression/sweep_solver_test.cpp.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/study/sweep.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include "corlab/core/error.hpp"
#include "corlab/study/results_table.hpp"
#include "support/scratch_files.hpp"

namespace corlab::study {
namespace {

namespace fs = std::filesystem;

// 2 cases x 2 densities x 3 velocities = 12 runs.
const std::string kSpec = R"(
[study]
name = "fake"
[grid]
"sphere.rho" = [3925.0, 7850.0]
"impact.velocity" = [1.0, 5.0, 20.0]
[[cases]]
"sphere.material" = "alumina_ma2023"
"substrate.material" = "aluminium_ma2023"
[[cases]]
"sphere.material" = "steel_ma2023"
"substrate.material" = "steel_ma2023"
)";

using test::fresh_path;
using test::slurp;
using test::spit;

/// A deterministic stand-in for fem::simulate that counts its calls and the configs it saw.
struct FakeSolver {
  std::atomic<int> calls{0};
  std::mutex mutex;
  std::multiset<double> velocities;
  double fail_at_velocity = -1.0;           ///< throw for this velocity
  double not_separated_at_velocity = -1.0;  ///< separated = false for this velocity
  std::chrono::milliseconds sleep{0};

  CaseRunner runner() {
    return [this](const fem::ImpactConfig& config, const fem::SimulationControl& control) {
      ++calls;
      {
        const std::lock_guard lock(mutex);
        velocities.insert(config.impact.velocity);
      }
      std::this_thread::sleep_for(sleep);
      if (control.cancel != nullptr && control.cancel->load()) {
        throw std::runtime_error("interrupted");
      }
      const double v = config.impact.velocity;
      if (v == fail_at_velocity) throw std::runtime_error("mesh inverted, element 17");
      fem::ImpactResult r;
      r.e = 1.0 / (1.0 + 0.01 * v * config.sphere.material.density / 1000.0);
      r.e_energy = r.e * r.e;
      r.F_max = v * 100.0;
      r.separated = v != not_separated_at_velocity;
      r.status = r.separated ? fem::RunStatus::kSeparated : fem::RunStatus::kNotSeparated;
      r.elements = 100;
      r.steps = 1000;
      r.wall_s = 0.001;
      return r;
    };
  }
};

SweepOptions quiet(FakeSolver& solver, int jobs) {
  SweepOptions options;
  options.jobs = jobs;
  options.progress = false;
  options.runner = solver.runner();
  return options;
}

TEST(Sweep, RunsEveryCaseAndWritesOneRowEach) {
  const SweepSpec spec = parse_sweep_spec(kSpec, "fake.toml");
  const fs::path out = fresh_path("all");
  FakeSolver solver;
  const SweepSummary summary = run_sweep(spec, out, quiet(solver, 2));
  EXPECT_EQ(summary.total, 12);
  EXPECT_EQ(summary.ran, 12);
  EXPECT_EQ(summary.already_done, 0);
  EXPECT_EQ(summary.failed, 0);
  EXPECT_FALSE(summary.interrupted);
  EXPECT_EQ(summary.remaining(), 0);
  EXPECT_EQ(solver.calls.load(), 12);

  const ResultsTable table = read_results(out / "results.csv");
  ASSERT_EQ(table.size(), 12u);
  EXPECT_EQ(table.columns(), results_header(spec.swept_keys()));
  std::set<std::string> ids(table.text("case_id").begin(), table.text("case_id").end());
  std::set<std::string> expected;
  for (const auto& run : spec.expand()) expected.insert(run.id);
  EXPECT_EQ(ids, expected);
  const auto velocity = table.numbers("velocity");
  const auto swept_velocity = table.numbers("impact.velocity");
  const auto force = table.numbers("F_max");
  for (std::size_t i = 0; i < table.size(); ++i) {
    EXPECT_EQ(table.cell(i, "status"), "ok");
    EXPECT_EQ(velocity[i], swept_velocity[i]);
    EXPECT_EQ(force[i], 100.0 * velocity[i]);
  }
  EXPECT_EQ(table.numbers("sphere.rho"), table.numbers("sphere_rho"));
  EXPECT_TRUE(fs::exists(out / "spec.toml"));
  EXPECT_EQ(slurp(out / "spec.toml"), kSpec);
}

TEST(Sweep, RerunOfAFinishedSweepRunsNothing) {
  const SweepSpec spec = parse_sweep_spec(kSpec, "fake.toml");
  const fs::path out = fresh_path("rerun");
  FakeSolver first;
  run_sweep(spec, out, quiet(first, 2));
  const std::string before = slurp(out / "results.csv");
  FakeSolver second;
  const SweepSummary summary = run_sweep(spec, out, quiet(second, 2));
  EXPECT_EQ(second.calls.load(), 0);
  EXPECT_EQ(summary.already_done, 12);
  EXPECT_EQ(summary.ran, 0);
  EXPECT_EQ(slurp(out / "results.csv"), before);
}

TEST(Sweep, ResumesAfterAKillWithoutRerunningFinishedCases) {
  const SweepSpec spec = parse_sweep_spec(kSpec, "fake.toml");
  const fs::path out = fresh_path("resume");
  FakeSolver first;
  run_sweep(spec, out, quiet(first, 1));
  // Simulate a kill: keep the header and 8 rows, then half of the 9th row.
  const std::string full = slurp(out / "results.csv");
  std::vector<std::string> lines;
  std::istringstream in(full);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 13u);
  std::string killed;
  for (std::size_t i = 0; i < 9; ++i) killed += lines[i] + "\n";
  killed += lines[9].substr(0, lines[9].size() / 2);
  spit(out / "results.csv", killed);
  FakeSolver second;
  const SweepSummary summary = run_sweep(spec, out, quiet(second, 2));
  EXPECT_EQ(second.calls.load(), 4) << "only the 3 missing cases and the partial one rerun";
  EXPECT_EQ(summary.already_done, 8);
  EXPECT_EQ(summary.ran, 4);
  const ResultsTable table = read_results(out / "results.csv");
  ASSERT_EQ(table.size(), 12u);
  std::set<std::string> ids(table.text("case_id").begin(), table.text("case_id").end());
  EXPECT_EQ(ids.size(), 12u) << "no duplicate rows";
  // Same content as the uninterrupted run, up to row order.
  std::vector<std::string> sorted_full(lines.begin() + 1, lines.end());
  std::sort(sorted_full.begin(), sorted_full.end());
  std::vector<std::string> sorted_now;
  std::istringstream now(slurp(out / "results.csv"));
  std::string header;
  std::getline(now, header);
  for (std::string line; std::getline(now, line);) sorted_now.push_back(line);
  std::sort(sorted_now.begin(), sorted_now.end());
  EXPECT_EQ(sorted_now, sorted_full);
}

TEST(Sweep, InterruptionKeepsFinishedRowsAndARerunCompletes) {
  const SweepSpec spec = parse_sweep_spec(kSpec, "fake.toml");
  const fs::path out = fresh_path("cancel");
  std::atomic<bool> cancel{false};
  FakeSolver solver;
  solver.sleep = std::chrono::milliseconds(5);
  SweepOptions options = quiet(solver, 2);
  const CaseRunner inner = options.runner;
  std::atomic<int> finished{0};
  options.runner = [&](const fem::ImpactConfig& config, const fem::SimulationControl& control) {
    auto result = inner(config, control);
    if (++finished == 5) cancel.store(true);  // "Ctrl-C" after the 5th finished case
    return result;
  };
  options.cancel = &cancel;
  const SweepSummary summary = run_sweep(spec, out, options);
  EXPECT_TRUE(summary.interrupted);
  EXPECT_GE(summary.ran, 5);
  EXPECT_LT(summary.ran, 12);
  EXPECT_EQ(summary.remaining(), 12 - summary.ran);
  const ResultsTable partial = read_results(out / "results.csv");
  EXPECT_EQ(static_cast<int>(partial.size()), summary.ran) << "every finished case was written";

  FakeSolver rest;
  const SweepSummary resumed = run_sweep(spec, out, quiet(rest, 2));
  EXPECT_EQ(rest.calls.load(), 12 - summary.ran);
  EXPECT_EQ(resumed.already_done, summary.ran);
  EXPECT_FALSE(resumed.interrupted);
  EXPECT_EQ(read_results(out / "results.csv").size(), 12u);
}

TEST(Sweep, FailedCasesAreRecordedAndDoNotStopTheSweep) {
  const SweepSpec spec = parse_sweep_spec(kSpec, "fake.toml");
  const fs::path out = fresh_path("failed");
  FakeSolver solver;
  solver.fail_at_velocity = 5.0;
  solver.not_separated_at_velocity = 20.0;
  const SweepSummary summary = run_sweep(spec, out, quiet(solver, 2));
  EXPECT_EQ(summary.ran, 12);
  EXPECT_EQ(summary.failed, 4);
  EXPECT_EQ(summary.not_separated, 4);
  const ResultsTable table = read_results(out / "results.csv");
  ASSERT_EQ(table.size(), 12u);
  const auto failed = table.where("status", "failed");
  ASSERT_EQ(failed.size(), 4u);
  for (const auto& message : failed.text("error")) EXPECT_EQ(message, "mesh inverted, element 17");
  for (const double v : failed.numbers("velocity")) EXPECT_EQ(v, 5.0);
  EXPECT_EQ(table.where("status", "not_separated").size(), 4u);
  EXPECT_EQ(table.where("status", "ok").size(), 4u);

  // A rerun retries only the failed cases and replaces their rows (one row per case).
  FakeSolver fixed;
  const SweepSummary retry = run_sweep(spec, out, quiet(fixed, 2));
  EXPECT_EQ(fixed.calls.load(), 4);
  EXPECT_EQ(fixed.velocities, (std::multiset<double>{5.0, 5.0, 5.0, 5.0}));
  EXPECT_EQ(retry.already_done, 8);
  EXPECT_EQ(retry.failed, 0);
  const ResultsTable after = read_results(out / "results.csv");
  EXPECT_EQ(after.size(), 12u);
  EXPECT_EQ(after.where("status", "failed").size(), 0u);
}

TEST(Sweep, ManyThreadsNeverInterleaveRows) {
  const std::string spec_text = R"(
[study]
name = "many"
[grid]
"impact.velocity" = [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16]
"sphere.rho" = [1000, 2000, 3000, 4000, 5000]
)";
  const SweepSpec spec = parse_sweep_spec(spec_text, "many.toml");
  const fs::path out = fresh_path("threads");
  FakeSolver solver;
  const SweepSummary summary = run_sweep(spec, out, quiet(solver, 8));
  EXPECT_EQ(summary.ran, 80);
  EXPECT_EQ(summary.workers, 8);
  const ResultsTable table = read_results(out / "results.csv");  // throws on a mangled row
  EXPECT_EQ(table.size(), 80u);
}

TEST(Sweep, RefusesAResultsTableOfAnotherSpec) {
  const fs::path out = fresh_path("other");
  FakeSolver solver;
  run_sweep(parse_sweep_spec(kSpec, "fake.toml"), out, quiet(solver, 1));
  const SweepSpec other =
      parse_sweep_spec("[study]\nname = \"o\"\n[grid]\n\"mesh.h_min\" = [1e-3]\n", "other.toml");
  EXPECT_THROW(run_sweep(other, out, quiet(solver, 1)), InputError);
  EXPECT_THROW(run_sweep(other, "/proc/no/such/dir", quiet(solver, 1)), InputError);
}

TEST(Sweep, TwoSweepsCannotShareADirectoryAtOnce) {
  const SweepSpec spec = parse_sweep_spec(kSpec, "fake.toml");
  const fs::path out = fresh_path("lock");
  std::atomic<bool> release{false};
  std::atomic<bool> started{false};
  SweepOptions slow;
  slow.jobs = 1;
  slow.progress = false;
  slow.runner = [&](const fem::ImpactConfig&, const fem::SimulationControl&) {
    started = true;
    while (!release) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    fem::ImpactResult r;
    r.separated = true;
    r.status = fem::RunStatus::kSeparated;
    return r;
  };
  std::thread first([&] { run_sweep(spec, out, slow); });
  while (!started) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  FakeSolver solver;
  EXPECT_THROW(run_sweep(spec, out, quiet(solver, 1)), InputError);
  release = true;
  first.join();
  EXPECT_EQ(solver.calls.load(), 0);
}

TEST(Sweep, OnlyRunsTheSelectedCasesAndCountsThemAsTheTotal) {
  const SweepSpec spec = parse_sweep_spec(kSpec, "fake.toml");
  const fs::path out = fresh_path("only");
  FakeSolver solver;
  SweepOptions options = quiet(solver, 1);
  options.only = parse_case_selection("0,2-3,11,3,0", spec.run_count(), "--only");  // repeats
  const SweepSummary summary = run_sweep(spec, out, options);
  EXPECT_EQ(summary.total, 4);
  EXPECT_EQ(summary.ran, 4);
  const auto runs = spec.expand();
  std::set<std::string> expected{runs[0].id, runs[2].id, runs[3].id, runs[11].id};
  const ResultsTable table = read_results(out / "results.csv");
  EXPECT_EQ(std::set<std::string>(table.text("case_id").begin(), table.text("case_id").end()),
            expected);
  // The whole study afterwards runs the other 8 only.
  FakeSolver rest;
  const SweepSummary all = run_sweep(spec, out, quiet(rest, 1));
  EXPECT_EQ(all.already_done, 4);
  EXPECT_EQ(rest.calls.load(), 8);
}

TEST(Sweep, InOrderRunsTheSpecsOrderElseLongestFirst) {
  const SweepSpec spec = parse_sweep_spec(kSpec, "fake.toml");
  const auto runs = spec.expand();
  for (const bool in_order : {true, false}) {
    const fs::path out = fresh_path(in_order ? "in_order" : "longest_first");
    FakeSolver solver;
    SweepOptions options = quiet(solver, 1);  // one worker: rows in the order run
    options.spec_order = in_order;
    run_sweep(spec, out, options);
    const ResultsTable table = read_results(out / "results.csv");
    const auto& ids = table.text("case_id");
    ASSERT_EQ(ids.size(), runs.size());
    std::vector<std::string> spec_ids;
    for (const auto& r : runs) spec_ids.push_back(r.id);
    // Longest first (estimate_run_cost) puts the slow 1 m/s runs before the spec's 5 m/s one.
    if (in_order) {
      EXPECT_EQ(ids, spec_ids);
    } else {
      EXPECT_NE(ids, spec_ids);
    }
  }
}

TEST(Sweep, CaseSelectionRejectsBadTokensAndIndicesOutOfRange) {
  EXPECT_EQ(parse_case_selection("3,1-2,2", 10, "--only"), (std::vector<std::size_t>{3, 1, 2, 2}));
  for (const char* bad : {"", "1,", "a", "5-2", "10", "-1", "1.5", "0-10"}) {
    try {
      (void)parse_case_selection(bad, 10, "--only");
      ADD_FAILURE() << bad;
    } catch (const InputError& err) {
      EXPECT_NE(std::string(err.what()).find("--only"), std::string::npos) << err.what();
      EXPECT_NE(std::string(err.what()).find("[0, 9]"), std::string::npos) << err.what();
    }
  }
}

}  // namespace
}  // namespace corlab::study
