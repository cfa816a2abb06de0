// The impact integrator against closed forms: Hertz (e = 1, contact time, max overlap), linear
// spring-dashpot, Thornton (1997) closed-form CoR, Tsuji/LAMMPS mapping.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dem/contact_ode.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "corlab/core/error.hpp"
#include "corlab/core/units.hpp"
#include "corlab/dem/calibration.hpp"
#include "corlab/dem/lammps_mapping.hpp"
#include "corlab/materials/material_database.hpp"
#include "corlab/restitution/thornton1997.hpp"

namespace corlab::dem {
namespace {

TEST(DemContactOde, HertzIsElasticWithTheClassicalContactTimeAndOverlap) {
  const double k = hertz_stiffness(100e9, 0.005);
  const double m = 4e-3;
  const double v = 2.0;
  const HertzLaw law{k};
  const ForceLaw f = [&law](double d, double, const ContactHistory&) { return law.force(d); };
  const auto out = simulate_impact(f, m, v);
  EXPECT_NEAR(out.restitution, 1.0, 1e-9);
  // delta_max = (5 m v^2 / (4 K))^(2/5); t_c = 2 (delta_max/v) int_0^1 dx/sqrt(1 - x^2.5)
  //   = 2 (delta_max/v) sqrt(pi) Gamma(7/5)/Gamma(9/10) = 2.9432 delta_max/v (Johnson 1985 s. 11.4)
  const double delta_max = std::pow(5.0 * m * v * v / (4.0 * k), 0.4);
  EXPECT_NEAR(out.max_overlap / delta_max, 1.0, 1e-9);
  const double shape = 2.0 * std::sqrt(units::kPi) * std::tgamma(1.4) / std::tgamma(0.9);
  EXPECT_NEAR(out.contact_time / (shape * delta_max / v), 1.0, 1e-8);
}

TEST(DemContactOde, LinearSpringDashpotMatchesItsClosedForm) {
  const double k = 1e6;
  const double m = 0.01;
  for (const double e : {0.1, 0.5, 0.9}) {
    const LinearSpringDashpotLaw law{k, linear_damping_for_restitution(e, m, k)};
    EXPECT_NEAR(linear_restitution(law.damping, m, k), e, 1e-12);
    const ForceLaw f = [&law](double d, double r, const ContactHistory&) {
      return law.force(d, r);
    };
    EXPECT_NEAR(simulate_impact(f, m, 1.5).restitution, e, 1e-8) << e;
  }
}

// Small damping: 1 - e = Delta E/(m v^2) with Delta E = 2 c v delta_m^1.5 I along the elastic path,
// I = int_0^1 x^0.5 sqrt(1 - x^2.5) dx = (2/5) B(3/5, 3/2): the leading term of the series of
// Ramirez et al. 1999 / Schwager & Poeschel 2008 (1 - e ~ v^(1/5)), derived here independently.
TEST(DemContactOde, ViscoelasticHertzLeadingOrderDamping) {
  const double k = hertz_stiffness(70e9, 0.002);
  const double m = 1e-4;
  const double beta_fn = std::tgamma(0.6) * std::tgamma(1.5) / std::tgamma(2.1);
  const double integral = 0.4 * beta_fn;
  for (const double v : {0.1, 1.0, 10.0}) {
    const double delta_m = std::pow(5.0 * m * v * v / (4.0 * k), 0.4);
    // c chosen so that 1 - e is about 1e-4: second-order terms are ~1e-8
    const double c = 1e-4 * m * v / (2.0 * std::pow(delta_m, 1.5) * integral);
    const ViscoelasticHertzLaw law{k, c};
    const ForceLaw f = [&law](double d, double r, const ContactHistory&) {
      return law.force(d, r);
    };
    const double one_minus_e = 1.0 - simulate_impact(f, m, v).restitution;
    EXPECT_NEAR(one_minus_e / 1e-4, 1.0, 2e-3) << "v = " << v;
  }
}

TEST(DemContactOde, ThorntonLawReproducesCorlabThornton1997) {
  const auto& db = MaterialDatabase::builtin();
  const auto pair =
      restitution::make_impact_pair(db.get("alumina_ma2023"), db.get("aluminium_ma2023"), "test");
  const restitution::Thornton1997 model{pair};
  const double radius = 0.005;
  const double mass = 4.0 / 3.0 * units::kPi * radius * radius * radius * pair.sphere_density;
  const ThorntonNingLaw law{{pair.effective_modulus, radius, model.limiting_pressure()}};
  const ForceLaw f = [&law](double d, double, const ContactHistory& h) { return law.force(d, h); };
  for (const double v : {0.1, 1.0, 3.0, 10.0}) {
    ASSERT_GT(v, model.yield_velocity());
    EXPECT_NEAR(simulate_impact(f, mass, v).restitution, model.cor(v), 1e-6) << "v = " << v;
  }
  EXPECT_NEAR(simulate_impact(f, mass, 0.5 * model.yield_velocity()).restitution, 1.0, 1e-8);
}

// LAMMPS damping tsuji asked for e delivers (issue 11, measured in LAMMPS): 0.1 -> 0.235,
// 0.3 -> 0.440, 0.5 -> 0.616, 0.7 -> 0.778, 0.9 -> 0.928. The ODE of the same law must agree.
TEST(DemContactOde, LammpsTsujiPolynomialDeliversTheMeasuredRestitution) {
  const double asked[] = {0.1, 0.3, 0.5, 0.7, 0.9};
  const double delivered[] = {0.235, 0.440, 0.616, 0.778, 0.928};
  for (int i = 0; i < 5; ++i) {
    EXPECT_NEAR(tsuji_restitution(lammps_tsuji_alpha(asked[i])), delivered[i], 1.5e-3) << asked[i];
  }
}

TEST(DemContactOde, LammpsTsujiInputDeliversTheTarget) {
  // Below about 0.12 the compensated input is negative (LAMMPS accepts it as a number; measured
  // in LAMMPS: target 0.05 -> e_in -0.0546 -> 0.04995 delivered).
  EXPECT_LT(lammps_tsuji_input(0.05), 0.0);
  for (const double e : {0.05, 0.3, 0.5, 0.7, 0.9}) {
    const double e_in = lammps_tsuji_input(e);
    EXPECT_LT(e_in, e);
    EXPECT_NEAR(tsuji_restitution(lammps_tsuji_alpha(e_in)), e, 1e-9);
  }
}

TEST(DemContactOde, BadInputAndNoSeparation) {
  const HertzLaw law{1e9};
  const ForceLaw f = [&law](double d, double, const ContactHistory&) { return law.force(d); };
  EXPECT_THROW(simulate_impact(f, -1.0, 1.0), InputError);
  EXPECT_THROW(simulate_impact(f, 1.0, 0.0), InputError);
  const LinearSpringDashpotLaw over{1e6, 1e5};  // zeta >> 1: never separates
  const ForceLaw g = [&over](double d, double r, const ContactHistory&) {
    return over.force(d, r);
  };
  EXPECT_THROW(simulate_impact(g, 0.01, 1.0, {.max_steps = 20000}), std::runtime_error);
}

}  // namespace
}  // namespace corlab::dem
