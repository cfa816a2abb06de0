// The 3-D impact model (hex_impact.hpp) in the elastic micro-slip regime against the theory of
// Maw, Barber & Fawcett (mbf_oblique.hpp; docs/theory/oblique_theory.md): the elastic steel
// sphere on the elastic steel flat (like materials: MBF's setting, no normal-tangential coupling),
// mu = 0.3, at psi1 = kappa tan(theta)/mu = 2 (theta = 36.08 deg), where the contact sticks,
// slips back and leaves with its contact point's velocity reversed (psi2 < 0), which rigid-body
// theory cannot give (its psi2 is 0: rolling, or psi1 - 4 chi: sliding). Coarse mesh (h = 1.5 mm,
// a/h = 2.5, 28,924 elements, about 8 CPU-s) on the 70 mm block with the viscous-spring far
// boundary (a half-space for the waves); the converged quasi-static runs (v_n = 1 m/s, h = 0.6 mm)
// and their command are in docs/theory/solver3d.md, "The small-angle reference".
//
// The rigid flat is not used: a sphere on a rigid flat is a dissimilar pair (Dundurs' beta =
// (1 - 2 nu)/(2 (1 - nu)) = 0.29 for steel), whose normal load drives radial slip that MBF leave
// out; it gave e_t = 0.553 against MBF's 0.595 at the same psi1 (oblique_theory.md).
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>

#include "corlab/core/units.hpp"
#include "corlab/fem/solver/simulate.hpp"
#include "corlab/restitution/mbf_oblique.hpp"

namespace corlab::fem {
namespace {

TEST(MbfHexImpact, MicroSlipOnTheElasticFlatFollowsMbf) {
  constexpr double kMu = 0.3;
  constexpr double kPsi1 = 2.0;
  constexpr double kNormalVelocity = 10.0;  // [m/s]: a_max = 3.75 mm, elastic
  ImpactConfig c;
  c.sphere.material.yield_stress.reset();
  c.substrate.material.yield_stress.reset();
  const double nu = c.sphere.material.poisson_ratio;
  ASSERT_EQ(nu, c.substrate.material.poisson_ratio);
  ASSERT_EQ(c.sphere.material.youngs_modulus, c.substrate.material.youngs_modulus);
  const double kappa = 2.0 * (1.0 - nu) / (2.0 - nu);
  const double theta = std::atan(kPsi1 * kMu / kappa);
  c.solver.model = SolverModel::kThreeD;
  c.impact.angle = PlaneAngle{theta};
  c.impact.velocity = kNormalVelocity / std::cos(theta);
  c.contact.friction = kMu;
  c.mesh.h_min = 1.5e-3;
  c.mesh.contact_elements = 0.0;
  c.substrate.boundary = SubstrateBoundary::kViscousSpring;
  validate(c);
  const ImpactResult r = simulate(c);
  ASSERT_EQ(r.status, RunStatus::kSeparated);
  // The waves carry energy away through the far boundary: Hunter (1957, Johnson 1985 section
  // 11.4) puts the loss into a half-space at 2.4 % of E0 here, e_n = 0.988; measured 0.9804.
  EXPECT_LT(r.e_n, 1.0);
  EXPECT_GT(r.e_n, 0.975);

  const restitution::MbfRebound mbf =
      restitution::mbf_rebound({.radius = c.sphere.radius,
                                .density = c.sphere.material.density,
                                .sphere_modulus = c.sphere.material.youngs_modulus,
                                .sphere_poisson = nu,
                                .flat_modulus = c.substrate.material.youngs_modulus,
                                .flat_poisson = c.substrate.material.poisson_ratio,
                                .velocity = c.impact.velocity,
                                .angle = theta / units::kDegree,
                                .friction = kMu});
  ASSERT_NEAR(mbf.psi1, kPsi1, 1e-12);
  ASSERT_FALSE(mbf.gross_sliding);
  // The FE's contact point at rebound, normalised with its own rebound normal velocity (e_n
  // differs from MBF's 1 by 2 %: that enters psi2 through v_n' only).
  const double v_t = c.impact.velocity * std::sin(theta);
  const double slip = r.e_t * v_t - c.sphere.radius * r.omega;
  const double psi2 = kappa * slip / (kMu * r.e_n * kNormalVelocity);
  // Measured (kinematic stick, the default): e_t 0.5863 vs 0.5947, omega R / v_n 0.7491 vs 0.7383
  // (+1.5 %), psi2 -0.902 vs -0.837, e_n 0.9804 (the waves' energy leaves through the far
  // boundary). Quasi-static (v_n = 1 m/s, h = 0.6 mm) the same contact gives e_t 0.5940, omega
  // -0.05 %, psi2 -0.842: this case's distance from MBF is its speed and mesh. The tangential
  // penalty (contact.friction_enforcement = penalty) gives e_t 0.5776 here, 0.0171 below MBF:
  // its compliance in series with the bodies'.
  // Bounds: issue 39's for the converged mesh, e_t within 0.01 and omega within 3 %, which this
  // coarse case meets; psi2 within 0.1 (rolling's 0 is 0.84 away).
  EXPECT_NEAR(r.e_t, mbf.tangential_restitution, 0.01);
  EXPECT_NEAR(r.omega / mbf.spin, 1.0, 0.03);
  EXPECT_NEAR(psi2, mbf.psi2, 0.1);
  EXPECT_LT(psi2, -0.5);                    // the contact point's velocity has reversed
  EXPECT_LT(r.energy_balance_error, 1e-3);  // measured 5.7e-5
}

}  // namespace
}  // namespace corlab::fem
