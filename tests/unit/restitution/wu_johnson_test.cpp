// Wu, Li & Thornton 2003 (UNVERIFIED candidate form B) and Johnson 1985 fully plastic rebound.
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>

#include "corlab/core/units.hpp"
#include "corlab/restitution/johnson1985.hpp"
#include "corlab/restitution/thornton1997.hpp"
#include "corlab/restitution/wu2003.hpp"
#include "pairs.hpp"

namespace corlab::restitution {
namespace {

using testing::alumina_on_al;
using testing::alumina_on_steel;

TEST(Wu2003, CandidateFormBValuesOfReference) {
  // reference sec. 3 table, alumina/Al: 1.441 (0.2 m/s), 0.963 (1), 0.616 (6)
  const Wu2003 m{.pair = alumina_on_al()};
  EXPECT_NEAR(m.cor(0.2), 1.441, 6e-4);
  EXPECT_NEAR(m.cor(1.0), 0.963, 6e-4);
  EXPECT_NEAR(m.cor(6.0), 0.616, 6e-4);
}

TEST(Wu2003, ExceedsOneAtLowSpeedUnlessClamped) {
  // e > 1 below ~0.86 m/s on Al and ~1.75 m/s on steel (reference sec. 3)
  const Wu2003 al{.pair = alumina_on_al()};
  const Wu2003 st{.pair = alumina_on_steel()};
  EXPECT_GT(al.cor(0.8), 1.0);
  EXPECT_LT(al.cor(0.9), 1.0);
  EXPECT_GT(st.cor(1.7), 1.0);
  EXPECT_LT(st.cor(1.8), 1.0);
  const Wu2003 clamped{.pair = alumina_on_al(), .clamp = true};
  EXPECT_DOUBLE_EQ(clamped.cor(0.2), 1.0);
  EXPECT_NEAR(clamped.cor(6.0), 0.616, 6e-4);
}

TEST(Wu2003, YieldVelocityIsThornton16) {
  const auto p = alumina_on_al();
  EXPECT_DOUBLE_EQ(Wu2003{.pair = p}.yield_velocity(), Thornton1997{.pair = p}.yield_velocity());
  EXPECT_DOUBLE_EQ(Wu2003{.pair = p}.cor(0.5 * Thornton1997{.pair = p}.yield_velocity()), 1.0);
}

TEST(Johnson1985, Prefactors) {
  // the reference prints 3.548 (truncated); 3 pi^(5/4) 4^(3/4)/10 = 3.5490
  EXPECT_NEAR(johnson_energy_prefactor(), 3.548, 1.5e-3);
  // Y-form (p_d = 3Y, energy group 1/2 m v^2/(Y R^3)): sqrt(3.548*3) * 3^(1/8)
  const double y_form = std::sqrt(johnson_energy_prefactor() * 3.0) * std::pow(3.0, 0.125);
  EXPECT_NEAR(y_form, 3.7432822830, 1e-9);
  // ρv²-form: 1.717 (p_d) and 3.41 (Y)
  const double rho_form =
      std::sqrt(johnson_energy_prefactor()) * std::pow(2.0 * units::kPi / 3.0, -0.125);
  EXPECT_NEAR(rho_form, 1.717, 1e-3);
  EXPECT_NEAR(rho_form * std::sqrt(3.0) * std::pow(3.0, 0.125), 3.41, 5e-3);
}

TEST(Johnson1985, YieldVelocityGolden) {
  const auto al = alumina_on_al();
  const auto st = alumina_on_steel();
  EXPECT_NEAR(johnson_yield_velocity(al.yield_stress, al.effective_modulus, al.sphere_density),
              0.0561, 5e-5);
  EXPECT_NEAR(johnson_yield_velocity(st.yield_stress, st.effective_modulus, st.sphere_density),
              0.1411, 5e-5);
  // = Thornton v_y with p_y = 1.6Y up to 26 vs 25.5 (sec. 5.1)
  const double th = Thornton1997{.pair = al}.yield_velocity();
  EXPECT_NEAR(Johnson1985{.pair = al}.yield_velocity() / th, std::sqrt(26.0 / 25.5), 2e-3);
}

TEST(Johnson1985, Section9TablesUnclamped) {
  const double v[] = {0.1, 0.2, 0.5, 1, 2, 3, 4, 5, 6};
  const double al[] = {1.965, 1.653, 1.314, 1.105, 0.929, 0.840, 0.781, 0.739, 0.706};
  const double st[] = {2.475, 2.082, 1.655, 1.392, 1.171, 1.058, 0.984, 0.931, 0.889};
  const Johnson1985 m_al{.pair = alumina_on_al(), .clamp = false};
  const Johnson1985 m_st{.pair = alumina_on_steel(), .clamp = false};
  for (int i = 0; i < 9; ++i) {
    // the table shows the fully plastic formula even below V_Y (steel, 0.1 m/s)
    EXPECT_NEAR(m_al.fully_plastic(v[i]), al[i], 6e-4) << v[i];
    EXPECT_NEAR(m_st.fully_plastic(v[i]), st[i], 6e-4) << v[i];
    if (v[i] > m_st.yield_velocity()) {
      EXPECT_DOUBLE_EQ(m_st.cor(v[i]), m_st.fully_plastic(v[i]));
    }
  }
}

TEST(Johnson1985, DefaultClampAtOne) {
  const Johnson1985 m{.pair = alumina_on_al()};
  EXPECT_DOUBLE_EQ(m.cor(0.5), 1.0);
  EXPECT_NEAR(m.cor(6.0), 0.706, 6e-4);
  // quarter-power law: e(16 v)/e(v) = 16^(-1/4) = 0.5 in the fully plastic range
  EXPECT_NEAR(m.cor(96.0) / m.cor(6.0), 0.5, 1e-12);
}

}  // namespace
}  // namespace corlab::restitution
