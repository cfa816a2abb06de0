// Verification: elastic sphere on an elastic substrate, and on the rigid flat, against Hertz
// (Johnson 1985, eqs. 11.22-11.24; the rigid flat: E* = E / (1 - nu^2)): F_max within 2 %,
// delta_max and the contact time within 1 %, 0.9995 <= e <= 1.
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

#include "corlab/fem/mesh/contact_estimate.hpp"
#include "corlab/fem/solver/simulate.hpp"

namespace corlab::fem {
namespace {

class HertzElastic : public ::testing::TestWithParam<std::tuple<double, SubstrateShape>> {};

TEST_P(HertzElastic, MatchesHertz) {
  const auto [v, shape] = GetParam();
  ImpactConfig c;
  c.impact.velocity = v;
  c.substrate.shape = shape;
  c.substrate.material.yield_stress = std::nullopt;  // elastic substrate
  const ImpactResult r = simulate(c);
  // Hertz reference (itself checked against an RK4 integration of the Hertz impact in
  // tests/unit/fem/mesh/mesh_contact_estimate_test.cpp).
  const HertzReference hertz = hertz_reference(c);
  const double delta = hertz.max_overlap;
  const double force = hertz.max_force;
  const double t_c = hertz.contact_time;
  std::printf(
      "%s, v = %.2f m/s: F_max = %.6g N (Hertz %.6g, %+.2f %%), delta_max = %.6g m (Hertz %.6g, "
      "%+.2f %%), t_c = %.6g s (Hertz %.6g, %+.2f %%), e = %.5f, balance = %.2e, elements = "
      "%d, steps = %lld\n",
      std::string(to_string(shape)).c_str(), v, r.F_max, force, 100 * (r.F_max / force - 1),
      r.delta_max, delta, 100 * (r.delta_max / delta - 1), r.t_contact, t_c,
      100 * (r.t_contact / t_c - 1), r.e, r.energy_balance_error, r.elements, r.steps);
  EXPECT_TRUE(r.separated);
  // Measured 2026-11-27 (AMD EPYC, AVX-512) at 0.5 / 2 m/s: F_max +0.56 / +1.26 %, delta_max
  // +0.06 / -0.50 %, t_c -0.14 / -0.72 %, 1 - e 3.1e-5 / 8.3e-5 (h_contact = a/12 at both);
  // on the rigid flat F_max +0.68 / +1.53 %, delta_max -0.00 / -0.68 %, t_c -0.15 / -0.91 %,
  // 1 - e 4e-5 / 1.0e-4 (its t_c at 2 m/s is within 1.1x of the bound: the deviation from
  // Hertz grows with the speed on both targets; deterministic to ~1e-11 across SIMD levels).
  // F_max: bound 2 % kept, not tightened: 2 m/s sits at 1.26 % (1.6x margin).
  EXPECT_NEAR(r.F_max, force, 0.02 * force);
  // delta_max: bound 1 % (was 2 %): 2x the worst measured (2 m/s).
  EXPECT_NEAR(r.delta_max, delta, 0.01 * delta);
  // t_c: bound 1 % (was 2 %): 1.4x the worst measured (2 m/s); a softer contact breaks it.
  EXPECT_NEAR(r.t_contact, t_c, 0.01 * t_c);
  // 1 - e <= 5e-4 (was e >= 0.99): 6x the worst measured (2 m/s), the elastic waves' share.
  EXPECT_GE(r.e, 0.9995);
  // Added: an elastic impact gives back at most what it was given (the subcycling resonance of
  // subcycling_resonance_test.cpp gave e = 1.00006, which e >= 0.99 alone lets through).
  EXPECT_LE(r.e, 1.0);
  EXPECT_EQ(r.energy_dissipated_plastic, 0.0);
}

INSTANTIATE_TEST_SUITE_P(Velocities,
                         HertzElastic,
                         ::testing::Combine(::testing::Values(0.5, 2.0),
                                            ::testing::Values(SubstrateShape::kFlat,
                                                              SubstrateShape::kRigid)));

}  // namespace
}  // namespace corlab::fem
