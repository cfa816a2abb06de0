// Patch tests of the one-point axisymmetric quad (axisym_quad4.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/kernels/axisym_quad4.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "corlab/core/units.hpp"

namespace corlab::fem {
namespace {

constexpr double kTol = 1e-12;

// A distorted element away from the axis and one touching it (counter-clockwise).
struct Element {
  double r[4];
  double z[4];
};
const Element kDistorted{{1.0e-3, 1.9e-3, 2.2e-3, 0.8e-3}, {0.1e-3, -0.2e-3, 1.3e-3, 0.9e-3}};
const Element kOnAxis{{0.0, 0.7e-3, 0.9e-3, 0.0}, {0.0, 0.1e-3, 0.8e-3, 0.6e-3}};

class Quad4Patch : public ::testing::TestWithParam<Element> {};

TEST_P(Quad4Patch, GeometryIsExact) {
  const Element el = GetParam();
  const Quad4Geometry g = quad4_geometry(el.r, el.z);
  // Omega = int r dA by 2 x 2 Gauss (exact for the bilinear map).
  const double gp = 1.0 / std::sqrt(3.0);
  double omega = 0.0, area = 0.0;
  for (double xi : {-gp, gp}) {
    for (double eta : {-gp, gp}) {
      const double n[4] = {0.25 * (1 - xi) * (1 - eta), 0.25 * (1 + xi) * (1 - eta),
                           0.25 * (1 + xi) * (1 + eta), 0.25 * (1 - xi) * (1 + eta)};
      const double dxi[4] = {-0.25 * (1 - eta), 0.25 * (1 - eta), 0.25 * (1 + eta),
                             -0.25 * (1 + eta)};
      const double deta[4] = {-0.25 * (1 - xi), -0.25 * (1 + xi), 0.25 * (1 + xi), 0.25 * (1 - xi)};
      double r = 0, rx = 0, re = 0, zx = 0, ze = 0;
      for (int i = 0; i < 4; ++i) {
        r += n[i] * el.r[i];
        rx += dxi[i] * el.r[i];
        re += deta[i] * el.r[i];
        zx += dxi[i] * el.z[i];
        ze += deta[i] * el.z[i];
      }
      const double det = rx * ze - re * zx;
      area += det;
      omega += r * det;
    }
  }
  EXPECT_NEAR(g.area, area, kTol * area);
  EXPECT_NEAR(g.omega, omega, kTol * omega);
  double sum_h = 0.0, sum_br = 0.0, sum_bz = 0.0;
  for (int i = 0; i < 4; ++i) {
    sum_h += g.hoop[i];
    sum_br += g.br[i];
    sum_bz += g.bz[i];
  }
  EXPECT_NEAR(sum_h, g.area, kTol * g.area);
  EXPECT_NEAR(sum_br, 0.0, kTol * g.area);
  EXPECT_NEAR(sum_bz, 0.0, kTol * g.area);
}

TEST_P(Quad4Patch, UniformStrainRatesAreExact) {
  const Element el = GetParam();
  const Quad4Geometry g = quad4_geometry(el.r, el.z);
  const double a = 3.0, b = -2.0, c = 5.0;
  double vr[4], vz[4];
  // Radial expansion v_r = a r: d_rr = d_tt = a.
  for (int i = 0; i < 4; ++i) {
    vr[i] = a * el.r[i];
    vz[i] = 0.0;
  }
  StrainRate s = quad4_strain_rate(g, vr, vz);
  EXPECT_NEAR(s.d.rr, a, kTol);
  EXPECT_NEAR(s.d.tt, a, kTol);
  EXPECT_NEAR(s.d.zz, 0.0, kTol);
  EXPECT_NEAR(s.d.rz, 0.0, kTol);
  // Axial stretch v_z = b z.
  for (int i = 0; i < 4; ++i) {
    vr[i] = 0.0;
    vz[i] = b * el.z[i];
  }
  s = quad4_strain_rate(g, vr, vz);
  EXPECT_NEAR(s.d.zz, b, kTol);
  EXPECT_NEAR(s.d.rr, 0.0, kTol);
  EXPECT_NEAR(s.d.tt, 0.0, kTol);
  EXPECT_NEAR(s.d.rz, 0.0, kTol);
  // Shear v_z = c r: d_rz = c/2, spin = -c/2.
  for (int i = 0; i < 4; ++i) {
    vr[i] = 0.0;
    vz[i] = c * el.r[i];
  }
  s = quad4_strain_rate(g, vr, vz);
  EXPECT_NEAR(s.d.rz, 0.5 * c, kTol);
  EXPECT_NEAR(s.spin, -0.5 * c, kTol);
  EXPECT_NEAR(s.d.rr, 0.0, kTol);
  EXPECT_NEAR(s.d.zz, 0.0, kTol);
  EXPECT_NEAR(s.d.tt, 0.0, kTol);
}

TEST_P(Quad4Patch, RigidMotionsGiveNoStretch) {
  const Element el = GetParam();
  const Quad4Geometry g = quad4_geometry(el.r, el.z);
  double vr[4], vz[4];
  for (int i = 0; i < 4; ++i) {
    vr[i] = 0.0;
    vz[i] = 7.0;  // translation along the axis
  }
  StrainRate s = quad4_strain_rate(g, vr, vz);
  const double scale = 7.0 / 1e-3;  // v / h: round-off is relative to this
  EXPECT_NEAR(s.d.rr, 0.0, 1e-14 * scale);
  EXPECT_NEAR(s.d.zz, 0.0, 1e-14 * scale);
  EXPECT_NEAR(s.d.tt, 0.0, 1e-14 * scale);
  EXPECT_NEAR(s.d.rz, 0.0, 1e-14 * scale);
  EXPECT_NEAR(s.spin, 0.0, 1e-14 * scale);
  // In-plane rigid rotation v = W x, W_rz = w: in-plane d = 0, spin = w.
  const double w = 40.0;
  for (int i = 0; i < 4; ++i) {
    vr[i] = w * el.z[i];
    vz[i] = -w * el.r[i];
  }
  s = quad4_strain_rate(g, vr, vz);
  EXPECT_NEAR(s.d.rr, 0.0, kTol);
  EXPECT_NEAR(s.d.zz, 0.0, kTol);
  EXPECT_NEAR(s.d.rz, 0.0, kTol);
  EXPECT_NEAR(s.spin, w, kTol);
}

TEST_P(Quad4Patch, ForcesAreTheTransposeOfTheRates) {
  // Internal power: sum f . v = V sigma : d for any stress and velocity.
  const Element el = GetParam();
  const Quad4Geometry g = quad4_geometry(el.r, el.z);
  const double vr[4] = {0.3, -1.2, 0.7, 2.1};
  const double vz[4] = {-0.4, 0.9, 1.6, -0.2};
  const AxisymTensor sigma{2.0e8, -1.3e8, 0.6e8, 0.45e8};
  double fr[4], fz[4];
  quad4_internal_forces(g, sigma, fr, fz);
  double power = 0.0;
  for (int i = 0; i < 4; ++i) power += fr[i] * vr[i] + fz[i] * vz[i];
  const StrainRate s = quad4_strain_rate(g, vr, vz);
  const double expected = 2.0 * units::kPi * g.omega * contract(sigma, s.d);
  EXPECT_NEAR(power, expected, 1e-12 * std::abs(expected));
}

INSTANTIATE_TEST_SUITE_P(Elements, Quad4Patch, ::testing::Values(kDistorted, kOnAxis));

TEST(Quad4Patch, HydrostaticStressIsInEquilibriumOnADistortedPatch) {
  // 3 x 3 nodes, 2 x 2 elements, interior node moved; sigma_rr = sigma_zz = sigma_tt = -p.
  for (const double r0 : {0.0, 2.0e-3}) {
    double r[9], z[9];
    for (int j = 0; j < 3; ++j) {
      for (int i = 0; i < 3; ++i) {
        r[3 * j + i] = r0 + 0.5e-3 * i;
        z[3 * j + i] = 0.5e-3 * j;
      }
    }
    r[4] += 0.13e-3;  // interior node
    z[4] -= 0.07e-3;
    r[5] += 0.05e-3;
    z[5] += 0.04e-3;
    z[7] += 0.06e-3;
    r[7] -= 0.08e-3;
    const int quads[4][4] = {{0, 1, 4, 3}, {1, 2, 5, 4}, {3, 4, 7, 6}, {4, 5, 8, 7}};
    const double p = 1.0e9;
    const AxisymTensor sigma{-p, -p, -p, 0.0};
    double f_r = 0.0, f_z = 0.0, scale = 0.0;
    for (const auto& q : quads) {
      double er[4], ez[4];
      for (int i = 0; i < 4; ++i) {
        er[i] = r[q[i]];
        ez[i] = z[q[i]];
      }
      const Quad4Geometry g = quad4_geometry(er, ez);
      double fr[4], fz[4];
      quad4_internal_forces(g, sigma, fr, fz);
      for (int i = 0; i < 4; ++i) {
        scale = std::max(scale, std::abs(fr[i]) + std::abs(fz[i]));
        if (q[i] == 4) {
          f_r += fr[i];
          f_z += fz[i];
        }
      }
    }
    EXPECT_NEAR(f_r, 0.0, 1e-13 * scale) << "r0 = " << r0;
    EXPECT_NEAR(f_z, 0.0, 1e-13 * scale) << "r0 = " << r0;
  }
}

}  // namespace
}  // namespace corlab::fem
