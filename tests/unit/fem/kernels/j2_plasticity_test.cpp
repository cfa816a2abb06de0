// J2 radial return (j2_plasticity.hpp) against the analytic uniaxial-stress response.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/kernels/j2_plasticity.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace corlab::fem {
namespace {

constexpr double kE = 210e9;
constexpr double kNu = 0.3;
constexpr double kSy = 500e6;

J2Plasticity steel(double hardening) { return J2Plasticity::from(kE, kNu, kSy, hardening); }

// Drives a material point in uniaxial stress along z: for each axial strain increment the
// lateral increment (rr = tt) is found so that sigma_rr = sigma_tt = 0 (secant iteration).
struct UniaxialDriver {
  J2Plasticity mat;
  AxisymTensor stress;
  J2Plasticity::State state;
  double plastic_work = 0.0;
  double internal_work = 0.0;

  void step(double d_axial) {
    auto trial = [&](double lateral, AxisymTensor& s, J2Plasticity::State& st) {
      s = stress;
      st = state;
      return mat.update(s, st, AxisymTensor{lateral, d_axial, lateral, 0.0});
    };
    double x0 = -kNu * d_axial, x1 = -0.5 * d_axial;
    AxisymTensor s;
    J2Plasticity::State st;
    trial(x0, s, st);
    double f0 = s.rr;
    for (int it = 0; it < 50; ++it) {
      trial(x1, s, st);
      const double f1 = s.rr;
      if (std::abs(f1) < 1e-6 || f1 == f0) break;
      const double x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
      x0 = x1;
      f0 = f1;
      x1 = x2;
    }
    const AxisymTensor old = stress;
    const auto inc = trial(x1, stress, state);
    plastic_work += inc.plastic_work;
    const AxisymTensor de{x1, d_axial, x1, 0.0};
    internal_work += 0.5 * (contract(old, de) + contract(stress, de));
  }
};

TEST(J2Plasticity, UniaxialElasticPerfectlyPlastic) {
  UniaxialDriver d{steel(0.0), {}, {}};
  const double de = 1e-5;
  for (int n = 1; n <= 800; ++n) {
    d.step(de);
    const double eps = n * de;
    const double expected = std::min(kE * eps, kSy);
    ASSERT_NEAR(d.stress.zz, expected, 1e-6 * kSy) << "eps = " << eps;
    EXPECT_NEAR(d.stress.rr, 0.0, 1e-3);
  }
  // Plastic strain = eps - sigma_y / E once yielded.
  EXPECT_NEAR(d.state.eps_p, 800 * de - kSy / kE, 1e-9);
}

TEST(J2Plasticity, UniaxialLinearHardening) {
  const double h = 0.1 * kE;
  UniaxialDriver d{steel(h), {}, {}};
  const double e_t = kE * h / (kE + h);  // elastic-plastic tangent modulus
  const double de = 1e-5;
  for (int n = 1; n <= 1000; ++n) {
    d.step(de);
    const double eps = n * de;
    const double eps_y = kSy / kE;
    const double expected = eps <= eps_y ? kE * eps : kSy + e_t * (eps - eps_y);
    // One increment straddles the yield point: the radial return is exact for linear
    // hardening, so only round-off remains.
    ASSERT_NEAR(d.stress.zz, expected, 1e-6 * kSy) << "eps = " << eps;
  }
  // Consistency: sigma_eq equals the current flow stress after the return.
  EXPECT_NEAR(von_mises(d.stress), d.mat.flow_stress(d.state), 1e-6 * kSy);
}

TEST(J2Plasticity, ReturnLandsOnTheYieldSurface) {
  const J2Plasticity mat = steel(2e9);
  AxisymTensor s;
  J2Plasticity::State st;
  const auto inc = mat.update(s, st, AxisymTensor{0.004, -0.003, 0.001, 0.002});
  EXPECT_GT(inc.d_eps_p, 0.0);
  EXPECT_NEAR(von_mises(s), mat.flow_stress(st), 1e-9 * kSy);
  // The return is radial: the pressure is the elastic trial pressure.
  const double trial_p = mat.bulk_modulus * (0.004 - 0.003 + 0.001);
  EXPECT_NEAR(trace(s) / 3.0, trial_p, 1e-9 * kSy);
}

TEST(J2Plasticity, PurePressureNeverYields) {
  const J2Plasticity mat = steel(0.0);
  AxisymTensor s;
  J2Plasticity::State st;
  for (int n = 0; n < 100; ++n) {
    const auto inc = mat.update(s, st, AxisymTensor{-1e-3, -1e-3, -1e-3, 0.0});
    EXPECT_EQ(inc.d_eps_p, 0.0);
  }
  EXPECT_EQ(st.eps_p, 0.0);
  EXPECT_NEAR(s.rr, -0.1 * 3.0 * mat.bulk_modulus, 1e-6 * kSy);
}

TEST(J2Plasticity, ElasticMaterialNeverYields) {
  const J2Plasticity mat = J2Plasticity::from(kE, kNu);
  AxisymTensor s;
  J2Plasticity::State st;
  const auto inc = mat.update(s, st, AxisymTensor{0.05, -0.05, 0.0, 0.03});
  EXPECT_EQ(inc.d_eps_p, 0.0);
  EXPECT_EQ(inc.plastic_work, 0.0);
  EXPECT_NEAR(s.rz, 2.0 * mat.shear_modulus * 0.03, 1e-6);
}

TEST(J2Plasticity, StrainEnergyFromWorkMatchesTheStress) {
  // Load into the plastic range and unload partly: internal work - plastic work (what the
  // solver reports as strain energy) equals the elastic energy computed from the stress.
  UniaxialDriver d{steel(0.05 * kE), {}, {}};
  for (int n = 0; n < 600; ++n) d.step(1e-5);
  for (int n = 0; n < 200; ++n) d.step(-1e-5);
  const double direct = d.mat.strain_energy_density(d.stress);
  EXPECT_NEAR(d.internal_work - d.plastic_work, direct, 1e-4 * direct);
}

// One material point for both geometries: a 3-D state whose y-y component plays the hoop and
// z-x the r-z shear (x = r, z = z, y = theta) returns exactly as the axisymmetric one, and the
// extra 3-D shears enter J2 as the axisymmetric one does.
TEST(J2Plasticity, ThreeDimensionalReturnIsTheAxisymmetricOne) {
  const J2Plasticity mat = steel(3e9);
  AxisymTensor a;
  SymTensor3 b;
  J2Plasticity::State sa;
  J2Plasticity::State sb;
  const double steps[3][4] = {
      {0.002, -0.001, 0.0005, 0.0015}, {0.001, 0.002, -0.002, -0.001}, {-0.003, 0.001, 0.0, 0.0}};
  for (const auto& d : steps) {
    const auto ia = mat.update(a, sa, AxisymTensor{d[0], d[1], d[2], d[3]});
    const auto ib = mat.update(b, sb, SymTensor3{d[0], d[2], d[1], 0.0, 0.0, d[3]});
    EXPECT_NEAR(ib.d_eps_p, ia.d_eps_p, 1e-15);
    EXPECT_NEAR(ib.plastic_work, ia.plastic_work, 1e-9 * std::abs(ia.plastic_work) + 1e-12);
    EXPECT_NEAR(b.xx, a.rr, 1e-6);
    EXPECT_NEAR(b.yy, a.tt, 1e-6);
    EXPECT_NEAR(b.zz, a.zz, 1e-6);
    EXPECT_NEAR(b.zx, a.rz, 1e-6);
  }
  EXPECT_GT(sb.eps_p, 0.0);
  // A pure xy shear beyond yield lands on the surface with sqrt(3) |s_xy| = sigma_y.
  SymTensor3 s;
  J2Plasticity::State st;
  (void)mat.update(s, st, SymTensor3{0.0, 0.0, 0.0, 0.01, 0.0, 0.0});
  EXPECT_NEAR(std::sqrt(3.0) * std::abs(s.xy), mat.flow_stress(st), 1e-9 * kSy);
  EXPECT_NEAR(von_mises(s), mat.flow_stress(st), 1e-9 * kSy);
}

}  // namespace
}  // namespace corlab::fem
