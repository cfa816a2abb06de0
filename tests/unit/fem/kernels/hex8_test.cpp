// The uniform-strain hexahedron (hex8.hpp) and its hourglass control (hourglass.hpp): the
// closed-form volume and mean gradients against 2x2x2 Gauss quadrature of the trilinear map
// (exact for both), linear velocity fields reproduced exactly, interior nodes of a distorted
// patch in equilibrium under a uniform stress, hourglass vectors blind to linear fields, the
// cube's characteristic length.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/kernels/hex8.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "corlab/fem/kernels/hourglass.hpp"

namespace corlab::fem {
namespace {

constexpr int kSign[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                             {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

struct Hex {
  double x[8];
  double y[8];
  double z[8];
};

// A unit cube at the origin scaled by h, each node moved by up to `jitter` x h at random.
Hex distorted_cube(double h, double jitter, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  Hex e{};
  for (int i = 0; i < 8; ++i) {
    e.x[i] = h * (0.5 * (kSign[i][0] + 1) + u(rng));
    e.y[i] = h * (0.5 * (kSign[i][1] + 1) + u(rng));
    e.z[i] = h * (0.5 * (kSign[i][2] + 1) + u(rng));
  }
  return e;
}

// Volume and int dN_I/dx_j dV by 2x2x2 Gauss quadrature of the isoparametric map (exact: the
// integrands are at most quadratic in each natural coordinate).
struct Reference {
  double volume = 0.0;
  double b[3][8] = {};  // (1/V) int dN_I/dx_j dV
};

Reference gauss_reference(const Hex& e) {
  Reference ref;
  const double g = 1.0 / std::sqrt(3.0);
  for (int q = 0; q < 8; ++q) {
    const double xi[3] = {g * kSign[q][0], g * kSign[q][1], g * kSign[q][2]};
    double dn[8][3];  // dN_I/dxi_k
    for (int i = 0; i < 8; ++i)
      for (int k = 0; k < 3; ++k) {
        double v = 0.125 * kSign[i][k];
        for (int m = 0; m < 3; ++m)
          if (m != k) v *= 1.0 + kSign[i][m] * xi[m];
        dn[i][k] = v;
      }
    double jac[3][3] = {};  // d x_j / d xi_k
    for (int i = 0; i < 8; ++i)
      for (int k = 0; k < 3; ++k) {
        jac[0][k] += e.x[i] * dn[i][k];
        jac[1][k] += e.y[i] * dn[i][k];
        jac[2][k] += e.z[i] * dn[i][k];
      }
    const double det = jac[0][0] * (jac[1][1] * jac[2][2] - jac[1][2] * jac[2][1]) -
                       jac[0][1] * (jac[1][0] * jac[2][2] - jac[1][2] * jac[2][0]) +
                       jac[0][2] * (jac[1][0] * jac[2][1] - jac[1][1] * jac[2][0]);
    // inverse: dxi_k/dx_j = cofactor(j, k) / det
    double inv[3][3];
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        const int j1 = (j + 1) % 3;
        const int j2 = (j + 2) % 3;
        const int k1 = (k + 1) % 3;
        const int k2 = (k + 2) % 3;
        inv[k][j] = (jac[j1][k1] * jac[j2][k2] - jac[j1][k2] * jac[j2][k1]) / det;
      }
    ref.volume += det;
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 3; ++j) {
        double d = 0.0;
        for (int k = 0; k < 3; ++k) d += dn[i][k] * inv[k][j];
        ref.b[j][i] += d * det;
      }
  }
  for (auto& row : ref.b)
    for (double& v : row) v /= ref.volume;
  return ref;
}

TEST(Hex8, CubeVolumeGradientsAndCharacteristicLength) {
  const double h = 2e-3;
  const Hex e = distorted_cube(h, 0.0, 1);
  const Hex8Geometry g = hex8_geometry(e.x, e.y, e.z);
  EXPECT_NEAR(g.volume, h * h * h, 1e-12 * h * h * h);
  for (int i = 0; i < 8; ++i) {
    EXPECT_NEAR(g.bx[i], kSign[i][0] / (4.0 * h), 1e-12 / h);
    EXPECT_NEAR(g.by[i], kSign[i][1] / (4.0 * h), 1e-12 / h);
    EXPECT_NEAR(g.bz[i], kSign[i][2] / (4.0 * h), 1e-12 / h);
  }
  EXPECT_NEAR(hex8_characteristic_length(g), h / std::sqrt(3.0), 1e-12 * h);
}

TEST(Hex8, ClosedFormMatchesGaussQuadratureOnDistortedElements) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const Hex e = distorted_cube(1e-3, 0.2, seed);
    const Hex8Geometry g = hex8_geometry(e.x, e.y, e.z);
    const Reference ref = gauss_reference(e);
    ASSERT_NEAR(g.volume, ref.volume, 1e-12 * ref.volume) << seed;
    for (int i = 0; i < 8; ++i) {
      EXPECT_NEAR(g.bx[i], ref.b[0][i], 1e-9 / 1e-3) << seed << " node " << i;
      EXPECT_NEAR(g.by[i], ref.b[1][i], 1e-9 / 1e-3) << seed << " node " << i;
      EXPECT_NEAR(g.bz[i], ref.b[2][i], 1e-9 / 1e-3) << seed << " node " << i;
    }
  }
}

