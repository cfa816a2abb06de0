// The 3-D impact model (hex_impact.hpp) in the elastic micro-slip regime against the theory of
// Maw, Barber & Fawcett (mbf_oblique.hpp; docs/theory/oblique_theory.md): the elastic steel
// sphere on the elastic steel flat (like materials: MBF's setting, no normal-tangential coupling),
// mu = 0.3, v_n = 10 m/s (a_max = 3.75 mm, elastic), on the 70 mm block with the viscous-spring
// far boundary (a half-space for the waves), at two incidences psi1 = kappa tan(theta)/mu:
// - psi1 = 2 (theta = 36.08 deg), where the contact sticks, slips back and leaves with its
//   contact point's velocity reversed (psi2 < 0), which rigid-body theory cannot give (its psi2
//   is 0: rolling, or psi1 - 4 chi: sliding); h = 1.5 mm (a/h = 2.5, 28,924 elements, about
//   10 CPU-s);
// - psi1 = 0.5 (theta = 10.32 deg), mostly stuck: the small-angle regime, where e_t is the
//   contact's tangential compliance and converges slowest; h = 1 mm (a/h = 3.75, 52,216 elements,
//   about 30 CPU-s).
// Quasi-static cases take psi1 = 0.5, 2, 4 and 6 at v_n = 0.5 m/s and psi1 = 1 at 0.125 m/s with
// the normal penalty's compliance taken out (two runs each, about 1,300 CPU-s in all). The
// quasi-static runs (v_n = 1 m/s) and their command are in docs/theory/solver3d.md, "The
// small-angle reference". At psi1 = 0.5 and 10 m/s the normal penalty's compliance (about +0.03 in
// e_t) and the impact's speed (about -0.03; MBF is quasi-static) nearly cancel: solver3d.md, "The
// speed".
//
// The rigid flat is not used: a sphere on a rigid flat is a dissimilar pair (Dundurs' beta =
// (1 - 2 nu)/(2 (1 - nu)) = 0.29 for steel), whose normal load drives radial slip that MBF leave
// out; it gave e_t = 0.553 against MBF's 0.595 at psi1 = 2 (oblique_theory.md).
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

#include "corlab/core/units.hpp"
#include "corlab/fem/solver/simulate.hpp"
#include "corlab/restitution/mbf_oblique.hpp"

