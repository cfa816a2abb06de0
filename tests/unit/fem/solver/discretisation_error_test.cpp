// The coarsened companion configs and the run with its error estimate (discretisation_error.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/discretisation_error.hpp"

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "corlab/core/error.hpp"
#include "corlab/fem/solver/error_bar.hpp"

namespace corlab::fem {
namespace {

TEST(DiscretisationError, CoarsenedDoublesEveryElement) {
  ImpactConfig c;
  c.mesh.h_min = 0.25e-3;
  c.mesh.contact_elements = 12.0;
  c.mesh.h_max = 5e-3;
  c.mesh.growth = 1.2;
  const ImpactConfig k = coarsened(c);
  EXPECT_EQ(k.mesh.h_min, 0.5e-3);
  EXPECT_EQ(k.mesh.contact_elements, 6.0);
  EXPECT_EQ(k.mesh.h_max, 10e-3);
  EXPECT_DOUBLE_EQ(k.mesh.growth, 1.44);  // two layers of 1.2 merged into one
  EXPECT_EQ(k.mesh.refine_factor, c.mesh.refine_factor);
  EXPECT_EQ(k.mesh.refine_depth, c.mesh.refine_depth);
  EXPECT_EQ(k.impact.velocity, c.impact.velocity);
  EXPECT_NO_THROW(validate(k));
  c.mesh.growth = 1.6;  // 2.56 is beyond the key's range: the steepest accepted grading
  EXPECT_EQ(coarsened(c).mesh.growth, MeshConfig::kMaxGrowth);
  EXPECT_NO_THROW(validate(coarsened(c)));
  c.mesh.file = "some.msh";
  EXPECT_THROW(coarsened(c), InputError);
}

TEST(DiscretisationError, EstimateOnACoarseRun) {
  ImpactConfig c;
  c.mesh.h_min = 0.8e-3;  // fast: a few thousand steps; companions up to 1.6 mm < R / 20
  c.mesh.contact_elements = 0.0;
  const ImpactResult r = simulate_with_error_estimate(c);
  ASSERT_EQ(r.status, RunStatus::kSeparated);
  EXPECT_TRUE(std::isfinite(r.e_coarse));
  EXPECT_NE(r.e_coarse, r.e);
  // The companions at sqrt 2 h and 2h (2 sqrt 2 h = 2.26 mm is beyond R / 20 and left out),
  // run for e only.
  SimulationControl e_only;
  e_only.e_only = true;
  const double e_sqrt2 = simulate(coarsened(c, std::sqrt(2.0)), e_only).e;
  EXPECT_EQ(r.e_coarse, simulate(coarsened(c, 2.0), e_only).e);
  const std::array<double, 3> e{r.e, e_sqrt2, r.e_coarse};
  const std::array<double, 3> ratios{1.0, std::sqrt(2.0), 2.0};
  EXPECT_EQ(r.e_error, error_bar(kDefaultErrorBar, e, ratios));
  EXPECT_GT(r.e_error, 0.0);
  EXPECT_TRUE(r.e_error_reason.empty()) << r.e_error_reason;
  const ImpactResult plain = simulate(c);
  EXPECT_EQ(plain.e, r.e);  // the estimate does not change the run itself
  EXPECT_TRUE(std::isnan(plain.e_error));
}

}  // namespace
}  // namespace corlab::fem

