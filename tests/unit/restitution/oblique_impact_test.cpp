// Rigid-body theory of an oblique impact with Coulomb friction (oblique_impact.hpp): the sliding
// identity, the rolling and sticking rebounds, the regimes' meeting point, energy, bad input.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/restitution/oblique_impact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "corlab/core/error.hpp"

namespace corlab::restitution {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

/// A sphere of R = 2.5 mm at speed 3.9 m/s, `angle` from the normal, no spin (Kharaz et al. 2001).
ObliqueIncidence at_angle(double angle_deg) {
  return {.normal_velocity = 3.9 * std::cos(angle_deg * kDeg),
          .tangential_velocity = 3.9 * std::sin(angle_deg * kDeg),
          .spin = 0.0,
          .radius = 2.5e-3};
}

/// Kinetic energy per unit mass, translation and rotation [J/kg].
double energy(double vn, double vt, double spin, double radius, double gyration) {
  return 0.5 * (vn * vn + vt * vt + gyration * radius * radius * spin * spin);
}

TEST(ObliqueImpact, SlidingThroughoutIsTheCoulombIdentity) {
  const ObliqueContact c{.normal_restitution = 0.8, .friction = 0.092};
  const ObliqueIncidence in = at_angle(60.0);
  const ObliqueRebound r = rigid_body_rebound(in, c);
  ASSERT_TRUE(r.slides);
  EXPECT_NEAR(r.tangential_restitution, 1.0 - 0.092 * 1.8 / std::tan(60.0 * kDeg), 1e-14);
  EXPECT_NEAR(r.spin * in.radius, 2.5 * 0.092 * 1.8 * in.normal_velocity, 1e-14);
  EXPECT_NEAR(r.normal_velocity, 0.8 * in.normal_velocity, 1e-15);
  EXPECT_NEAR(std::tan(r.rebound_angle * kDeg), r.tangential_velocity / r.normal_velocity, 1e-12);
}

TEST(ObliqueImpact, StickingWithoutTangentialRestitutionLeavesRolling) {
  // Below the threshold with beta = 0: v_t' = 5/7 v_t and the contact point at rest, u' = 0.
  const ObliqueContact c{.normal_restitution = 0.8, .friction = 0.5};
  const ObliqueIncidence in = at_angle(20.0);
  const ObliqueRebound r = rigid_body_rebound(in, c);
  ASSERT_FALSE(r.slides);
  EXPECT_NEAR(r.tangential_restitution, 5.0 / 7.0, 1e-14);
  EXPECT_NEAR(r.tangential_velocity - in.radius * r.spin, 0.0, 1e-14);
}

TEST(ObliqueImpact, TangentialRestitutionReversesTheContactPoint) {
  // beta = 1 (an elastic tangential spring that gives back all it stored): u' = -u.
  const ObliqueContact c{
      .normal_restitution = 1.0, .friction = 10.0, .tangential_restitution = 1.0};
  const ObliqueIncidence in{
      .normal_velocity = 1.0, .tangential_velocity = 0.3, .spin = 20.0, .radius = 0.01};
  const ObliqueRebound r = rigid_body_rebound(in, c);
  const double u = in.tangential_velocity - in.radius * in.spin;
  EXPECT_NEAR(r.tangential_velocity - in.radius * r.spin, -u, 1e-14);
  // ... and, both restitutions 1, no energy is lost.
  EXPECT_NEAR(energy(r.normal_velocity, r.tangential_velocity, r.spin, in.radius, c.gyration),
              energy(1.0, 0.3, 20.0, 0.01, c.gyration), 1e-14);
}

TEST(ObliqueImpact, TheRegimesMeetAtTheThreshold) {
  const ObliqueContact c{.normal_restitution = 0.6, .friction = 0.2, .tangential_restitution = 0.3};
  const double t = sliding_threshold(c);
  EXPECT_NEAR(t, 3.5 * 0.2 * 1.6 / 1.3, 1e-15);
  const double vn = 2.0;
  auto rebound = [&](double tangent) {
    return rigid_body_rebound(
        {.normal_velocity = vn, .tangential_velocity = tangent * vn, .spin = 0.0, .radius = 0.005},
        c);
  };
  const ObliqueRebound below = rebound(t * (1 - 1e-9));
  const ObliqueRebound above = rebound(t * (1 + 1e-9));
  EXPECT_FALSE(below.slides);
  EXPECT_TRUE(above.slides);
  EXPECT_NEAR(below.tangential_restitution, above.tangential_restitution, 1e-8);
  EXPECT_NEAR(below.spin, above.spin, 1e-6);
}

TEST(ObliqueImpact, NoImpactGainsEnergy) {
  for (const double en : {0.0, 0.5, 1.0}) {
    for (const double mu : {0.0, 0.1, 1.0}) {
      for (const double beta : {-1.0, 0.0, 0.5, 1.0}) {
        for (const double angle : {0.0, 10.0, 45.0, 80.0}) {
          for (const double spin : {-500.0, 0.0, 800.0}) {
            const ObliqueContact c{
                .normal_restitution = en, .friction = mu, .tangential_restitution = beta};
            ObliqueIncidence in = at_angle(angle);
            in.spin = spin;
            const ObliqueRebound r = rigid_body_rebound(in, c);
            EXPECT_LE(energy(r.normal_velocity, r.tangential_velocity, r.spin, in.radius, 0.4),
                      energy(in.normal_velocity, in.tangential_velocity, spin, in.radius, 0.4) *
                          (1 + 1e-14))
                << "e_n " << en << " mu " << mu << " beta " << beta << " angle " << angle
                << " spin " << spin;
          }
        }
      }
    }
  }
}

TEST(ObliqueImpact, ANormalImpactHasNoTangentialResult) {
  const ObliqueRebound r =
      rigid_body_rebound(at_angle(0.0), {.normal_restitution = 0.7, .friction = 0.3});
  EXPECT_TRUE(std::isnan(r.tangential_restitution));
  EXPECT_EQ(r.tangential_velocity, 0.0);
  EXPECT_EQ(r.spin, 0.0);
  EXPECT_EQ(r.rebound_angle, 0.0);
  EXPECT_FALSE(r.slides);
}

TEST(ObliqueImpact, BadInputNamesItsField) {
  const ObliqueContact ok{.normal_restitution = 0.5, .friction = 0.1};
  EXPECT_THROW(rigid_body_rebound({.normal_velocity = 0.0, .radius = 1e-3}, ok), InputError);
  EXPECT_THROW(rigid_body_rebound({.normal_velocity = 1.0, .radius = 0.0}, ok), InputError);
  for (const ObliqueContact bad :
       {ObliqueContact{.normal_restitution = 1.1}, ObliqueContact{.friction = -0.1},
        ObliqueContact{.tangential_restitution = -1.5}, ObliqueContact{.gyration = 0.0},
        ObliqueContact{.friction = std::nan("")}}) {
    EXPECT_THROW(rigid_body_rebound({.normal_velocity = 1.0, .radius = 1e-3}, bad), InputError);
    EXPECT_THROW(sliding_threshold(bad), InputError);
  }
  try {
    rigid_body_rebound({.normal_velocity = 1.0, .radius = 1e-3}, {.friction = -0.1});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "friction");
  }
}

}  // namespace
}  // namespace corlab::restitution
