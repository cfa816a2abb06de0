// Verification: elastic sphere on an elastic substrate against Hertz (Johnson 1985, eqs.
// 11.22-11.24): F_max, delta_max and the contact time within 2 %, e >= 0.99.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "corlab/core/units.hpp"
#include "corlab/fem/simulate.hpp"
#include "corlab/materials/material.hpp"

namespace corlab::fem {
namespace {

class HertzElastic : public ::testing::TestWithParam<double> {};

TEST_P(HertzElastic, MatchesHertz) {
  const double v = GetParam();
  ImpactConfig c;
  c.impact.velocity = v;
  c.substrate.material.yield_stress = std::nullopt;  // elastic substrate
  const ImpactResult r = simulate(c);
  // Hertz, computed here independently of the mesh sizing code.
  const double radius = c.sphere.radius;
  const double mass = 4.0 / 3.0 * units::kPi * std::pow(radius, 3) * c.sphere.material.density;
  const double e_star = effective_modulus(c.sphere.material, c.substrate.material);
  const double delta = std::pow(15.0 * mass * v * v / (16.0 * e_star * std::sqrt(radius)), 0.4);
  const double force = 4.0 / 3.0 * e_star * std::sqrt(radius) * std::pow(delta, 1.5);
  const double t_c = 2.9432 * delta / v;  // 2 int_0^1 (1 - x^2.5)^-0.5 dx = 2.9432
  std::printf(
      "v = %.2f m/s: F_max = %.6g N (Hertz %.6g, %+.2f %%), delta_max = %.6g m (Hertz %.6g, "
      "%+.2f %%), t_c = %.6g s (Hertz %.6g, %+.2f %%), e = %.5f, balance = %.2e, elements = "
      "%d, steps = %lld\n",
      v, r.force_max, force, 100 * (r.force_max / force - 1), r.indentation_max, delta,
      100 * (r.indentation_max / delta - 1), r.contact_time, t_c, 100 * (r.contact_time / t_c - 1),
      r.e, r.energy_balance_error, r.elements, r.steps);
  EXPECT_TRUE(r.separated);
  EXPECT_NEAR(r.force_max, force, 0.02 * force);
  EXPECT_NEAR(r.indentation_max, delta, 0.02 * delta);
  EXPECT_NEAR(r.contact_time, t_c, 0.02 * t_c);
  EXPECT_GE(r.e, 0.99);
  EXPECT_EQ(r.energy_dissipated_plastic, 0.0);
}

INSTANTIATE_TEST_SUITE_P(Velocities, HertzElastic, ::testing::Values(0.5, 2.0));

}  // namespace
}  // namespace corlab::fem
