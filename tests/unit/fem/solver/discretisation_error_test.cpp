// Two-grid GCI and the coarsened companion config (discretisation_error.hpp).
#include "corlab/fem/solver/discretisation_error.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "corlab/core/error.hpp"

namespace corlab::fem {
namespace {

TEST(DiscretisationError, GciIsThreeTimesTheChangeOverThree) {
  // Fs = 3, p = 2, r = 2: GCI = 3 |de| / 3 = |de|; the paper case's (0.5, 0.25) mm pair.
  EXPECT_NEAR(grid_convergence_index(0.5354, 0.5374), 0.0020, 1e-12);
  EXPECT_NEAR(grid_convergence_index(0.5374, 0.5354), 0.0020, 1e-12);
  // ratio 1.5: 3 |de| / (2.25 - 1)
  EXPECT_NEAR(grid_convergence_index(0.5, 0.51, 1.5), 3.0 * 0.01 / 1.25, 1e-12);
  EXPECT_TRUE(std::isnan(grid_convergence_index(0.5, std::nan(""))));
}

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
  c.mesh.h_min = 0.8e-3;  // fast: a few thousand steps; the companion at 1.6 mm < R / 20
  c.mesh.contact_elements = 0.0;
  const ImpactResult r = simulate_with_error_estimate(c);
  ASSERT_EQ(r.status, RunStatus::kSeparated);
  EXPECT_TRUE(std::isfinite(r.e_coarse));
  EXPECT_NE(r.e_coarse, r.e);
  EXPECT_DOUBLE_EQ(r.e_error, std::abs(r.e - r.e_coarse));
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
  c.mesh.h_min = 1.5e-3;  // 2h = 3 mm > R / 20: the companion mesh is refused
  c.mesh.contact_elements = 0.0;
  const ImpactResult r = simulate_with_error_estimate(c);
  EXPECT_EQ(r.status, RunStatus::kSeparated);
  EXPECT_TRUE(std::isfinite(r.e));
  EXPECT_TRUE(std::isnan(r.e_error));
  EXPECT_TRUE(std::isnan(r.e_coarse));
}

}  // namespace
}  // namespace corlab::fem
