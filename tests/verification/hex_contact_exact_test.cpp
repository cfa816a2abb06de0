// Issue 39's exact checks of the 3-D model's contact on the deformable flat (hex_contact.cpp,
// hex_master_surface.cpp): without friction nothing acts along the surface, so an elastic
// oblique impact keeps its tangential velocity (e_t = 1) and leaves no spin, an elastic impact
// does not rebound faster than it came (e_n <= 1), and a normal impact, symmetric about x = 0,
// leaves no spin. The slaves meet a smooth (C1) surface through the flat's top nodes and the
// force is the gap's exact gradient, so the energy is kept (below 1e-4 of E0) at every h; the
// faceted master it replaced lost 1.1 % and 5.1 % at 5 deg and h = 1 and 0.75 mm. The elastic
// steel pair at 10 m/s (test::sliding_on_elastic_flat) on the coarse mesh, h = 1.5 mm (a/h 2.5):
// the bound (1e-3) holds there at 80 deg; at 5 and 40 deg e_t converges to 1 at about
// first order in h (5 deg: 0.99300, 0.99567 at 1.5 and 1 mm; extrapolated at first order,
// 1.0009), too slowly for CI, so those bounds are the measured error at 1.5 mm with a margin
// (docs/theory/solver3d.md, "The contact surface"). The faceted master fails them (e_t 0.8266 and
// 0.9936 at 5 and 40 deg). SPDX-License-Identifier: BSD-3-Clause
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "corlab/fem/solver/simulate.hpp"
#include "support/hex_cases.hpp"

namespace corlab::fem {
namespace {

// The bound on omega R / v after a normal impact [-]: the surface is smooth, so the
// projections of a slave and of its mirror image across x = 0 mirror each other to round-off.
constexpr double kNormalSpinTolerance = 1e-6;
// The energy balance the contact keeps [-] (of E0).
constexpr double kEnergyTolerance = 1e-4;
// e_n - 1 at h = 1.5 mm [-]: measured +5.1e-4 at 40 deg (the faceted master: +3.8e-3).
constexpr double kReboundExcessTolerance = 1e-3;

struct ObliqueCase {
  double angle = 0.0;           // [deg]
  double e_t_tolerance = 0.0;   // on |e_t - 1| [-]
  double spin_tolerance = 0.0;  // on |omega| R / v [-]
};

class FrictionlessObliqueImpact : public ::testing::TestWithParam<ObliqueCase> {};

// Measured at h = 1.5 mm (e_t, omega R / v, e_n, energy balance error): 5 deg 0.99300, 1.5e-3,
// 0.99931, 9.8e-6; 40 deg 0.99841, 2.6e-3, 1.00051, 3.7e-6; 80 deg 1.00004, 1.1e-4, 0.99824,
// 1.6e-7. The faceted master: 0.8266, 0.038; 0.9936, 0.0103; 1.0003, 8e-4.
TEST_P(FrictionlessObliqueImpact, KeepsItsTangentialVelocityAndEnergy) {
  ImpactConfig c = test::sliding_on_elastic_flat(0.0, 1.5e-3);
  c.impact.angle = PlaneAngle::degrees(GetParam().angle);
  validate(c);
  const ImpactResult r = simulate(c);
  ASSERT_EQ(r.status, RunStatus::kSeparated);
  EXPECT_NEAR(r.e_t, 1.0, GetParam().e_t_tolerance);
  EXPECT_LT(std::abs(r.omega) * c.sphere.radius / c.impact.velocity, GetParam().spin_tolerance);
  EXPECT_LT(r.e_n - 1.0, kReboundExcessTolerance);
  EXPECT_LT(r.energy_balance_error, kEnergyTolerance);
  EXPECT_EQ(r.energy_friction, 0.0);
}

INSTANTIATE_TEST_SUITE_P(Angles,
                         FrictionlessObliqueImpact,
                         ::testing::Values(ObliqueCase{5.0, 1e-2, 3e-3},
                                           ObliqueCase{40.0, 3e-3, 5e-3},
                                           ObliqueCase{80.0, 1e-3, 1e-3}),
                         [](const ::testing::TestParamInfo<ObliqueCase>& p) {
                           return "deg" + std::to_string(static_cast<int>(p.param.angle));
                         });

// Measured: omega R / v = 1.9e-16 (the faceted master: 1.6e-6), e_n = 0.99925, energy 7.5e-6.
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
