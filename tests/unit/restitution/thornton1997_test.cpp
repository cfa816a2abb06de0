// Thornton (1997): golden values, asymptote, and the closed form reproduced by integrating the
// load/unload contact law numerically.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/restitution/thornton1997.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "corlab/core/units.hpp"
#include "pairs.hpp"
#include "restitution/detail/numerics.hpp"

namespace corlab::restitution {
namespace {

using testing::alumina_on_al;
using testing::alumina_on_steel;

TEST(Thornton1997, YieldConstant) {
  EXPECT_NEAR(kThorntonYieldConstant, std::sqrt(std::pow(units::kPi, 4) / 40.0), 1e-15);
  EXPECT_NEAR(kThorntonYieldConstant, 1.5605214756, 1e-10);
}

TEST(Thornton1997, GoldenYieldVelocityAndCor) {
  const Thornton1997 al{.pair = alumina_on_al()};
  const Thornton1997 st{.pair = alumina_on_steel()};
  EXPECT_NEAR(al.yield_velocity(), 0.0556, 5e-5);
  EXPECT_NEAR(st.yield_velocity(), 0.1399, 5e-5);
  EXPECT_NEAR(al.cor(1.0), 0.5716, 5e-5);
  EXPECT_NEAR(st.cor(1.0), 0.7127, 5e-5);
}

TEST(Thornton1997, Section9Tables) {
  const double v[] = {0.1, 0.2, 0.5, 1, 2, 3, 4, 5, 6};
  const double al16[] = {0.947, 0.831, 0.675, 0.572, 0.482, 0.436, 0.406, 0.384, 0.367};
  const double alc[] = {0.958, 0.845, 0.688, 0.583, 0.492, 0.445, 0.414, 0.392, 0.374};
  const double st16[] = {1.000, 0.977, 0.832, 0.713, 0.604, 0.548, 0.510, 0.483, 0.462};
  const double stc[] = {1.000, 0.977, 0.833, 0.713, 0.605, 0.548, 0.511, 0.484, 0.462};
  const Thornton1997 a16{.pair = alumina_on_al()};
  const Thornton1997 ac{.pair = alumina_on_al(), .pressure = ThorntonPressure::kJacksonGreenC};
  const Thornton1997 s16{.pair = alumina_on_steel()};
  const Thornton1997 sc{.pair = alumina_on_steel(), .pressure = ThorntonPressure::kJacksonGreenC};
  for (int i = 0; i < 9; ++i) {
    EXPECT_NEAR(a16.cor(v[i]), al16[i], 6e-4) << v[i];
    EXPECT_NEAR(ac.cor(v[i]), alc[i], 6e-4) << v[i];
    EXPECT_NEAR(s16.cor(v[i]), st16[i], 6e-4) << v[i];
    EXPECT_NEAR(sc.cor(v[i]), stc[i], 6e-4) << v[i];
  }
}

TEST(Thornton1997, YieldStressChoiceIsLower) {
  // p_y = sigma_y lowers e by about 0.1-0.2 (reference sec. 2.4)
  const Thornton1997 a16{.pair = alumina_on_al()};
  const Thornton1997 asy{.pair = alumina_on_al(), .pressure = ThorntonPressure::kYieldStress};
  for (double v : {1.0, 3.0, 6.0}) {
    const double drop = a16.cor(v) - asy.cor(v);
    EXPECT_GT(drop, 0.05) << v;
    EXPECT_LT(drop, 0.25) << v;
  }
}

TEST(Thornton1997, HighSpeedAsymptote) {
  const double c = std::sqrt(6.0 * std::sqrt(3.0) / 5.0) / std::pow(2.0 * std::sqrt(1.2), 0.25);
  EXPECT_NEAR(c, 1.185, 5e-4);
  for (double r : {1e-4, 1e-6, 1e-8}) {
    EXPECT_NEAR(thornton_closed_form(r) / std::pow(r, 0.25), c, 0.2 * r + 1e-12) << r;
  }
}

TEST(Thornton1997, ContinuousAtYield) {
  EXPECT_DOUBLE_EQ(thornton_closed_form(1.0), 1.0);
  const Thornton1997 m{.pair = alumina_on_al()};
  const double vy = m.yield_velocity();
  EXPECT_NEAR(m.cor(vy * (1 + 1e-10)), 1.0, 1e-4);
}

// e from the contact law: W_load = m v^2/2 by root finding on the numerically integrated load
// curve, W_unload by integrating the unloading curve; e = sqrt(W_unload/W_load).
double integrated_cor(const ImpactPair& pair, double velocity, double radius) {
  const ThorntonContact law{.effective_modulus = pair.effective_modulus,
                            .radius = radius,
                            .limiting_pressure = 1.6 * pair.yield_stress};
  const double mass = 4.0 / 3.0 * units::kPi * radius * radius * radius * pair.sphere_density;
  const double w_target = 0.5 * mass * velocity * velocity;
  const double dy = law.yield_overlap();
  const auto load = [&law](double d) { return law.loading_force(d); };
  const double w_elastic = detail::adaptive_simpson(load, 0.0, dy, 1e-13 * w_target);
  const auto work_to = [&](double d) {
    return w_elastic + detail::adaptive_simpson(load, dy, d, 1e-13 * w_target);
  };
  double hi = 2.0 * dy;
  while (work_to(hi) < w_target) hi *= 2.0;
  const double d_max = detail::bisect_root([&](double d) { return work_to(d) - w_target; }, dy, hi);
  const auto curve = law.unloading(d_max);
  const double w_unload =
      detail::adaptive_simpson([&](double d) { return law.unloading_force(curve, d); },
                               curve.offset, d_max, 1e-13 * w_target);
  return std::sqrt(w_unload / work_to(d_max));
}

TEST(Thornton1997, IntegratedContactLawReproducesClosedForm) {
  for (const ImpactPair& pair : {alumina_on_al(), alumina_on_steel()}) {
    const Thornton1997 model{.pair = pair};
    const double vy = model.yield_velocity();
    for (double ratio : {1.8, 3.0, 10.0, 50.0, 180.0}) {
      const double v = ratio * vy;
      EXPECT_NEAR(integrated_cor(pair, v, 2.5e-3), model.cor(v), 1e-9) << ratio;
    }
  }
}

TEST(Thornton1997, YieldVelocityFromHertzEnergy) {
  // 1/2 m v_y^2 = integral_0^dy Hertz -> same v_y (reproduces 1.5605)
  const ImpactPair pair = alumina_on_al();
  const double radius = 0.01;
  const ThorntonContact law{.effective_modulus = pair.effective_modulus,
                            .radius = radius,
                            .limiting_pressure = 1.6 * pair.yield_stress};
  const double mass = 4.0 / 3.0 * units::kPi * radius * radius * radius * pair.sphere_density;
  const double vy = Thornton1997{.pair = pair}.yield_velocity();
  const double w = detail::adaptive_simpson([&](double d) { return law.loading_force(d); }, 0.0,
                                            law.yield_overlap(), 1e-13 * 0.5 * mass * vy * vy);
  EXPECT_NEAR(std::sqrt(2.0 * w / mass) / vy, 1.0, 1e-10);
}

TEST(Thornton1997, UnloadingContinuousAtReversal) {
  const ThorntonContact law{.effective_modulus = 64e9, .radius = 0.01, .limiting_pressure = 6e8};
  const double d_max = 20.0 * law.yield_overlap();
  const auto curve = law.unloading(d_max);
  EXPECT_NEAR(law.unloading_force(curve, d_max) / law.loading_force(d_max), 1.0, 1e-12);
  // contact radius continuous: R_p (d_max - d_p) = a_max^2 = (2F_max + F_y)/(2 pi p_y)
  const double a2 = (2.0 * law.loading_force(d_max) + law.yield_force()) /
                    (2.0 * units::kPi * law.limiting_pressure);
  EXPECT_NEAR(curve.radius * (d_max - curve.offset) / a2, 1.0, 1e-12);
  EXPECT_GT(curve.offset, 0.0);
}

}  // namespace
}  // namespace corlab::restitution
