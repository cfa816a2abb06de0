// find_yield_onset_scaled(): elastic scaling + confirming bracket, with a fake solver whose
// peak stress follows p0 ~ v^(2/5) (optionally with a bias the bracket has to catch).
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "corlab/core/error.hpp"
#include "corlab/materials/material.hpp"
#include "corlab/paper/yield_velocity.hpp"

namespace corlab::study {
namespace {

/// Peak substrate von Mises stress [Pa] = sigma_y (v / onset)^(2/5) x bias(v); plastic above
/// sigma_y; every run stops at maximum compression as asked.
struct FakeSolver {
  double onset = 0.0234;       // [m/s]
  double bias_exponent = 0.0;  // extra v-dependence the scaling does not know about
  int runs = 0;
  fem::ImpactResult operator()(const fem::ImpactConfig& c, const fem::SimulationControl& ctl) {
    ++runs;
    EXPECT_TRUE(ctl.stop_at_max_compression);
    const double v = c.impact.velocity;
    const double sy = 300e6;
    const double vm = sy * std::pow(v / onset, 0.4) * std::pow(v / onset, bias_exponent);
    fem::ImpactResult r;
    r.status = fem::RunStatus::kMaxCompression;
    const bool elastic = !c.substrate.material.yield_stress.has_value();
    r.substrate_von_mises_max = elastic ? vm : std::min(vm, sy);
    r.plastic_strain_max = !elastic && vm > sy ? 1e-2 : 0.0;  // a step at the onset
    return r;
  }
};

fem::ImpactConfig case_300mpa() {
  fem::ImpactConfig c;
  c.substrate.material.yield_stress = 300e6;
  return c;
}

TEST(YieldOnsetScaled, ExactScalingNeedsThreeRuns) {
  FakeSolver solver;
  const auto res = find_yield_onset_scaled(
      case_300mpa(), {},
      [&](const fem::ImpactConfig& c, fem::SimulationControl ctl) { return solver(c, ctl); });
  ASSERT_TRUE(res.bracketed);
  EXPECT_NEAR(res.v_scaled, solver.onset, 1e-12 * solver.onset);
  EXPECT_LE(res.v_elastic, solver.onset);
  EXPECT_GE(res.v_plastic, solver.onset);
  EXPECT_NEAR(res.v_plastic / res.v_elastic, 1.02 * 1.02, 1e-12);
  // The Hertz start (p0 = 1.6 sigma_y) is within 10 % here: one elastic run + two bracket runs.
  EXPECT_EQ(solver.runs, res.probes.size());
  EXPECT_LE(solver.runs, 4);
}

TEST(YieldOnsetScaled, BiasedScalingIsCaughtByTheBracket) {
  FakeSolver solver;
  solver.bias_exponent = 0.05;  // stress grows faster than v^(2/5): the estimate is off
  const auto res = find_yield_onset_scaled(
      case_300mpa(), {},
      [&](const fem::ImpactConfig& c, fem::SimulationControl ctl) { return solver(c, ctl); });
  ASSERT_TRUE(res.bracketed);
  EXPECT_LE(res.v_elastic, solver.onset);
  EXPECT_GE(res.v_plastic, solver.onset);
  EXPECT_LE(res.v_plastic / res.v_elastic, 1.02 * 1.02 * 1.0000001);
}

TEST(YieldOnsetScaled, ResumeUsesCachedProbes) {
  FakeSolver solver;
  std::map<std::pair<bool, double>, OnsetProbe> cache;
  auto run = [&](const fem::ImpactConfig& c, fem::SimulationControl ctl) { return solver(c, ctl); };
  const auto first = find_yield_onset_scaled(case_300mpa(), {}, run, {}, [&](const OnsetProbe& p) {
    cache[{p.elastic_reference, p.velocity}] = p;
  });
  const int runs = solver.runs;
  const auto second = find_yield_onset_scaled(
      case_300mpa(), {}, run, [&](bool elastic, double v) -> std::optional<OnsetProbe> {
        auto it = cache.find({elastic, v});
        if (it == cache.end()) return std::nullopt;
        return it->second;
      });
  EXPECT_EQ(solver.runs, runs);  // nothing re-run
  EXPECT_EQ(second.v_onset, first.v_onset);
}

TEST(YieldOnsetScaled, RejectsAnElasticSubstrateAndBadOptions) {
  fem::ImpactConfig elastic;
  elastic.substrate.material.yield_stress = std::nullopt;
  EXPECT_THROW(find_yield_onset_scaled(elastic, {}), InputError);
  ScaledOnsetOptions o;
  o.bracket = 0.0;
  EXPECT_THROW(find_yield_onset_scaled(case_300mpa(), o), InputError);
}

}  // namespace
}  // namespace corlab::study
