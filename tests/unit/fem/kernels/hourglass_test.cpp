// Flanagan-Belytschko hourglass control (hourglass.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/kernels/hourglass.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace corlab::fem {
namespace {

const double kR[4] = {1.0e-3, 1.9e-3, 2.2e-3, 0.8e-3};
const double kZ[4] = {0.1e-3, -0.2e-3, 1.3e-3, 0.9e-3};

TEST(Hourglass, ShapeVectorIsOrthogonalToLinearFields) {
  const Quad4Geometry g = quad4_geometry(kR, kZ);
  double gamma[4];
  hourglass_shape(g, kR, kZ, gamma);
  double s1 = 0.0, sr = 0.0, sz = 0.0, sh = 0.0;
  const double h[4] = {1, -1, 1, -1};
  for (int i = 0; i < 4; ++i) {
    s1 += gamma[i];
    sr += gamma[i] * kR[i];
    sz += gamma[i] * kZ[i];
    sh += gamma[i] * h[i];
  }
  EXPECT_NEAR(s1, 0.0, 1e-15);
  EXPECT_NEAR(sr, 0.0, 1e-18);
  EXPECT_NEAR(sz, 0.0, 1e-18);
  EXPECT_NEAR(sh, 1.0, 1e-12);
}

TEST(Hourglass, LinearVelocityGivesNoForce) {
  const Quad4Geometry g = quad4_geometry(kR, kZ);
  double gamma[4];
  hourglass_shape(g, kR, kZ, gamma);
  double vr[4], vz[4], fr[4] = {0, 0, 0, 0}, fz[4] = {0, 0, 0, 0};
  for (int i = 0; i < 4; ++i) {
    vr[i] = 2.0 + 3.0 * kR[i] - 5.0 * kZ[i];
    vz[i] = -1.0 + 4.0 * kR[i] + 7.0 * kZ[i];
  }
  double qr = 0.0, qz = 0.0;
  const double work = hourglass_update(gamma, vr, vz, 1e9, 1e-8, qr, qz, fr, fz);
  EXPECT_NEAR(qr, 0.0, 1e-12);
  EXPECT_NEAR(qz, 0.0, 1e-12);
  EXPECT_NEAR(work, 0.0, 1e-20);
}

TEST(Hourglass, StiffnessFormStoresEnergy) {
  // A constant hourglass-mode velocity: Q grows linearly, the work is 1/2 k (q t)^2 exactly.
  const Quad4Geometry g = quad4_geometry(kR, kZ);
  double gamma[4];
  hourglass_shape(g, kR, kZ, gamma);
  const double h[4] = {1, -1, 1, -1};
  double vr[4], vz[4];
  for (int i = 0; i < 4; ++i) {
    vr[i] = 0.1 * h[i];
    vz[i] = 0.0;
  }
  const double k = hourglass_stiffness(0.05, 80e9, 1e-9, quad4_gradient_norm2(g));
  double qr = 0.0, qz = 0.0, work = 0.0;
  const double dt = 1e-8;
  for (int n = 0; n < 100; ++n) {
    double fr[4] = {0, 0, 0, 0}, fz[4] = {0, 0, 0, 0};
    work += hourglass_update(gamma, vr, vz, k, dt, qr, qz, fr, fz);
  }
  double q = 0.0;
  for (int i = 0; i < 4; ++i) q += gamma[i] * vr[i];
  const double disp = q * 100 * dt;
  EXPECT_NEAR(qr, k * disp, 1e-9 * k * disp);
  EXPECT_NEAR(work, 0.5 * k * disp * disp, 1e-9 * 0.5 * k * disp * disp);
  EXPECT_GT(k, 0.0);
}

}  // namespace
}  // namespace corlab::fem
