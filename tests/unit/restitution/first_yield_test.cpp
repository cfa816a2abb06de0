// First yield of an impact pair (first_yield.hpp): the weaker body yields first, at Thornton's
// velocity.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/restitution/first_yield.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "corlab/materials/material.hpp"

namespace corlab::restitution {
namespace {

TEST(FirstYield, WeakerBodyYieldsFirstAtThorntonsVelocity) {
  Material sphere{.name = "s",
                  .youngs_modulus = 100e9,
                  .poisson_ratio = 0.25,
                  .density = 5000.0,
                  .yield_stress = std::nullopt,
                  .hardening_modulus = 0.0,
                  .source = ""};
  Material substrate{.name = "b",
                     .youngs_modulus = 200e9,
                     .poisson_ratio = 0.35,
                     .density = 7000.0,
                     .yield_stress = 400e6,
                     .hardening_modulus = 0.0,
                     .source = ""};
  const double e_star = effective_modulus(sphere, substrate);
  const double c_b = 1.295 * std::exp(0.736 * 0.35);
  auto y = first_yield(sphere, substrate);  // elastic sphere: the substrate
  EXPECT_FALSE(y.sphere_first);
  EXPECT_DOUBLE_EQ(y.pressure, c_b * 400e6);
  // v_y = sqrt(pi^4/40) sqrt(p^5 / (E*^4 rho_sphere)), written out.
  EXPECT_NEAR(y.velocity,
              std::sqrt(std::pow(M_PI, 4) / 40.0 * std::pow(y.pressure, 5) /
                        (std::pow(e_star, 4) * 5000.0)),
              1e-12 * y.velocity);
  sphere.yield_stress = 300e6;  // C(0.25) 300 MPa < C(0.35) 400 MPa: the sphere first
  y = first_yield(sphere, substrate);
  EXPECT_TRUE(y.sphere_first);
  EXPECT_DOUBLE_EQ(y.pressure, 1.295 * std::exp(0.736 * 0.25) * 300e6);
}

// rho* = 3 m* / (4 pi R*^3): rho1 on a flat, 4 rho of two identical spheres, the same whichever
// body is called 1.
TEST(FirstYield, PairEffectiveDensityLimitsAndSymmetry) {
  EXPECT_DOUBLE_EQ(pair_effective_density(0.0, 7850.0, 3.0), 7850.0);
  EXPECT_DOUBLE_EQ(pair_effective_density(1.0, 7850.0, 1.0), 4.0 * 7850.0);
  const double r = 0.37;
  const double rho1 = 2700.0;
  const double rho2 = 15000.0;
  EXPECT_NEAR(pair_effective_density(r, rho1, rho1 / rho2),
              pair_effective_density(1.0 / r, rho2, rho2 / rho1), 1e-12 * rho1);
}

// Two spheres of different radii and densities first yield at the approach speed whose Hertz
// peak pressure, from R* and m* directly (Johnson 1985 section 11.4), is C(nu) sigma_y.
TEST(FirstYield, PairYieldsWhereItsHertzPressureReachesTheLimit) {
  const Material sphere{.name = "s",
                        .youngs_modulus = 600e9,
                        .poisson_ratio = 0.24,
                        .density = 15000.0,
                        .yield_stress = std::nullopt,
                        .hardening_modulus = 0.0,
                        .source = ""};
  const Material other{.name = "b",
                       .youngs_modulus = 70e9,
                       .poisson_ratio = 0.33,
                       .density = 2700.0,
                       .yield_stress = 100e6,
                       .hardening_modulus = 0.0,
                       .source = ""};
  const double r1 = 2e-3;
  const double r2 = 5e-3;
  const double m1 = 4.0 / 3.0 * M_PI * r1 * r1 * r1 * sphere.density;
  const double m2 = 4.0 / 3.0 * M_PI * r2 * r2 * r2 * other.density;
  const double m = m1 * m2 / (m1 + m2);
  const double radius = r1 * r2 / (r1 + r2);
  const double rho =
      pair_effective_density(r1 / r2, sphere.density, sphere.density / other.density);
  EXPECT_NEAR(rho, 3.0 * m / (4.0 * M_PI * std::pow(radius, 3)), 1e-12 * rho);
  const FirstYield y = first_yield(sphere, other, rho);
  const double e_star = effective_modulus(sphere, other);
  const double v = y.velocity;
  const double delta = std::pow(15.0 * m * v * v / (16.0 * e_star * std::sqrt(radius)), 0.4);
  const double p0 = 2.0 * e_star / M_PI * std::sqrt(delta / radius);
  EXPECT_NEAR(p0 / y.pressure, 1.0, 1e-12);
}

}  // namespace
}  // namespace corlab::restitution
