// Bulk viscosity (bulk_viscosity.hpp) and the stable step (stable_time_step.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/kernels/bulk_viscosity.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "corlab/fem/kernels/stable_time_step.hpp"

namespace corlab::fem {
namespace {

TEST(BulkViscosity, OpposesCompressionAndExpansion) {
  const double rho = 7850.0, c = 6000.0, len = 2.5e-4, b1 = 0.06, b2 = 1.2;
  const double rate = 1e4;
  const double s_c = bulk_viscous_stress(-rate, rho, c, len, b1, b2);
  const double s_e = bulk_viscous_stress(rate, rho, c, len, b1, b2);
  // Compression: compressive (negative) mean stress with linear + quadratic parts.
  EXPECT_NEAR(s_c, -(b1 * rho * c * len * rate + rho * b2 * b2 * len * len * rate * rate),
              1e-9 * std::abs(s_c));
  // Expansion: linear part only, tensile.
  EXPECT_NEAR(s_e, b1 * rho * c * len * rate, 1e-9 * s_e);
  // Dissipation s * rate >= 0 both ways.
  EXPECT_GT(s_c * -rate, 0.0);
  EXPECT_GT(s_e * rate, 0.0);
  EXPECT_EQ(bulk_viscous_stress(0.0, rho, c, len, b1, b2), 0.0);
}

TEST(BulkViscosity, DampingReducesTheStableStep) {
  const double xi = bulk_viscous_damping_ratio(0.0, 6000.0, 1e-3, 0.06, 1.2);
  EXPECT_DOUBLE_EQ(xi, 0.06);
  EXPECT_NEAR(element_stable_time_step(1e-3, 6000.0, xi),
              1e-3 / 6000.0 * (std::sqrt(1.0 + 0.0036) - 0.06), 1e-20);
  EXPECT_GT(bulk_viscous_damping_ratio(-1e4, 6000.0, 1e-3, 0.06, 1.2), xi);
}

TEST(StableTimeStep, SquareElementLengthIsTheLatticeLimit) {
  // Square of side h far from the axis: L = h / sqrt(2) (hoop term negligible).
  const double h = 1e-3, r0 = 1.0;
  const double r[4] = {r0, r0 + h, r0 + h, r0};
  const double z[4] = {0.0, 0.0, h, h};
  const Quad4Geometry g = quad4_geometry(r, z);
  EXPECT_NEAR(characteristic_length(g), h / std::sqrt(2.0), 1e-6 * h);
  // Next to the axis the hoop stiffness shortens it.
  const double ra[4] = {0.0, h, h, 0.0};
  EXPECT_LT(characteristic_length(quad4_geometry(ra, z)), 0.99 * h / std::sqrt(2.0));
}

}  // namespace
}  // namespace corlab::fem
