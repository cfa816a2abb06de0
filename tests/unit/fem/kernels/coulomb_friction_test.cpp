// Coulomb friction (coulomb_friction.hpp). Penalty: stick below mu f_n, slip capped at mu f_n
// opposing the motion, the dissipation of a sliding block equal to mu N x distance, the energy
// of the tangential spring accounted for, and a turning normal keeping the force's magnitude.
// Kinematic: one update stops a slave on a rigid master within the step, slip is capped at
// mu f_n against the motion, repeated updates (projected Gauss-Seidel) settle two slaves that
// share a master node, and the work booked from the velocities is the kinetic energy lost.
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

// A node of mass m moving at v along x on a rigid master: one update's force, acting over dt,
// brings its tangential velocity to 0 and leaves the normal one; the booked work is the kinetic
// energy of the tangential motion it removed.
TEST(KinematicFriction, OneUpdateStopsASlaveOnARigidMaster) {
  const double mass = 2e-3;
  const double dt = 1e-7;
  const double v[3] = {0.3, -0.4, -1.0};  // the normal part (z) is left to the normal contact
  const double t0[3] = {0.0, 0.0, 0.0};
  const FrictionUpdate u = kinematic_friction(t0, kNormal, v, mass, dt, 1e5, 0.5);
  EXPECT_FALSE(u.sliding);
  const double after[3] = {v[0] + dt * u.t[0] / mass, v[1] + dt * u.t[1] / mass, v[2]};
  EXPECT_NEAR(after[0], 0.0, 1e-15);
  EXPECT_NEAR(after[1], 0.0, 1e-15);
  EXPECT_EQ(u.t[2], 0.0);
  EXPECT_EQ(u.dissipation, 0.0);
  const double lost = 0.5 * mass * (v[0] * v[0] + v[1] * v[1]);
  EXPECT_NEAR(-friction_work(u.t, v, after, dt), lost, 1e-12 * lost);
}

// The force to stop it exceeds mu f_n: slip, at mu f_n against the motion.
TEST(KinematicFriction, SlipIsCappedAtMuFnAgainstTheMotion) {
  const double v[3] = {0.6, 0.8, 0.0};
  const double t0[3] = {0.0, 0.0, 0.0};
  const FrictionUpdate u = kinematic_friction(t0, kNormal, v, 2e-3, 1e-7, 100.0, 0.3);
  EXPECT_TRUE(u.sliding);
  EXPECT_NEAR(u.t[0], -30.0 * 0.6, 1e-12);
  EXPECT_NEAR(u.t[1], -30.0 * 0.8, 1e-12);
  const FrictionUpdate none = kinematic_friction(t0, kNormal, v, 2e-3, 1e-7, 0.0, 0.3);
  EXPECT_EQ(none.t[0], 0.0);
  EXPECT_FALSE(none.sliding);
}

// Two slaves (masses m1, m2) on one free master node (mass M), all moving along x: the
// coupled stick forces stop both relative motions, t1/m1 + (t1 + t2)/M = -v1/dt and the same
// for 2. Repeating each slave's update with the other's force so far (projected Gauss-Seidel,
// as hex_friction.cpp does) converges to them.
TEST(KinematicFriction, RepeatedUpdatesSettleSlavesSharingAMaster) {
  const double m1 = 1e-3;
  const double m2 = 3e-3;
  const double big = 2e-3;  // the master node
  const double dt = 1e-7;
  const double v1 = 0.5;  // relative velocities predicted without friction [m/s]
  const double v2 = -0.2;
  // Exact: [1/m1 + 1/M, 1/M; 1/M, 1/m2 + 1/M] (t1, t2) = -(v1, v2)/dt.
  const double a = 1.0 / m1 + 1.0 / big;
  const double b = 1.0 / big;
  const double d = 1.0 / m2 + 1.0 / big;
  const double det = a * d - b * b;
  const double t1_exact = -(d * v1 - b * v2) / dt / det;
  const double t2_exact = -(a * v2 - b * v1) / dt / det;
  double t1[3] = {0.0, 0.0, 0.0};
  double t2[3] = {0.0, 0.0, 0.0};
  const double e1 = 1.0 / a;  // each slave's effective mass alone: 1 / (1/m + 1/M)
  const double e2 = 1.0 / d;
  for (int sweep = 0; sweep < 60; ++sweep) {
    const double dv_master = dt * (t1[0] + t2[0]) / big;  // the master moves against both
    const double r1[3] = {v1 + dt * t1[0] / m1 + dv_master, 0.0, 0.0};
    const FrictionUpdate u1 = kinematic_friction(t1, kNormal, r1, e1, dt, 1e9, 0.5);
    t1[0] = u1.t[0];
    const double dv_master2 = dt * (t1[0] + t2[0]) / big;
    const double r2[3] = {v2 + dt * t2[0] / m2 + dv_master2, 0.0, 0.0};
    const FrictionUpdate u2 = kinematic_friction(t2, kNormal, r2, e2, dt, 1e9, 0.5);
    t2[0] = u2.t[0];
  }
  EXPECT_NEAR(t1[0], t1_exact, 1e-9 * std::abs(t1_exact));
  EXPECT_NEAR(t2[0], t2_exact, 1e-9 * std::abs(t1_exact));
}

}  // namespace
}  // namespace corlab::fem
