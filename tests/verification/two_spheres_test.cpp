// Verification of two deformable spheres (substrate.shape = sphere: a head-on impact on a second,
// free sphere at rest): Hertz with R*, m*, E* (Johnson 1985, section 11.4); the symmetry
// identity (two identical spheres approaching at 2v are each a sphere on the rigid flat at v: the
// symmetry plane is that flat); momentum conservation; the error bar against h/2; the flat as
// the limit R2 -> infinity.
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "corlab/fem/mesh/contact_estimate.hpp"
#include "corlab/fem/solver/discretisation_error.hpp"
#include "corlab/fem/solver/simulate.hpp"

namespace corlab::fem {
namespace {

ImpactConfig two_spheres(double r2, double velocity) {
  ImpactConfig c;
  c.substrate.shape = SubstrateShape::kSphere;
  c.substrate.radius = r2;
  c.impact.velocity = velocity;
  return c;
}

TEST(TwoSpheres, ElasticSpheresOfDifferentSizeAndMaterialMatchHertz) {
  // Steel R1 = 35 mm on aluminium R2 = 20 mm (E 70 GPa, nu 0.33, rho 2700) at 1 m/s.
  ImpactConfig c = two_spheres(20e-3, 1.0);
  c.substrate.material = Material{.name = "aluminium (elastic)",
                                  .youngs_modulus = 70e9,
                                  .poisson_ratio = 0.33,
                                  .density = 2700.0,
                                  .yield_stress = std::nullopt,
                                  .source = "test values"};
  const HertzReference hertz = hertz_reference(c);
  const ImpactResult r = simulate(c);
  std::printf("F_max %+.2f %%, delta_max %+.2f %%, t_c %+.2f %%, e = %.6f, balance %.2e\n",
              100 * (r.F_max / hertz.max_force - 1), 100 * (r.delta_max / hertz.max_overlap - 1),
              100 * (r.t_contact / hertz.contact_time - 1), r.e, r.energy_balance_error);
  ASSERT_TRUE(r.separated) << r.status_detail;
  // Measured 2026-11-27 (AMD EPYC): F_max +0.88 %, delta_max -0.12 %, t_c -0.32 %, 1 - e 4.5e-5;
  // the bounds of the sphere on a flat (hertz_elastic_test.cpp).
  EXPECT_NEAR(r.F_max, hertz.max_force, 0.02 * hertz.max_force);
  EXPECT_NEAR(r.delta_max, hertz.max_overlap, 0.01 * hertz.max_overlap);
  EXPECT_NEAR(r.t_contact, hertz.contact_time, 0.01 * hertz.contact_time);
  EXPECT_GE(r.e, 0.9995);
  EXPECT_LE(r.e, 1.0);
  EXPECT_LT(r.energy_balance_error, 1e-5);
}

TEST(TwoSpheres, TwoIdenticalSpheresAreEachASphereOnTheRigidFlat) {
  // Both spheres yield (sigma_y = 500 MPa): approach at 10 m/s against one sphere on the rigid
  // flat at 5 m/s, at the paper's contact resolution. The meshes' contact zones are the same
  // (R* = R/2, m* = m/2, E* halved, twice the speed: the same predicted contact radius).
  ImpactConfig pair = two_spheres(35e-3, 10.0);
  pair.sphere.material.yield_stress = 500e6;
  pair.substrate.material = pair.sphere.material;
  ImpactConfig flat;
  flat.substrate.shape = SubstrateShape::kRigid;
  flat.sphere.material.yield_stress = 500e6;
  flat.impact.velocity = 5.0;
  const ImpactResult p = simulate(pair);
  const ImpactResult f = simulate(flat);
  std::printf(
      "pair e = %.6f, rigid flat e = %.6f (%+.3f %%); loss %.5g J vs 2 x %.5g J; "
      "v1' + v2' + 10 = %.3g m/s; balance %.2e\n",
      p.e, f.e, 100 * (p.e / f.e - 1), p.energy_sphere_loss, f.energy_sphere_loss,
      p.sphere_velocity_final + p.target_velocity_final + 10.0, p.energy_balance_error);
  ASSERT_TRUE(p.separated) << p.status_detail;
  ASSERT_TRUE(f.separated) << f.status_detail;
  // Measured: +0.30 % (h = 0.25 mm; +0.68 % at 0.5 mm); the bound 0.5 %.
  EXPECT_NEAR(p.e, f.e, 5e-3 * f.e);
  // The relative motion's energy loss is the two halves' (measured -0.10 %); bound 0.5 %.
  EXPECT_NEAR(p.energy_sphere_loss, 2.0 * f.energy_sphere_loss, 5e-3 * p.energy_sphere_loss);
  // Momentum: identical masses (mirror-image meshes), so v1' + v2' = -v0 (down) to round-off
  // (measured 1.8e-14 m/s); bound 1e-10 of v0.
  EXPECT_NEAR(p.sphere_velocity_final + p.target_velocity_final, -10.0, 1e-9);
  EXPECT_LT(p.energy_balance_error, 2e-5);
}

TEST(TwoSpheres, ErrorBarBracketsTheFinerMesh) {
  // Two identical spheres, both yielding (sigma_y = 500 MPa), 10 m/s: the run at the default
  // mesh with its error bar (discretisation_error.hpp) against the same case at h/2.
  ImpactConfig c = two_spheres(35e-3, 10.0);
  c.sphere.material.yield_stress = 500e6;
  c.substrate.material = c.sphere.material;
  const ImpactResult r = simulate_with_error_estimate(c);
  const ImpactResult finer = simulate(coarsened(c, 0.5));
  ASSERT_TRUE(r.separated && finer.separated) << r.status_detail << finer.status_detail;
  std::printf("e = %.5f +/- %.5f; e(h/2) = %.5f (%+.5f)\n", r.e, r.e_error, finer.e, finer.e - r.e);
  // Measured 2026-11-27 (AMD EPYC): 0.37436 +/- 0.00562, e(h/2) = 0.37133 (-0.00303, 0.54 of
  // the bar). h_min = 0.18 mm alone (`--set mesh.h_min=0.18e-3`) gives 0.36855 (-0.00581), just
  // outside (1.03 bars): e scatters with h here as on the flat (docs/theory/error_bars.md: a
  // bound in about 95 % of cases).
  EXPECT_LE(std::abs(finer.e - r.e), r.e_error);
  EXPECT_LT(r.e_error, 0.02 * r.e);
}

TEST(TwoSpheres, ALargeSecondSphereTendsToTheFlat) {
  // The paper's pair (elastic sphere, elastic-perfectly plastic target, 5 m/s) with the target a
  // sphere of R2 = 10 and 30 R1, against the flat, on the coarse mesh. A rate-independent impact
  // has no length scale of its own, so e depends on the geometry only through R1/R2: linear
  // extrapolation of e in R1/R2 to 0 must give the flat's e.
  auto with_target_radius = [](double r2) {
    ImpactConfig c = two_spheres(r2, 5.0);
    c.mesh.h_min = 0.5e-3;
    return simulate(c);
  };
  ImpactConfig flat_case;
  flat_case.mesh.h_min = 0.5e-3;
  const ImpactResult flat = simulate(flat_case);
  const ImpactResult r10 = with_target_radius(0.35);
  const ImpactResult r30 = with_target_radius(1.05);
  ASSERT_TRUE(flat.separated && r10.separated && r30.separated) << r30.status_detail;
  const double x10 = 1.0 / 10.0, x30 = 1.0 / 30.0;
  const double extrapolated = r30.e + (r30.e - r10.e) * x30 / (x10 - x30);
  std::printf("flat e = %.6f; R2 = 10 R1: %+.3f %%, 30 R1: %+.3f %%, extrapolated %+.3f %%\n",
              flat.e, 100 * (r10.e / flat.e - 1), 100 * (r30.e / flat.e - 1),
              100 * (extrapolated / flat.e - 1));
  // Measured 2026-11-27 (AMD EPYC): -2.39 %, -0.80 %, extrapolated -0.007 % (and R2 = 3 R1
  // -8.2 %, 100 R1 -0.17 %: first order in R1/R2 throughout). Bounds: the approach monotone, the
  // extrapolation within 0.2 % (30 x the measurement; e scatters by ~0.5 % with h, issue 28).
  EXPECT_LT(r10.e, r30.e);
  EXPECT_LT(r30.e, flat.e);
  EXPECT_NEAR(extrapolated, flat.e, 2e-3 * flat.e);
}

}  // namespace
}  // namespace corlab::fem
