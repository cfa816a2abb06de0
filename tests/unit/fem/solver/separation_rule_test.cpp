// The stop rule that defines e (separation_rule.hpp), driven by hand-made contact histories.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/separation_rule.hpp"

#include <gtest/gtest.h>

namespace corlab::fem {
namespace {

using Decision = SeparationRule::Decision;

constexpr double kWave = 1e-6;  // t_wave [s]
constexpr double kV0 = 5.0;     // impact speed [m/s]
constexpr double kDt = 1e-7;    // step [s]

/// Steps the rule from t0 with `contact` for n steps at velocity v; returns the last decision.
Decision run(SeparationRule& rule, double& t, int n, bool contact, double v) {
  Decision d = Decision::kContinue;
  for (int i = 0; i < n && d == Decision::kContinue; ++i) {
    t += kDt;
    rule.accumulate(0.5 * v * v, kDt);
    d = rule.update(t, kDt, contact, v);
  }
  return d;
}

TEST(SeparationRule, SteadyReboundEndsAfterOneWindow) {
  SeparationRule rule(kWave, kV0);
  double t = 0.0;
  EXPECT_EQ(run(rule, t, 100, true, -1.0), Decision::kContinue);  // 10 us of contact
  EXPECT_NEAR(rule.contact_time(), 100 * kDt, 1e-12);
  EXPECT_FALSE(rule.separated());
  // After contact: window = max(0.1 x 10 us, 1 us) = 1 us = 10 steps, constant velocity 2.5.
  const double t_sep = t;
  EXPECT_EQ(run(rule, t, 1000, false, 2.5), Decision::kRebound);
  EXPECT_TRUE(rule.separated());
  EXPECT_NEAR(t - t_sep, 11 * kDt, 1e-12);  // separation step + one 10-step window
  EXPECT_NEAR(rule.mean_sphere_kinetic_energy(), 0.5 * 2.5 * 2.5, 1e-12);
}

TEST(SeparationRule, ARunForEOnlyWatchesAShorterWindow) {
  // window = max(0.02 x 10 us, 0.25 x 1 us) = 0.25 us: 3 steps.
  SeparationRule rule = SeparationRule::e_only(kWave, kV0);
  double t = 0.0;
  EXPECT_EQ(run(rule, t, 100, true, -1.0), Decision::kContinue);
  const double t_sep = t;
  EXPECT_EQ(run(rule, t, 1000, false, 2.5), Decision::kRebound);
  EXPECT_NEAR(t - t_sep, 4 * kDt, 1e-12);  // separation step + a 3-step window
  // The chatter of a first touch (one step in contact) is spanned by the floor.
  SeparationRule touch = SeparationRule::e_only(kWave, kV0);
  t = 0.0;
  run(touch, t, 1, true, -kV0);
  run(touch, t, 2, false, -kV0);
  EXPECT_EQ(run(touch, t, 100, true, -4.0), Decision::kContinue);
  EXPECT_FALSE(touch.separated());
}

TEST(SeparationRule, ChangingVelocityKeepsWatching) {
  SeparationRule rule(kWave, kV0);
  double t = 0.0;
  run(rule, t, 100, true, -1.0);
  double v = 2.0;
  Decision d = Decision::kContinue;
  for (int i = 0; i < 30 && d == Decision::kContinue; ++i) {
    v += 1e-2;  // still accelerating: 1e-2 per step >> 1e-4 relative per window
    t += kDt;
    d = rule.update(t, kDt, false, v);
  }
  EXPECT_EQ(d, Decision::kContinue);
}

TEST(SeparationRule, ReContactRestartsTheWatch) {
  SeparationRule rule(kWave, kV0);
  double t = 0.0;
  run(rule, t, 100, true, -1.0);
  run(rule, t, 5, false, 0.5);  // half a window off contact
  EXPECT_TRUE(rule.separated());
  run(rule, t, 50, true, 0.1);  // chatter: back in contact
  EXPECT_FALSE(rule.separated());
  EXPECT_NEAR(rule.contact_time(), 155 * kDt, 1e-12);  // first to last contact step
  EXPECT_EQ(run(rule, t, 1000, false, 0.4), Decision::kRebound);
}

TEST(SeparationRule, SphereMovingIntoTheSubstrateIsNoRebound) {
  SeparationRule rule(kWave, kV0);
  double t = 0.0;
  run(rule, t, 100, true, -1.0);
  // Contact lost while still moving down (e.g. the sphere passed through a coarse surface).
  EXPECT_EQ(run(rule, t, 1000, false, -0.9), Decision::kNoRebound);
}

TEST(SeparationRule, NoContactNoDecision) {
  SeparationRule rule(kWave, kV0);
  double t = 0.0;
  EXPECT_EQ(run(rule, t, 1000, false, -kV0), Decision::kContinue);
  EXPECT_FALSE(rule.touched());
  EXPECT_EQ(rule.contact_time(), 0.0);
}

TEST(SeparationRule, SlowReboundUsesTheVelocityFloor) {
  // |v| = 1e-6 m/s: relative 1e-4 of it would never be met by round-off noise of 1e-9 m/s;
  // the floor 1e-3 v0 = 5e-3 m/s makes the tolerance 5e-7 m/s.
  SeparationRule rule(kWave, kV0);
  double t = 0.0;
  run(rule, t, 100, true, -1.0);
  Decision d = Decision::kContinue;
  for (int i = 0; i < 100 && d == Decision::kContinue; ++i) {
    t += kDt;
    d = rule.update(t, kDt, false, 1e-6 + ((i % 2) != 0 ? 1e-9 : -1e-9));
  }
  EXPECT_EQ(d, Decision::kRebound);
}

}  // namespace
}  // namespace corlab::fem