namespace corlab::fem {
namespace {

// The FE's and MBF's rebound for the steel pair at psi1 [-] and element size h [m].
struct Comparison {
  ImpactResult fe;
  restitution::MbfRebound mbf;
  double psi2 = 0.0;  // the FE's, normalised with its own rebound normal velocity [-]
};

constexpr double kMu = 0.3;

// The elastic steel pair (the config's materials, yield stresses removed) at psi1 [-] and normal
// speed v_n [m/s] with friction kMu, on the viscous-spring block, before its mesh keys.
ImpactConfig elastic_steel_case(double psi1, double normal_velocity) {
  ImpactConfig c;
  c.sphere.material.yield_stress.reset();
  c.substrate.material.yield_stress.reset();
  const double nu = c.sphere.material.poisson_ratio;
  EXPECT_EQ(nu, c.substrate.material.poisson_ratio);
  EXPECT_EQ(c.sphere.material.youngs_modulus, c.substrate.material.youngs_modulus);
  const double theta = std::atan(psi1 * kMu / (2.0 * (1.0 - nu) / (2.0 - nu)));
  c.solver.model = SolverModel::kThreeD;
  c.impact.angle = PlaneAngle{theta};
  c.impact.velocity = normal_velocity / std::cos(theta);
  c.contact.friction = kMu;
  c.substrate.boundary = SubstrateBoundary::kViscousSpring;
  return c;
}

// MBF's rebound for the case's pair, speed and angle.
restitution::MbfRebound mbf_of(const ImpactConfig& c) {
  return restitution::mbf_rebound({.radius = c.sphere.radius,
                                   .density = c.sphere.material.density,
                                   .sphere_modulus = c.sphere.material.youngs_modulus,
                                   .sphere_poisson = c.sphere.material.poisson_ratio,
                                   .flat_modulus = c.substrate.material.youngs_modulus,
                                   .flat_poisson = c.substrate.material.poisson_ratio,
                                   .velocity = c.impact.velocity,
                                   .angle = c.impact.angle.radians / units::kDegree,
                                   .friction = c.contact.friction});
}

Comparison run_against_mbf(double psi1, double h) {
  constexpr double kNormalVelocity = 10.0;  // [m/s]
  ImpactConfig c = elastic_steel_case(psi1, kNormalVelocity);
  c.mesh.h_min = h;
  c.mesh.contact_elements = 0.0;
  validate(c);
  const double theta = c.impact.angle.radians;
  const double nu = c.sphere.material.poisson_ratio;
  const double kappa = 2.0 * (1.0 - nu) / (2.0 - nu);
  Comparison out;
  out.fe = simulate(c);
  out.mbf = mbf_of(c);
  EXPECT_NEAR(out.mbf.psi1, psi1, 1e-12);
  EXPECT_FALSE(out.mbf.gross_sliding);
  // The contact point at rebound (e_n differs from MBF's 1 by 2 %: it enters psi2 through v_n').
  const double v_t = c.impact.velocity * std::sin(theta);
  const double slip = out.fe.e_t * v_t - c.sphere.radius * out.fe.omega;
  out.psi2 = kappa * slip / (kMu * out.fe.e_n * kNormalVelocity);
  return out;
}

// The waves carry energy away through the far boundary: Hunter (1957, Johnson 1985 section
// 11.4) puts the loss into a half-space at 2.4 % of E0 here, e_n = 0.988; measured 0.980.
void expect_elastic_rebound(const ImpactResult& r) {
  ASSERT_EQ(r.status, RunStatus::kSeparated);
  EXPECT_LT(r.e_n, 1.0);
  EXPECT_GT(r.e_n, 0.975);
  EXPECT_LT(r.energy_balance_error, 1e-3);
}

TEST(MbfHexImpact, MicroSlipOnTheElasticFlatFollowsMbf) {
  const Comparison c = run_against_mbf(2.0, 1.5e-3);
  expect_elastic_rebound(c.fe);
  // Measured (kinematic stick at the contact points, the default): e_t 0.5913 vs 0.5947,
  // omega R / v_n 0.7420 vs 0.7383 (+0.5 %), energy balance 6.5e-5 (0.10.0's lumped sphere:
  // 0.5909, +0.5 %, psi2 -0.872 vs -0.837);
  // friction at the slave nodes (0.9.0) gave 0.5930, -0.04 %, -0.857. The tangential penalty
  // (contact.friction_enforcement = penalty) gave e_t 0.5776 here (with 0.8.0's contact), 0.0171
  // below MBF: its compliance in series with the bodies'.
  // Bounds: issue 39's for the converged mesh, e_t within 0.01 and omega within 3 %, which this
  // coarse case meets; psi2 within 0.1 (rolling's 0 is 0.84 away).
  EXPECT_NEAR(c.fe.e_t, c.mbf.tangential_restitution, 0.01);
  EXPECT_NEAR(c.fe.omega / c.mbf.spin, 1.0, 0.03);
  EXPECT_NEAR(c.psi2, c.mbf.psi2, 0.1);
  EXPECT_LT(c.psi2, -0.5);  // the contact point's velocity has reversed
}

TEST(MbfHexImpact, SmallIncidenceOnTheElasticFlatFollowsMbf) {
  const Comparison c = run_against_mbf(0.5, 1e-3);
  expect_elastic_rebound(c.fe);
  // Measured (contact points): e_t 0.7404 vs MBF 0.7416, omega R / v_n 0.1182 vs 0.1177
  // (+0.5 %; 0.10.0's lumped sphere 0.7401, +0.5 %); at h = 1.5 mm 0.7494 and -3.3 % (0.10.0).
  // Friction at the slave nodes (0.9.0) gave 0.7525 and -4.2 % here, 0.7674 and -10.3 % at 1.5 mm:
  // its e_t came down to MBF from above. Bounds: issue 39's, e_t within 0.01 and omega within 3 %.
  EXPECT_NEAR(c.fe.e_t, c.mbf.tangential_restitution, 0.01);
  EXPECT_NEAR(c.fe.omega / c.mbf.spin, 1.0, 0.03);
}

// One case at a quasi-static speed with the normal penalty's compliance taken out: the steel
// pair scaled to R = 2.5 mm on a 10 mm viscous-spring block, at psi1 [-] and v_n [m/s], a/4, run
// at two penalty scales; e_t and omega taken out linearly in the deepest penetration over
// delta_max (solver3d.md, "The speed").
struct QuasiStatic {
  double e_t_soft = 0.0;   // at solver.penalty_scale 0.28 [-]
  double e_t_stiff = 0.0;  // at 0.5 [-]
  double e_t = 0.0;        // at no penetration [-]
  double omega = 0.0;      // at no penetration [rad/s]
  restitution::MbfRebound mbf;
};

QuasiStatic quasi_static_against_mbf(double psi1, double normal_velocity) {
  ImpactConfig c = elastic_steel_case(psi1, normal_velocity);
  c.sphere.radius = 2.5e-3;
  c.substrate.radius = 0.01;
  c.substrate.depth = 0.01;
  c.mesh.contact_elements = 4.0;
  c.mesh.h_min = 1.25e-4;
  c.mesh.h_max = 1e-3;
  c.mesh.growth = 1.6;
  struct Run {
    double e_t, omega, penetration;  // [-], [rad/s], over delta_max [-]
  };
  const double v_t = c.impact.velocity * std::sin(c.impact.angle.radians);
  const auto run = [&c, v_t](double penalty_scale) {
    ImpactConfig k = c;
    k.solver.penalty_scale = penalty_scale;
    validate(k);
    const ImpactResult r = simulate(k);
    expect_elastic_rebound(r);
    // The tangential impulse m (1 - e_t) v_t acts at the contact, R from the centre, and gives
    // the spin I omega: their ratio is the sphere's gyration I/(m R^2) = 2/5 up to the contact's
    // depth (delta/R = 1.4e-3 at 0.5 m/s) and the pressure's shift. Measured 0.39999-0.40011
    // over these cases; the lumped mesh's own (corlab 0.10.0) gave 0.4020.
    EXPECT_NEAR((1.0 - r.e_t) * v_t / (r.omega * k.sphere.radius), 0.4, 5e-4);
    return Run{r.e_t, r.omega, r.penetration_max / r.delta_max};
  };
  const Run soft = run(0.28);
  const Run stiff = run(0.5);
  EXPECT_GT(soft.penetration, stiff.penetration);
  const auto at_no_penetration = [&](double soft_value, double stiff_value) {
    return stiff_value -
           (soft_value - stiff_value) / (soft.penetration - stiff.penetration) * stiff.penetration;
  };
  QuasiStatic out{.e_t_soft = soft.e_t,
                  .e_t_stiff = stiff.e_t,
                  .e_t = at_no_penetration(soft.e_t, stiff.e_t),
                  .omega = at_no_penetration(soft.omega, stiff.omega),
                  .mbf = mbf_of(c)};
  EXPECT_NEAR(out.mbf.psi1, psi1, 1e-12);
  std::printf("psi1 %.2f, v_n %.3f m/s, no penetration: e_t %.4f (MBF %.4f), omega / MBF's %.4f\n",
              psi1, normal_velocity, out.e_t, out.mbf.tangential_restitution,
              out.omega / out.mbf.spin);
  return out;
}

// The small-angle case, psi1 = 0.5, at v_n = 0.5 m/s. Each run about 100 CPU-s.
TEST(MbfHexImpact, QuasiStaticSmallIncidenceWithoutThePenaltysComplianceFollowsMbf) {
  const QuasiStatic q = quasi_static_against_mbf(0.5, 0.5);
  // The penalty's compliance raises e_t (0.7622 at 0.28, 0.7518 at 0.5, penetration 3.9 % and
  // 2.3 % of delta_max, measured).
  EXPECT_GT(q.e_t_soft, q.e_t_stiff);
  // Measured: e_t 0.7370 against MBF's 0.7416 (-0.0046), omega +1.8 %; at 1 m/s -0.0081 and
  // +3.1 %, at 0.25 m/s -0.0018 and +0.7 % (the speed's share). Bounds: issue 39's.
  EXPECT_NEAR(q.e_t, q.mbf.tangential_restitution, 0.01);
  EXPECT_NEAR(q.omega / q.mbf.spin, 1.0, 0.03);
}

// The rest of MBF's range, each at a speed where the FE's dynamic deficit is inside issue 39's
// bounds (solver3d.md, "The speed"): psi1 = 1, where the contact point's velocity just reverses
// (MBF's psi2 -0.060) and the deficit shrinks slowest with the speed, at 0.125 m/s (about 270
// CPU-s a run); 2, 4 and 6 (gross sliding) at 0.5 m/s (about 90 CPU-s a run).
struct PsiCase {
  double psi1;             // [-]
  double normal_velocity;  // [m/s]
};

void PrintTo(const PsiCase& c, std::ostream* os) {
  *os << "psi1 " << c.psi1 << " at " << c.normal_velocity << " m/s";
}

class QuasiStaticOverPsi1 : public ::testing::TestWithParam<PsiCase> {};

TEST_P(QuasiStaticOverPsi1, WithoutThePenaltysComplianceFollowsMbf) {
  const QuasiStatic q = quasi_static_against_mbf(GetParam().psi1, GetParam().normal_velocity);
  // Measured (e_t, omega against MBF): psi1 1 -0.0077, +2.6 % (-0.0121, +4.0 % at 0.5 m/s);
  // 2 -0.0063, +1.5 %; 4 0.0000, -0.0 %; 6 +0.0011, -0.4 %. Bounds: issue 39's.
  EXPECT_NEAR(q.e_t, q.mbf.tangential_restitution, 0.01);
  EXPECT_NEAR(q.omega / q.mbf.spin, 1.0, 0.03);
}

INSTANTIATE_TEST_SUITE_P(
    MbfHexImpact,
    QuasiStaticOverPsi1,
    ::testing::Values(PsiCase{1.0, 0.125}, PsiCase{2.0, 0.5}, PsiCase{4.0, 0.5}, PsiCase{6.0, 0.5}),
    [](const ::testing::TestParamInfo<PsiCase>& param) {
      return "psi1_" + std::to_string(static_cast<int>(param.param.psi1));
    });

}  // namespace
}  // namespace corlab::fem