// The shared-difference form of the eight volume derivatives is the rotated node-0 formula.
TEST(Hex8, SharedDifferenceDerivativesEqualTheRotatedFormula) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const Hex e = distorted_cube(1e-3, 0.3, seed);
    double d[8];
    hex8_volume_derivatives12(e.y, e.z, d);
    for (int i = 0; i < 8; ++i) {
      const double reference = hex8_volume_derivative12(e.y, e.z, kHex8Rotation[i]);
      EXPECT_NEAR(d[i], reference, 1e-15 * 1e-6) << seed << " node " << i;  // [m^2]
    }
  }
}

TEST(Hex8, LinearVelocityFieldsAreReproducedExactly) {
  const double a[3][3] = {{0.3, -1.2, 0.7}, {2.0, -0.4, 0.1}, {-0.6, 0.9, 0.5}};  // [1/s]
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const Hex e = distorted_cube(1e-3, 0.25, seed);
    const Hex8Geometry g = hex8_geometry(e.x, e.y, e.z);
    double v[3][8];
    for (int i = 0; i < 8; ++i) {
      const double p[3] = {e.x[i], e.y[i], e.z[i]};
      for (int r = 0; r < 3; ++r) v[r][i] = 4.0 + a[r][0] * p[0] + a[r][1] * p[1] + a[r][2] * p[2];
    }
    const StrainRate3 rate = hex8_strain_rate(g, v[0], v[1], v[2]);
    const double tol = 1e-9;
    EXPECT_NEAR(rate.d.xx, a[0][0], tol);
    EXPECT_NEAR(rate.d.yy, a[1][1], tol);
    EXPECT_NEAR(rate.d.zz, a[2][2], tol);
    EXPECT_NEAR(rate.d.xy, 0.5 * (a[0][1] + a[1][0]), tol);
    EXPECT_NEAR(rate.d.yz, 0.5 * (a[1][2] + a[2][1]), tol);
    EXPECT_NEAR(rate.d.zx, 0.5 * (a[2][0] + a[0][2]), tol);
    EXPECT_NEAR(rate.spin.x, 0.5 * (a[2][1] - a[1][2]), tol);
    EXPECT_NEAR(rate.spin.y, 0.5 * (a[0][2] - a[2][0]), tol);
    EXPECT_NEAR(rate.spin.z, 0.5 * (a[1][0] - a[0][1]), tol);
    // The hourglass rates of a linear field vanish.
    double gamma[4][8];
    hex8_hourglass_shape(g, e.x, e.y, e.z, gamma);
    for (int m = 0; m < 4; ++m)
      for (int r = 0; r < 3; ++r) {
        double q = 0.0;
        for (int i = 0; i < 8; ++i) q += gamma[m][i] * v[r][i];
        EXPECT_NEAR(q, 0.0, 1e-12) << "mode " << m;
      }
  }
}

