// Penalty Coulomb friction (coulomb_friction.hpp): stick below mu f_n, slip capped at mu f_n
// opposing the motion, the dissipation of a sliding block equal to mu N x distance, the energy
// of the tangential spring accounted for, and a turning normal keeping the force's magnitude.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/kernels/coulomb_friction.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace corlab::fem {
namespace {

const double kNormal[3] = {0.0, 0.0, 1.0};

TEST(CoulombFriction, SticksBelowTheLimitAndSlipsAtIt) {
  const double t0[3] = {0.0, 0.0, 0.0};
  const double k = 1e6;
  // 1 um tangential step against a 10 N normal force, mu = 0.5: 1 N < 5 N, stick.
  const double small[3] = {1e-6, 0.0, 3e-7};  // the normal part (z) is ignored
  FrictionUpdate u = coulomb_friction(t0, kNormal, small, 10.0, k, 0.5);
  EXPECT_FALSE(u.sliding);
  EXPECT_NEAR(u.t[0], -1.0, 1e-12);
  EXPECT_EQ(u.t[2], 0.0);
  EXPECT_EQ(u.dissipation, 0.0);
  // 20 um more: trial 21 N, capped at 5 N against the motion; dissipation 5 N x 16 um.
  const double large[3] = {20e-6, 0.0, 0.0};
  u = coulomb_friction(u.t, kNormal, large, 10.0, k, 0.5);
  EXPECT_TRUE(u.sliding);
  EXPECT_NEAR(u.t[0], -5.0, 1e-12);
  EXPECT_NEAR(u.dissipation, 5.0 * 16e-6, 1e-15);
}

// A block pressed by N slides a distance L in many steps: the friction force is mu N from the
// first slip on, and the work the block does against it is the dissipation, mu N (L - mu N / k),
// plus the spring's stored energy (mu N)^2 / (2 k).
TEST(CoulombFriction, SlidingBlockDissipatesMuNTimesTheSlip) {
  const double n = 40.0;
  const double mu = 0.3;
  const double k = 2e7;
  const double step = 1e-7;
  const int steps = 5000;  // L = 0.5 mm
  FrictionUpdate u;
  double dissipated = 0.0;
  double work = 0.0;
  for (int i = 0; i < steps; ++i) {
    const double du[3] = {step * 0.6, step * 0.8, 0.0};
    const double old[3] = {u.t[0], u.t[1], u.t[2]};
    u = coulomb_friction(old, kNormal, du, n, k, mu);
    dissipated += u.dissipation;
    for (int c = 0; c < 3; ++c) work -= 0.5 * (old[c] + u.t[c]) * du[c];
  }
  const double limit = mu * n;
  const double length = steps * step;
  EXPECT_NEAR(std::hypot(u.t[0], u.t[1]), limit, 1e-12 * limit);
  EXPECT_NEAR(u.t[0] / limit, -0.6, 1e-12);
  // Exact but for the step in which sticking turns to slip: at most one step's worth.
  EXPECT_NEAR(dissipated, limit * (length - limit / k), limit * step);
  EXPECT_NEAR(work, dissipated + friction_stored_energy(u.t, k), 0.5 * k * step * step);
}

TEST(CoulombFriction, OpeningReleasesTheSpringAsDissipation) {
  const double t[3] = {3.0, -4.0, 0.0};
  const double du[3] = {0.0, 0.0, 0.0};
  const FrictionUpdate u = coulomb_friction(t, kNormal, du, 0.0, 1e6, 0.5);
  EXPECT_EQ(u.t[0], 0.0);
  EXPECT_EQ(u.t[1], 0.0);
  EXPECT_NEAR(u.dissipation, 0.5 * 25.0 / 1e6, 1e-18);
}

TEST(CoulombFriction, TurningNormalKeepsTheForceInThePlane) {
  const double t[3] = {2.0, 0.0, 0.0};
  const double theta = 0.1;
  const double n[3] = {std::sin(theta), 0.0, std::cos(theta)};  // turned about y
  const double du[3] = {0.0, 0.0, 0.0};
  const FrictionUpdate u = coulomb_friction(t, n, du, 100.0, 1e6, 0.5);
  EXPECT_NEAR(u.t[0] * n[0] + u.t[1] * n[1] + u.t[2] * n[2], 0.0, 1e-14);
  EXPECT_NEAR(std::sqrt(u.t[0] * u.t[0] + u.t[1] * u.t[1] + u.t[2] * u.t[2]), 2.0, 1e-14);
  EXPECT_FALSE(u.sliding);
}

TEST(CoulombFriction, FrictionlessContactCarriesNoTangentialForce) {
  const double t[3] = {0.0, 0.0, 0.0};
  const double du[3] = {1e-3, 0.0, 0.0};
  const FrictionUpdate u = coulomb_friction(t, kNormal, du, 100.0, 1e6, 0.0);
  EXPECT_EQ(u.t[0], 0.0);
  EXPECT_TRUE(u.sliding);
  EXPECT_EQ(u.dissipation, 0.0);
}

}  // namespace
}  // namespace corlab::fem
