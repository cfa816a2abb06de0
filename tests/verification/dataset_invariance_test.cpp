// Dimensional analysis on dataset points (issue 10): a run with the same dimensionless inputs
// and other dimensions (every length x 0.4, moduli and stresses x 1/3, densities x 0.344, the
// speed that keeps k1) gives the same e. Two of the cheapest of the design's first 64 points
// are run: one with an elastic sphere, one with a yielding, hardening sphere.
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "corlab/dataset/dataset_spec.hpp"
#include "corlab/fem/solver/run_cost.hpp"
#include "corlab/fem/solver/simulate.hpp"

namespace corlab::dataset {
namespace {

// The design point's configuration (dataset base + its settings).
fem::ImpactConfig design_config(const DesignPoint& p) {
  fem::ImpactConfig c;
  study::apply_settings(c, dataset_base_settings(ImpactBox{}));
  study::apply_settings(c, p.settings);
  return c;
}

// Lengths x s, stresses x lambda, densities x mu, speed x sqrt(lambda / mu): k1, k2 and every
// ratio unchanged.
fem::ImpactConfig rescaled(fem::ImpactConfig c, double s, double lambda, double mu) {
  for (double* length : {&c.sphere.radius, &c.substrate.radius, &c.substrate.depth, &c.impact.gap,
                         &c.mesh.h_min, &c.mesh.h_max}) {
    *length *= s;
  }
  for (Material* m : {&c.sphere.material, &c.substrate.material}) {
    m->youngs_modulus *= lambda;
    m->hardening_modulus *= lambda;
    if (m->yield_stress) *m->yield_stress *= lambda;
    m->density *= mu;
  }
  c.impact.velocity *= std::sqrt(lambda / mu);
  return c;
}

// The cheapest of the first 64 design points with (yielding) or without a yielding sphere.
DesignPoint cheapest(bool yielding_sphere) {
  DesignPoint best;
  double best_cost = std::numeric_limits<double>::infinity();
  for (const DesignPoint& p : design_points(DatasetDesign{.name = "t", .points = 64, .box = {}})) {
    if (p.point.sphere_yield_ratio.has_value() != yielding_sphere) continue;
    const double cost = fem::estimate_run_cost(design_config(p)).element_steps();
    if (cost < best_cost) {
      best_cost = cost;
      best = p;
    }
  }
  return best;
}

TEST(DatasetInvariance, SameDimensionlessInputsGiveTheSameRestitution) {
  for (const bool yielding : {false, true}) {
    const DesignPoint p = cheapest(yielding);
    const fem::ImpactConfig a = design_config(p);
    const fem::ImpactConfig b = rescaled(a, 0.4, 1.0 / 3.0, 2700.0 / 7850.0);
    const fem::ImpactResult ra = fem::simulate(a);
    const fem::ImpactResult rb = fem::simulate(b);
    std::printf("design point %zu (%s sphere): v = %.4g vs %.4g m/s, e = %.9f vs %.9f\n", p.index,
                yielding ? "yielding" : "elastic", a.impact.velocity, b.impact.velocity, ra.e,
                rb.e);
    ASSERT_TRUE(ra.separated && rb.separated);
    EXPECT_EQ(ra.elements, rb.elements);
    // Measured 1.0e-11 (elastic, point 55) and 3.2e-13 (yielding, point 50) relative
    // (2026-11-27, AMD EPYC AVX-512). Bound 1e-9 kept, not tightened: the measurement is
    // round-off, and AVX2 vs AVX-512 clones of the element loop differ by ~1e-11 already.
    EXPECT_NEAR(rb.e, ra.e, 1e-9 * ra.e) << "design point " << p.index;
  }
}

}  // namespace
}  // namespace corlab::dataset
