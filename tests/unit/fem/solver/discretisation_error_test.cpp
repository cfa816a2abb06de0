// The coarsened companion configs and the run with its error estimate (discretisation_error.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/discretisation_error.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

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
  // The companions at sqrt 2 h and 2h (2 sqrt 2 h = 2.26 mm is beyond R / 20 and left out).
  const double e_sqrt2 = simulate(coarsened(c, std::sqrt(2.0))).e;
  EXPECT_EQ(r.e_coarse, simulate(coarsened(c, 2.0)).e);
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

}  // namespace
}  // namespace corlab::fem
