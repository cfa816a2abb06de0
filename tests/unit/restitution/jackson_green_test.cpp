// Jackson-Green 2005 critical quantities and loading law; Jackson-Green-Marghitu 2010 energy
// models (J-G1, J-G2) and empirical fit.
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>

#include "corlab/core/units.hpp"
#include "corlab/restitution/jackson_green2005.hpp"
#include "corlab/restitution/jackson_green2010.hpp"
#include "corlab/restitution/thornton1997.hpp"
#include "pairs.hpp"
#include "restitution/detail/numerics.hpp"

namespace corlab::restitution {
namespace {

using testing::alumina_on_al;
using testing::alumina_on_steel;

JacksonGreen2005 law_for(const ImpactPair& p, double radius) {
  return JacksonGreen2005{.effective_modulus = p.effective_modulus,
                          .yield_stress = p.yield_stress,
                          .poisson_ratio = p.substrate_poisson,
                          .radius = radius};
}

TEST(JacksonGreen2005, CriticalConstantsGolden) {
  EXPECT_NEAR(jackson_green_c(0.33), 1.6510, 5e-5);
  EXPECT_NEAR(jackson_green_c(0.29), 1.6031, 5e-5);
  const auto al = alumina_on_al();
  const auto st = alumina_on_steel();
  EXPECT_NEAR(jackson_green_critical_velocity(al.effective_modulus, al.yield_stress,
                                              al.substrate_poisson, al.sphere_density),
              0.0601, 5e-5);
  EXPECT_NEAR(jackson_green_critical_velocity(st.effective_modulus, st.yield_stress,
                                              st.substrate_poisson, st.sphere_density),
              0.1405, 5e-5);
}

TEST(JacksonGreen2005, CriticalVelocityFromHertzEnergy) {
  // 1/2 m V_c^2 = 2/5 P_c omega_c for any R; equals Thornton's v_y with p_y = C S_y
  const auto p = alumina_on_steel();
  for (double radius : {1e-3, 0.035, 1.0}) {
    const auto law = law_for(p, radius);
    const double m = 4.0 / 3.0 * units::kPi * std::pow(radius, 3) * p.sphere_density;
    const double vc =
        std::sqrt(4.0 * law.critical_force() * law.critical_interference() / (5.0 * m));
    EXPECT_NEAR(vc / jackson_green_critical_velocity(p.effective_modulus, p.yield_stress,
                                                     p.substrate_poisson, p.sphere_density),
                1.0, 1e-12);
    // P_c is the Hertz force at omega_c
    EXPECT_NEAR(law.critical_force() / (4.0 / 3.0 * p.effective_modulus * std::sqrt(radius) *
                                        std::pow(law.critical_interference(), 1.5)),
                1.0, 1e-12);
  }
  EXPECT_NEAR(jackson_green_critical_velocity(p.effective_modulus, p.yield_stress,
                                              p.substrate_poisson, p.sphere_density),
              thornton_yield_velocity(jackson_green_c(p.substrate_poisson) * p.yield_stress,
                                      p.effective_modulus, p.sphere_density),
              1e-15);
}

TEST(JacksonGreen2005, LoadingLawHertzBelowSwitchAndNearlyContinuous) {
  const auto law = law_for(alumina_on_al(), 1.0);
  EXPECT_DOUBLE_EQ(law.load_ratio(1.0), 1.0);
  EXPECT_DOUBLE_EQ(law.load_ratio(1.9), 1.9 * std::sqrt(1.9));
  const double below = law.load_ratio(1.9);
  const double above = law.load_ratio(1.9 * (1 + 1e-12));
  EXPECT_LT(std::abs(above - below) / below, 5e-3);  // the 2005 fit is nearly continuous
  // the elastic-plastic load grows monotonically
  double prev = above;
  for (double s = 2.0; s < 1e4; s *= 1.05) {
    const double p = law.load_ratio(s);
    EXPECT_GT(p, prev) << s;
    prev = p;
  }
}

TEST(JacksonGreen2010, LoadingWorkMatchesAdaptiveSimpson) {
  const auto p = alumina_on_al();
  const JacksonGreen2010 model{.pair = p, .radius = 0.0025};
  const auto law = model.loading_law();
  const double wc = law.critical_interference();
  for (double s : {1.5, 1.9, 2.5, 10.0, 100.0, 3000.0}) {
    const double w = s * wc;
    const double split = std::min(w, 1.9 * wc);
    const auto f = [&law](double x) { return law.load(x); };
    const double scale = law.critical_force() * wc * s * s;
    double ref = detail::adaptive_simpson(f, 0.0, split, 1e-13 * scale);
    if (w > split) ref += detail::adaptive_simpson(f, split, w, 1e-13 * scale);
    EXPECT_NEAR(model.loading_work(w) / ref, 1.0, 1e-9) << s;
  }
}

TEST(JacksonGreen2010, MaxInterferenceBalancesKineticEnergy) {
  const JacksonGreen2010 model{.pair = alumina_on_steel(), .radius = 0.0025};
  for (double v : {0.2, 1.0, 6.0, 100.0}) {
    const double w = model.max_interference(v);
    const double ke = 0.5 * model.mass() * v * v;
    EXPECT_NEAR(model.loading_work(w) / ke, 1.0, 1e-12) << v;
  }
}

TEST(JacksonGreen2010, RadiusIndependent) {
  for (auto residual :
       {JacksonGreenResidual::kEtsion2005, JacksonGreenResidual::kContinuousContactRadius}) {
    const JacksonGreen2010 unit{.pair = alumina_on_al(), .residual = residual, .radius = 1.0};
    const JacksonGreen2010 small{.pair = alumina_on_al(), .residual = residual, .radius = 2.5e-3};
    for (double v : {0.1, 0.5, 2.0, 6.0, 50.0}) {
      EXPECT_NEAR(unit.cor(v), small.cor(v), 1e-10) << v;
    }
  }
}

TEST(JacksonGreen2010, ContinuousContactRadiusUnloadingClosedForm) {
  // W_unload = 8/15 E* sqrt(R_bar) (w_max - w_bar)^2.5 == 3/10 P^2/(E* a) (sec. 4.5)
  const JacksonGreen2010 model{.pair = alumina_on_al(), .radius = 0.01};
  const auto law = model.loading_law();
  const double w_max = 40.0 * law.critical_interference();
  const double p = law.load(w_max);
  const double a = law.radius * law.contact_radius_ratio(w_max);
  const double es = law.effective_modulus;
  const double r_bar = 4.0 * es * a * a * a / (3.0 * p);
  const double depth = 3.0 * p / (4.0 * es * a);
  const double w_bar = w_max - depth;
  const double numeric = detail::adaptive_simpson(
      [&](double x) {
        const double d = std::max(x - w_bar, 0.0);
        return 4.0 / 3.0 * es * std::sqrt(r_bar) * d * std::sqrt(d);
      },
      w_bar, w_max, 1e-14 * p * depth);
  EXPECT_NEAR(model.unloading_work(w_max) / numeric, 1.0, 1e-9);
  // the unloading curve passes through (w_max, P_max)
  EXPECT_NEAR(4.0 / 3.0 * es * std::sqrt(r_bar) * std::pow(depth, 1.5) / p, 1.0, 1e-12);
}

TEST(JacksonGreen2010, OneBelowCriticalVelocityAndContinuousThere) {
  for (const auto& pair : {alumina_on_al(), alumina_on_steel()}) {
    for (auto residual :
         {JacksonGreenResidual::kEtsion2005, JacksonGreenResidual::kContinuousContactRadius}) {
      const JacksonGreen2010 m{.pair = pair, .residual = residual};
      const double vc = m.yield_velocity();
      EXPECT_DOUBLE_EQ(m.cor(0.5 * vc), 1.0);
      EXPECT_DOUBLE_EQ(m.cor(vc), 1.0);
      EXPECT_NEAR(m.cor(vc * (1 + 1e-6)), 1.0, 1e-5);
    }
  }
}

TEST(JacksonGreen2010, ContinuousRadiusIsElasticUpToHertzSwitch) {
  // Hertz loading + Hertz unloading with R_bar = R: no loss for omega* <= 1.9
  const JacksonGreen2010 m{.pair = alumina_on_al()};
  const double v_switch = m.yield_velocity() * std::pow(1.9, 1.25);
  EXPECT_NEAR(m.cor(0.99 * v_switch), 1.0, 1e-12);
  // the 2005 loading law's small step at 1.9 gives a small drop
  EXPECT_GT(m.cor(1.01 * v_switch), 0.99);
}

TEST(JacksonGreen2010, DecreasingInVelocity) {
  for (auto residual :
       {JacksonGreenResidual::kEtsion2005, JacksonGreenResidual::kContinuousContactRadius}) {
    const JacksonGreen2010 m{.pair = alumina_on_al(), .residual = residual};
    double prev = 1.0;
    for (double v = 1e-3; v <= 1e3; v *= 1.07) {
      const double e = m.cor(v);
      EXPECT_LE(e, prev + 1e-12) << v;
      prev = e;
    }
    EXPECT_LT(prev, 0.5);
  }
}

TEST(JacksonGreen2010, QualitativeOrderingOfSeedPaper) {
  // Ma et al. 2023: J-G1 is low at high speed compared with J-G2 (both pairs).
  for (const auto& pair : {alumina_on_al(), alumina_on_steel()}) {
    const JacksonGreen2010 jg1{.pair = pair, .residual = JacksonGreenResidual::kEtsion2005};
    const JacksonGreen2010 jg2{.pair = pair};
    EXPECT_LT(jg1.cor(6.0), jg2.cor(6.0));
  }
}

TEST(JacksonGreen2010Fit, Section9Tables) {
  const double v[] = {0.1, 0.2, 0.5, 1, 2, 3, 4, 5, 6};
  const double al_e[] = {0.968, 0.918, 0.846, 0.787, 0.724, 0.685, 0.656, 0.633, 0.614};
  const double al_c[] = {0.970, 0.920, 0.844, 0.778, 0.704, 0.656, 0.621, 0.592, 0.568};
  const double st_e[] = {1.000, 0.979, 0.914, 0.859, 0.799, 0.761, 0.733, 0.711, 0.692};
  const double st_c[] = {1.000, 0.981, 0.916, 0.856, 0.788, 0.743, 0.709, 0.682, 0.658};
  const auto c = JacksonGreenFitStrain::kCTimesYieldOverModulus;
  const JacksonGreen2010Fit ae{.pair = alumina_on_al()};
  const JacksonGreen2010Fit ac{.pair = alumina_on_al(), .strain = c};
  const JacksonGreen2010Fit se{.pair = alumina_on_steel()};
  const JacksonGreen2010Fit sc{.pair = alumina_on_steel(), .strain = c};
  for (int i = 0; i < 9; ++i) {
    EXPECT_NEAR(ae.cor(v[i]), al_e[i], 6e-4) << v[i];
    EXPECT_NEAR(ac.cor(v[i]), al_c[i], 6e-4) << v[i];
    EXPECT_NEAR(se.cor(v[i]), st_e[i], 6e-4) << v[i];
    EXPECT_NEAR(sc.cor(v[i]), st_c[i], 6e-4) << v[i];
  }
}

TEST(JacksonGreen2010Fit, ContinuousAtCriticalVelocity) {
  const JacksonGreen2010Fit m{.pair = alumina_on_steel()};
  const double vc = m.yield_velocity();
  EXPECT_DOUBLE_EQ(m.cor(vc), 1.0);
  EXPECT_NEAR(m.cor(vc * (1 + 1e-9)), 1.0, 1e-8);
}

}  // namespace
}  // namespace corlab::restitution
