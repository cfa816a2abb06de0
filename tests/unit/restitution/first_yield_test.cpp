// First yield of an impact pair (first_yield.hpp): the weaker body yields first, at Thornton's
// velocity.
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

}  // namespace
}  // namespace corlab::restitution
