// estimate_run_cost(): the a-priori cost used to schedule sweeps longest first.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/run_cost.hpp"

#include <gtest/gtest.h>

#include "corlab/core/error.hpp"
#include "corlab/fem/mesh/mesh_generator.hpp"
#include "corlab/fem/solver/simulate.hpp"
#include "support/hex_cases.hpp"

namespace corlab::fem {
namespace {

ImpactConfig coarse(double velocity) {
  ImpactConfig c;
  c.mesh.h_min = 1e-3;
  c.impact.velocity = velocity;
  return c;
}

TEST(RunCost, MatchesTheMeshAndGrowsAtLowSpeed) {
  const RunCost fast = estimate_run_cost(coarse(5.0));
  EXPECT_EQ(fast.elements, build_impact_mesh(coarse(5.0)).num_elements());
  EXPECT_GT(fast.time_step, 0.0);
  // Slow impacts last longer (t_c ~ v^(-1/5)) on finer contact meshes (h <= a_max / 12).
  const RunCost slow = estimate_run_cost(coarse(0.1));
  EXPECT_GT(slow.expected_steps, 2.0 * fast.expected_steps);
  EXPECT_GT(slow.element_steps(), fast.element_steps());
}

// The 3-D model's cost is its own hexahedral mesh's (it once came from the axisymmetric mesh,
// 200 times too low): the elements of the run, and steps to within a factor of two of it.
TEST(RunCost, TheThreeDModelCountsItsHexahedra) {
  const ImpactConfig c = test::sliding_on_rigid_flat();
  const RunCost cost = estimate_run_cost(c);
  const ImpactResult run = simulate(c);
  EXPECT_EQ(cost.elements, run.elements);
  EXPECT_NEAR(cost.expected_steps / static_cast<double>(run.steps), 1.0, 0.5);
}

TEST(RunCost, InvalidConfigIsAnInputError) {
  ImpactConfig c = coarse(5.0);
  c.impact.velocity = -1.0;
  EXPECT_THROW(estimate_run_cost(c), InputError);
}

}  // namespace
}  // namespace corlab::fem