// A 2x2x2 block of hexahedra around one interior node, every node but the block's corners
// jittered: a uniform stress leaves the interior node in equilibrium (sum over the elements of
// V b_I = d(total volume)/dx_I = 0), whatever the distortion.
TEST(Hex8, UniformStressLeavesAnInteriorNodeInEquilibrium) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.15, 0.15);
  double grid[3][3][3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        grid[i][j][k][0] = i + u(rng);
        grid[i][j][k][1] = j + u(rng);
        grid[i][j][k][2] = k + u(rng);
      }
  const SymTensor3 s{1e8, -2e8, 5e7, 3e7, -4e7, 6e7};
  double f[3] = {0.0, 0.0, 0.0};
  for (int ei = 0; ei < 2; ++ei)
    for (int ej = 0; ej < 2; ++ej)
      for (int ek = 0; ek < 2; ++ek) {
        Hex e{};
        int centre = -1;
        for (int n = 0; n < 8; ++n) {
          const int i = ei + (kSign[n][0] + 1) / 2;
          const int j = ej + (kSign[n][1] + 1) / 2;
          const int k = ek + (kSign[n][2] + 1) / 2;
          e.x[n] = grid[i][j][k][0];
          e.y[n] = grid[i][j][k][1];
          e.z[n] = grid[i][j][k][2];
          if (i == 1 && j == 1 && k == 1) centre = n;
        }
        const Hex8Geometry g = hex8_geometry(e.x, e.y, e.z);
        ASSERT_GT(g.volume, 0.0);
        double fx[8] = {};
        double fy[8] = {};
        double fz[8] = {};
        hex8_add_internal_force(g, s, fx, fy, fz);
        f[0] += fx[centre];
        f[1] += fy[centre];
        f[2] += fz[centre];
      }
  for (const double c : f) EXPECT_NEAR(c, 0.0, 1e-7 * 2e8);
}

// The hourglass force stores and returns energy: driving an element through an hourglass mode
// and back gives zero net work, and the mode's generalised force is k q.
TEST(Hex8, HourglassModeIsResistedElasticallyAndOnlyByItsOwnForce) {
  const Hex e = distorted_cube(1e-3, 0.0, 1);
  const Hex8Geometry g = hex8_geometry(e.x, e.y, e.z);
  double gamma[4][8];
  hex8_hourglass_shape(g, e.x, e.y, e.z, gamma);
  // On a cube gamma_a = h_a / 8: orthogonal modes of unit generalised rate per unit h.v.
  for (int m = 0; m < 4; ++m)
    for (int i = 0; i < 8; ++i) EXPECT_NEAR(gamma[m][i], kHex8HourglassBase[m][i] / 8.0, 1e-12);
  Hex8HourglassForce q;
  const double k = hourglass_stiffness(0.05, 80e9, g.volume, hex8_gradient_norm2(g));
  const double dt = 1e-8;
  double work = 0.0;
  double v[8];
  const double zero[8] = {};
  for (int step = 0; step < 200; ++step) {
    const double sign = step < 100 ? 1.0 : -1.0;
    for (int i = 0; i < 8; ++i) v[i] = sign * kHex8HourglassBase[1][i];  // y-velocity, mode 1
    double fx[8] = {};
    double fy[8] = {};
    double fz[8] = {};
    work += hex8_hourglass_update(gamma, zero, v, zero, k, dt, q, fx, fy, fz);
    if (step == 99) {
      // After 100 steps of unit generalised rate: Q = k * 100 dt in mode 1 only.
      EXPECT_NEAR(q.q[1][1], k * 100 * dt, 1e-9 * k * 100 * dt);
      EXPECT_EQ(q.q[0][1], 0.0);
      EXPECT_EQ(q.q[1][0], 0.0);
      EXPECT_EQ(fx[0], 0.0);
    }
  }
  EXPECT_NEAR(q.q[1][1], 0.0, 1e-9 * k * 100 * dt);
  EXPECT_NEAR(work, 0.0, 1e-9 * k * std::pow(100 * dt, 2));
}

}  // namespace
}  // namespace corlab::fem
