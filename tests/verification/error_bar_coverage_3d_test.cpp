// Verification of the 3-D model's error bars on e_n, e_t and omega (discretisation_error.hpp,
// error_bars.md "The 3-D model"), end to end: two cases of the first seeded sample
// (data/error_bar_coverage/3d_seed20261129), one elastic and one elastic-plastic, each run with its
// error estimate and again at h / sqrt 2. Each finer value must lie inside its bar (as measured: 6
// of 6), and the median of the six bars, relative to each value, must be at most issue 39's 3 x
// the median relative change: 2.61 x with the friction at the contact points (3.05e-2 against
// 1.17e-2; 0.9.0's contact: 2.60 x, 4.71e-2 against 1.81e-2; about 3.2 x with scatter_3d on e_t
// and omega). A median over six values of two cases: the stored samples' 24 cases per quantity
// are re-scored by python/tests/test_error_bar_coverage_3d.py.
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "corlab/fem/solver/discretisation_error.hpp"
#include "corlab/fem/solver/error_bar.hpp"
#include "support/coverage_tally.hpp"

namespace corlab::fem {
namespace {

/// One case of the script's sample: its BASE settings with the drawn angle [deg], speed [m/s],
/// friction [-] and the flat's yield stress ("none": elastic).
ImpactConfig sample_case(double angle, double velocity, double friction, const char* sigma_y) {
  ImpactConfig c;
  apply_settings(
      c,
      {"solver.model=3d", "sphere.radius=2.5e-3", "substrate.radius=2.5e-3",
       "substrate.depth=2.5e-3", "mesh.contact_elements=4", "mesh.h_min=1.25e-4", "mesh.h_max=1e-3",
       "mesh.growth=1.6", "impact.angle=" + std::to_string(angle),
       "impact.velocity=" + std::to_string(velocity),
       "contact.friction=" + std::to_string(friction), std::string("substrate.sigma_y=") + sigma_y},
      "test");
  return c;
}

TEST(ErrorBarCoverage3d, TwoCasesOfTheSeededSample) {
  struct Case {
    double angle, velocity, friction;
    const char* sigma_y;
  };
  const std::array<Case, 2> cases{{{3.83, 5.911, 0.147, "none"}, {6.14, 1.422, 0.255, "850e6"}}};
  test::CoverageTally tally;  // relative to each value: omega is 28-96 rad/s, e_n near 1
  for (const Case& k : cases) {
    const ImpactConfig c = sample_case(k.angle, k.velocity, k.friction, k.sigma_y);
    const ImpactResult r = simulate_with_error_estimate(c);
    SimulationControl e_only;  // as the companions: ends one short window after the contact
    e_only.e_only = true;
    const ImpactResult finer = simulate(coarsened(c, 1.0 / std::sqrt(2.0)), e_only);
    ASSERT_TRUE(r.separated && finer.separated) << r.status_detail << finer.status_detail;
    const std::array<std::array<double, 3>, 3> rows{{{r.e_n, r.e_error, finer.e_n},
                                                     {r.e_t, r.e_t_error, finer.e_t},
                                                     {r.omega, r.omega_error, finer.omega}}};
    for (const auto& [x, bar, fine] : rows) {
      ASSERT_TRUE(std::isfinite(bar)) << r.e_error_reason;
      const double scale = std::abs(x);
      const char* verdict = tally.add(bar / scale, std::abs(fine - x) / scale);
      std::printf("%5.2f deg, %6.3f m/s: %.5g +/- %.3g, finer %.5g (%s)\n", k.angle, k.velocity, x,
                  bar, fine, verdict);
    }
  }
  tally.print();
  EXPECT_EQ(tally.inside, 6);
  EXPECT_LE(test::median(tally.bars), 3.0 * test::median(tally.changes));
}

}  // namespace
}  // namespace corlab::fem
