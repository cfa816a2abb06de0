// The Lysmer-Kuhlemeyer dashpot kernel (absorbing_boundary.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/kernels/absorbing_boundary.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "corlab/core/units.hpp"

namespace corlab::fem {
namespace {

TEST(AbsorbingBoundary, ImpedancesAreRhoTimesTheWaveSpeeds) {
  // Glass: E 70 GPa, nu 0.25, rho 2500: M = E (1 - nu) / ((1 + nu)(1 - 2 nu)) = 84 GPa,
  // G = 28 GPa; c_p = sqrt(M / rho) = 5797 m/s, c_s = 3347 m/s.
  const double rho = 2500.0, m = 84e9, g = 28e9;
  const BoundaryImpedance z = lysmer_impedance(rho, m, g);
  EXPECT_NEAR(z.normal, rho * std::sqrt(m / rho), 1e-9 * z.normal);
  EXPECT_NEAR(z.shear, rho * std::sqrt(g / rho), 1e-9 * z.shear);
  EXPECT_GT(z.normal, z.shear);
}

TEST(AbsorbingBoundary, FaceDashpotTakesTheNormalImpedanceAlongItsNormalOnly) {
  const BoundaryImpedance z{3.0, 2.0};
  const auto c = face_dashpot<3>(1, 0.5, z);
  EXPECT_DOUBLE_EQ(c[0], 1.0);
  EXPECT_DOUBLE_EQ(c[1], 1.5);
  EXPECT_DOUBLE_EQ(c[2], 1.0);
  const auto d = face_dashpot<2>(0, 2.0, z);
  EXPECT_DOUBLE_EQ(d[0], 6.0);
  EXPECT_DOUBLE_EQ(d[1], 4.0);
}

TEST(AbsorbingBoundary, RingSegmentAreasSumToTheSurfaceOfRevolution) {
  // The base: a segment from r = 1 to r = 3 on z = -1 sweeps the annulus pi (9 - 1).
  const auto base = ring_segment_areas(1.0, -1.0, 3.0, -1.0);
  EXPECT_NEAR(base[0] + base[1], units::kPi * 8.0, 1e-12);
  EXPECT_GT(base[1], base[0]);  // the outer node carries more
  // Linear shape functions: 2 pi L int_0^1 (1 - s)(1 + 2 s) ds = 2 pi 2 (5/6) = 10 pi / 3.
  EXPECT_NEAR(base[0], 10.0 * units::kPi / 3.0, 1e-12);
  EXPECT_NEAR(base[1], 14.0 * units::kPi / 3.0, 1e-12);
  // The side: a segment on r = 2 from z = 0 to z = -0.5 sweeps a cylinder 2 pi 2 0.5, halved.
  const auto side = ring_segment_areas(2.0, 0.0, 2.0, -0.5);
  EXPECT_NEAR(side[0], units::kPi, 1e-12);
  EXPECT_NEAR(side[1], units::kPi, 1e-12);
  // A segment from the axis: its axis node carries a third of the disc.
  const auto tip = ring_segment_areas(0.0, 0.0, 1.0, 0.0);
  EXPECT_NEAR(tip[0], units::kPi / 3.0, 1e-12);
  EXPECT_NEAR(tip[1], 2.0 * units::kPi / 3.0, 1e-12);
}

TEST(AbsorbingBoundary, SpringsAreAlphaGOverTheDistance) {
  // Liu et al. 2006: alpha_N = 4/3, alpha_T = 2/3; G = 28 GPa at 10 mm: 3.73e12 and 1.87e12 Pa/m.
  const BoundaryStiffness k = spring_stiffness(28e9, 10e-3);
  EXPECT_NEAR(k.normal, 4.0 / 3.0 * 28e9 / 10e-3, 1e-3);
  EXPECT_NEAR(k.shear, 2.0 / 3.0 * 28e9 / 10e-3, 1e-3);
  const auto s = face_spring<3>(2, 1e-6, k);  // a 1 mm^2 share of a base face
  EXPECT_DOUBLE_EQ(s[2], 1e-6 * k.normal);
  EXPECT_DOUBLE_EQ(s[0], 1e-6 * k.shear);
  EXPECT_DOUBLE_EQ(s[1], 1e-6 * k.shear);
  // Twice as far, half as stiff: the outer medium's static stiffness falls as 1/distance.
  EXPECT_DOUBLE_EQ(spring_stiffness(28e9, 20e-3).normal, 0.5 * k.normal);
}

TEST(AbsorbingBoundary, DashpotOpposesTheVelocityAndDissipates) {
  EXPECT_DOUBLE_EQ(dashpot_force(4.0, 0.5), -2.0);
  EXPECT_DOUBLE_EQ(dashpot_force(4.0, -0.5), 2.0);
  EXPECT_DOUBLE_EQ(dashpot_work(4.0, -0.5, 0.1), 0.1);
  EXPECT_GE(dashpot_work(4.0, 0.0, 0.1), 0.0);
}

}  // namespace
}  // namespace corlab::fem
