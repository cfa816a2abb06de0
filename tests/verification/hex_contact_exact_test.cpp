// Issue 39's exact checks of the 3-D model's contact on the deformable flat (hex_contact.cpp,
// hex_master_surface.cpp): without friction nothing acts along the surface, so an elastic
// oblique impact keeps its tangential velocity (e_t = 1) and leaves no spin, an elastic impact
// does not rebound faster than it came (e_n <= 1), and a normal impact, symmetric about x = 0,
// leaves no spin. The contact points (3 x 3 on each of the sphere's slave faces) meet a smooth
// (C1) surface through the flat's top nodes and the force is the gap's exact gradient, so the
// energy is kept (below 1e-4 of E0). The elastic steel pair at 10 m/s
// (test::sliding_on_elastic_flat) on the coarse mesh, h = 1.5 mm (a/h 2.5), holds the issue's
// bounds (1e-3 on e_t - 1 and omega R / v at 5, 40 and 80 deg). With the contact at the sphere's
// nodes alone, which sample the flat's grid in step with it, the same runs gave e_t 0.99300 and
// 0.99841 at 5 and 40 deg, omega R / v 1.5e-3 and 2.6e-3, e_n 1.00051 at 40 deg; with the
// faceted master before that, 0.8266 and 0.9936 (docs/theory/solver3d.md, "The contact points").
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "corlab/fem/solver/simulate.hpp"
#include "support/hex_cases.hpp"

namespace corlab::fem {
namespace {

// The bounds [-]: on |e_t - 1| and omega R / v after an oblique impact, and on omega R / v
// after a normal one (the surface is smooth and the mesh symmetric about x = 0, so the
// projections of a point and of its mirror image mirror each other to round-off).
constexpr double kTangentialTolerance = 1e-3;
constexpr double kNormalSpinTolerance = 1e-6;
// The energy balance the contact keeps [-] (of E0).
constexpr double kEnergyTolerance = 1e-4;

class FrictionlessObliqueImpact : public ::testing::TestWithParam<double> {};

// Measured at h = 1.5 mm (e_t, omega R / v, e_n, energy balance error): 5 deg 1.00061, 2.0e-4,
// 0.99949, 3.4e-6; 40 deg 0.99996, 1.9e-4, 0.99962, 1.3e-6; 80 deg 1.00001, 1.1e-4, 0.99943,
// 7e-9. At h = 1 mm: docs/theory/solver3d.md.
TEST_P(FrictionlessObliqueImpact, KeepsItsTangentialVelocityAndEnergy) {
  ImpactConfig c = test::sliding_on_elastic_flat(0.0, 1.5e-3);
  c.impact.angle = PlaneAngle::degrees(GetParam());
  validate(c);
  const ImpactResult r = simulate(c);
  ASSERT_EQ(r.status, RunStatus::kSeparated);
  EXPECT_NEAR(r.e_t, 1.0, kTangentialTolerance);
  EXPECT_LT(std::abs(r.omega) * c.sphere.radius / c.impact.velocity, kTangentialTolerance);
  EXPECT_LE(r.e_n, 1.0);
  EXPECT_LT(r.energy_balance_error, kEnergyTolerance);
  EXPECT_EQ(r.energy_friction, 0.0);
}

INSTANTIATE_TEST_SUITE_P(Angles,
                         FrictionlessObliqueImpact,
                         ::testing::Values(5.0, 40.0, 80.0),
                         [](const ::testing::TestParamInfo<double>& p) {
                           return "deg" + std::to_string(static_cast<int>(p.param));
                         });

// Measured: omega R / v = 1.1e-16 (the nodes' contact: 1.9e-16), e_n = 0.99949, energy 3.4e-6.
TEST(FrictionlessNormalImpact, LeavesNoSpin) {
  ImpactConfig c = test::sliding_on_elastic_flat(0.0, 1.5e-3);
  c.impact.angle = PlaneAngle{};
  validate(c);
  const ImpactResult r = simulate(c);
  ASSERT_EQ(r.status, RunStatus::kSeparated);
  EXPECT_LT(std::abs(r.omega) * c.sphere.radius / c.impact.velocity, kNormalSpinTolerance);
  EXPECT_LE(r.e_n, 1.0);
  EXPECT_LT(r.energy_balance_error, kEnergyTolerance);
}

}  // namespace
}  // namespace corlab::fem