namespace corlab::fem {
namespace {

TEST(DiscretisationError, ARunForEOnlyEndsSoonerWithTheSameE) {
  ImpactConfig c;
  c.mesh.h_min = 1.6e-3;  // the 0.8 mm run's 2h companion
  c.mesh.contact_elements = 0.0;
  SimulationControl e_only;
  e_only.e_only = true;
  const ImpactResult full = simulate(c);
  const ImpactResult short_run = simulate(c, e_only);
  ASSERT_EQ(full.status, RunStatus::kSeparated);
  ASSERT_EQ(short_run.status, RunStatus::kSeparated);
  // Nothing acts on the sphere after the last contact: e is final there (round-off apart).
  EXPECT_NEAR(short_run.e, full.e, 1e-12 * full.e);
  EXPECT_EQ(short_run.t_contact, full.t_contact);
  EXPECT_LT(short_run.steps, full.steps);
  EXPECT_LT(short_run.end_time, full.end_time);
}

TEST(DiscretisationError, ASpareThreadRunsTheCompanionsAlongsideWithTheSameResult) {
  ImpactConfig c;
  c.mesh.h_min = 0.8e-3;
  c.mesh.contact_elements = 0.0;
  const ImpactResult alone = simulate_with_error_estimate(c);
  std::atomic<int> spare{1};
  SimulationControl control;
  control.spare_threads = &spare;
  const ImpactResult shared = simulate_with_error_estimate(c, control);
  EXPECT_EQ(shared.e, alone.e);
  EXPECT_EQ(shared.e_coarse, alone.e_coarse);
  EXPECT_EQ(shared.e_error, alone.e_error);
  EXPECT_EQ(spare.load(), 1);  // given back
  std::atomic<int> none{0};
  control.spare_threads = &none;
  EXPECT_EQ(simulate_with_error_estimate(c, control).e_error, alone.e_error);
  EXPECT_EQ(none.load(), 0);
}

TEST(DiscretisationError, NoValidCompanionMeansNoErrorBar) {
  ImpactConfig c;
  c.mesh.h_min = 1.5e-3;  // sqrt 2 h = 2.1 mm > R / 20: every companion mesh is refused
  c.mesh.contact_elements = 0.0;
  const ImpactResult r = simulate_with_error_estimate(c);
  EXPECT_EQ(r.status, RunStatus::kSeparated);
  EXPECT_TRUE(std::isfinite(r.e));
  EXPECT_TRUE(std::isnan(r.e_error));
  EXPECT_TRUE(std::isnan(r.e_coarse));
  EXPECT_NE(r.e_error_reason.find("no companion mesh at 1.41h"), std::string::npos)
      << r.e_error_reason;
}

TEST(DiscretisationError, ThreeDCompanionsKeepTheContactResolved) {
  ImpactConfig c;
  EXPECT_EQ(error_bar_ratios(c).size(), kErrorBarRatios.size());  // axisymmetric: all three
  EXPECT_EQ(error_bar_estimator(c), kDefaultErrorBar);
  c.solver.model = SolverModel::kThreeD;
  c.impact.angle = PlaneAngle::degrees(30.0);
  EXPECT_EQ(error_bar_estimator(c), kErrorBar3dNormal);  // e_n's narrower bar
  c.mesh.h_min = c.mesh.h_max;                           // h = a / contact_elements
  for (const auto& [across, kept] : {std::pair{8.0, 3U}, std::pair{4.0, 3U}, std::pair{3.4, 2U},
                                     std::pair{3.0, 1U}, std::pair{2.5, 0U}}) {
    c.mesh.contact_elements = across;
    const std::vector<double> ratios = error_bar_ratios(c);
    EXPECT_EQ(ratios.size(), kept) << "a/h = " << across;
    for (const double q : ratios) EXPECT_GE(across / q, kMinCompanionContactElements - 1e-9);
  }
  // With no companion left the run has no bar, and says why.
  c.mesh.contact_elements = 2.5;  // a few thousand elements on the rigid flat
  c.substrate.shape = SubstrateShape::kRigid;
  c.impact.velocity = 10.0;  // a ~ R / 10
  c.mesh.growth = 1.6;
  const ImpactResult r = simulate_with_error_estimate(c);
  EXPECT_EQ(r.status, RunStatus::kSeparated);
  EXPECT_TRUE(std::isnan(r.e_error));
  EXPECT_NE(r.e_error_reason.find("fewer than 2 elements across the contact radius"),
            std::string::npos)
      << r.e_error_reason;
}

}  // namespace
}  // namespace corlab::fem
