// Node-to-segment penalty contact (penalty_contact.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/kernels/penalty_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace corlab::fem {
namespace {

TEST(PenaltyContact, GapSignAndProjection) {
  // Flat segment from (0,0) to (2,0): a point above has g > 0, below g < 0.
  auto p = project_on_segment(0.5, 0.1, 0.0, 0.0, 2.0, 0.0);
  EXPECT_NEAR(p.gap, 0.1, 1e-15);
  EXPECT_NEAR(p.xi, 0.25, 1e-15);
  EXPECT_NEAR(p.nz, 1.0, 1e-15);
  p = project_on_segment(1.5, -0.2, 0.0, 0.0, 2.0, 0.0);
  EXPECT_NEAR(p.gap, -0.2, 1e-15);
  EXPECT_NEAR(p.xi, 0.75, 1e-15);
}

TEST(PenaltyContact, ForcesBalanceAndAreTheEnergyGradient) {
  const double ra = 0.1, za = 0.02, rb = 1.1, zb = -0.05, rs = 0.45, zs = -0.03, k = 3e6;
  auto energy = [&](double r_s, double z_s, double r_a, double z_a, double r_b, double z_b) {
    const auto p = project_on_segment(r_s, z_s, r_a, z_a, r_b, z_b);
    return p.gap < 0.0 ? 0.5 * k * p.gap * p.gap : 0.0;
  };
  double f[6] = {0, 0, 0, 0, 0, 0};
  const auto p = project_on_segment(rs, zs, ra, za, rb, zb);
  ASSERT_LT(p.gap, 0.0);
  const double e = penalty_force(p, k, f[0], f[1], f[2], f[3], f[4], f[5]);
  EXPECT_NEAR(e, energy(rs, zs, ra, za, rb, zb), 1e-12 * e);
  EXPECT_NEAR(f[0] + f[2] + f[4], 0.0, 1e-9);
  EXPECT_NEAR(f[1] + f[3] + f[5], 0.0, 1e-9);
  // f = -dE/dx for every coordinate (central differences).
  const double x[6] = {rs, zs, ra, za, rb, zb};
  for (int i = 0; i < 6; ++i) {
    double xp[6], xm[6];
    for (int j = 0; j < 6; ++j) xp[j] = xm[j] = x[j];
    const double hh = 1e-7;
    xp[i] += hh;
    xm[i] -= hh;
    const double grad = (energy(xp[0], xp[1], xp[2], xp[3], xp[4], xp[5]) -
                         energy(xm[0], xm[1], xm[2], xm[3], xm[4], xm[5])) /
                        (2 * hh);
    EXPECT_NEAR(f[i], -grad, 1e-5 * std::abs(k * p.gap)) << "coordinate " << i;
  }
}

TEST(PenaltyContact, NoForceWhenOpen) {
  double f[6] = {0, 0, 0, 0, 0, 0};
  const auto p = project_on_segment(0.5, 0.01, 0.0, 0.0, 1.0, 0.0);
  EXPECT_EQ(penalty_force(p, 1e6, f[0], f[1], f[2], f[3], f[4], f[5]), 0.0);
  for (double v : f) EXPECT_EQ(v, 0.0);
}

TEST(PenaltyContact, StiffnessAtTheStabilityLimit) {
  // scale 1: a two-mass spring at the limit omega dt = 2.
  const double k = penalty_stiffness(1.0, 2.0, 2.0, 1e-6);
  const double m_eff = 1.0;
  EXPECT_NEAR(std::sqrt(k / m_eff) * 1e-6, 2.0, 1e-12);
}

}  // namespace
}  // namespace corlab::fem
