// The a-priori costs behind `corlab reproduce`'s progress of the whole reproduction
// (reproduce_progress.cpp): the companions' share, what a resumed study skips, the onset cases.
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <stdexcept>
#include <string>

#include "corlab/fem/solver/discretisation_error.hpp"
#include "corlab/study/sweep.hpp"
#include "paper/reproduce_internal.hpp"
#include "support/scratch_files.hpp"

namespace corlab::study::reproduce_detail {
namespace {

namespace fs = std::filesystem;

// One pair of materials at three velocities, on a coarse mesh (fast to build).
const std::string kSpec = R"(
[study]
name = "costs"
[base]
"sphere.material" = "alumina_ma2023"
"substrate.material" = "aluminium_ma2023"
"mesh.h_min" = 1.0e-3
[grid]
"impact.velocity" = [1.0, 5.0, 20.0]
)";

/// fem::simulate's stand-in: fails at 5 m/s, else a clean rebound.
fem::ImpactResult fake_run(const fem::ImpactConfig& config, const fem::SimulationControl&) {
  if (config.impact.velocity == 5.0) throw std::runtime_error("fake failure");
  fem::ImpactResult r;
  r.e = 0.5;
  r.separated = true;
  r.status = fem::RunStatus::kSeparated;
  return r;
}

TEST(ReproduceProgress, CompanionsAddTheirMeshesCost) {
  double expected = 0.0;
  for (const double r : fem::kErrorBarRatios) expected += 1.0 / (r * r * r);
  EXPECT_DOUBLE_EQ(companion_cost_factor(), expected);
  const SweepSpec spec = parse_sweep_spec(kSpec, "costs.toml");
  const fem::ImpactConfig config = spec.expand().front().config;
  const double alone = case_cost(config, false);
  EXPECT_GT(alone, 0.0);
  EXPECT_DOUBLE_EQ(case_cost(config, true), alone * (1.0 + companion_cost_factor()));
}

TEST(ReproduceProgress, ResumedSweepSkipsItsFinishedCasesButNotItsFailedOnes) {
  const SweepSpec spec = parse_sweep_spec(kSpec, "costs.toml");
  const fs::path dir = test::fresh_path("sweep");
  SweepOptions so;
  so.progress = false;
  so.jobs = 1;
  so.runner = fake_run;
  run_sweep(spec, dir, so);  // 1 and 20 m/s finished, 5 m/s failed

  ReproduceOptions opt;
  const StudyCost cost = study_cost("table2", spec, dir, opt);
  ASSERT_EQ(cost.cases.size(), 3U);
  double finished = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    const double v = cost.cases[i].config.impact.velocity;
    EXPECT_EQ(cost.done[i], v != 5.0) << v;
    EXPECT_DOUBLE_EQ(cost.cost[i], case_cost(cost.cases[i].config, true)) << v;
    if (v != 5.0) finished += cost.cost[i];
  }
  EXPECT_DOUBLE_EQ(cost.skipped(), finished);
  EXPECT_GT(cost.total(), cost.skipped());

  opt.error_estimate = false;
  const StudyCost plain = study_cost("table2", spec, test::fresh_path("nothing"), opt);
  EXPECT_EQ(plain.skipped(), 0.0);
  EXPECT_DOUBLE_EQ(plain.cost[0], case_cost(plain.cases[0].config, false));
}

TEST(ReproduceProgress, HistoryStudyRunIsDoneWithItsSummary) {
  const SweepSpec spec = parse_sweep_spec(kSpec, "costs.toml");
  const fs::path dir = test::fresh_path("history");
  const std::string id = spec.expand()[1].id;
  fs::create_directories(dir / "runs" / id);
  test::spit(dir / "runs" / id / "summary.json", "{}");
  const StudyCost cost = study_cost("verification_mesh", spec, dir, ReproduceOptions{});
  EXPECT_FALSE(cost.done[0]);
  EXPECT_TRUE(cost.done[1]);
  EXPECT_FALSE(cost.done[2]);
  // History runs have no companions.
  EXPECT_DOUBLE_EQ(cost.cost[0], case_cost(cost.cases[0].config, false));
}

TEST(ReproduceProgress, OnsetCaseCostsItsSearchNotItsSpecVelocity) {
  const SweepSpec spec = parse_sweep_spec(kSpec, "costs.toml");
  const StudyCost cost = study_cost(kOnsetStudy, spec, test::fresh_path("onset"), {});
  EXPECT_GT(cost.cost[0], 0.0);
  EXPECT_DOUBLE_EQ(cost.cost[0], cost.cost[2]);  // the search starts from the Hertz onset
  EXPECT_EQ(cost.skipped(), 0.0);
}

TEST(ReproduceProgress, SweptKeyTellsTheCasesApart) {
  const SweepSpec spec = parse_sweep_spec(kSpec, "costs.toml");
  const auto cases = spec.expand();
  std::set<std::string> keys;
  for (const auto& c : cases) keys.insert(swept_key(c.config, spec.swept_keys()));
  EXPECT_EQ(keys.size(), cases.size());
  EXPECT_EQ(swept_key(cases[0].config, spec.swept_keys()),
            swept_key(spec.expand()[0].config, spec.swept_keys()));
}

}  // namespace
}  // namespace corlab::study::reproduce_detail
