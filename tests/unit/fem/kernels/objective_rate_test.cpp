// Hughes-Winget incremental rotation (objective_rate.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/kernels/objective_rate.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace corlab::fem {
namespace {

TEST(HughesWinget, PreservesInvariantsAndHoop) {
  AxisymTensor s{3.0, -1.0, 2.0, 0.7};
  const double tr = trace(s);
  const double vm = von_mises(s);
  rotate_hughes_winget(s, 0.37);
  EXPECT_NEAR(trace(s), tr, 1e-14);
  EXPECT_NEAR(von_mises(s), vm, 1e-14);
  EXPECT_EQ(s.tt, 2.0);
}

TEST(HughesWinget, QuarterTurnSwapsTheAxes) {
  // Spin w over time T with w T = pi/2 in many small steps: sigma_rr -> sigma_zz.
  AxisymTensor s{1.0, 0.0, 0.0, 0.0};
  const int n = 2000;
  const double angle = 0.5 * 3.14159265358979323846;
  // Each step rotates by 2 atan(a/2) for spin increment a; choose a to hit the angle exactly.
  const double a = 2.0 * std::tan(0.5 * angle / n);
  for (int i = 0; i < n; ++i) rotate_hughes_winget(s, a);
  EXPECT_NEAR(s.rr, 0.0, 1e-12);
  EXPECT_NEAR(s.zz, 1.0, 1e-12);
  EXPECT_NEAR(s.rz, 0.0, 1e-12);
}

TEST(HughesWinget, RotatesWithTheMaterial) {
  // v = W x with W_rz = w rotates material lines by R = exp(W t) = [[c, s], [-s, c]]: a stress
  // sigma = e_r e_r becomes R e_r (R e_r)^T = [[c^2, -cs], [-cs, s^2]].
  AxisymTensor s{1.0, 0.0, 0.0, 0.0};
  const double a = 1e-3;
  rotate_hughes_winget(s, a);
  const double th = 2.0 * std::atan(0.5 * a);
  EXPECT_NEAR(s.rr, std::cos(th) * std::cos(th), 1e-15);
  EXPECT_NEAR(s.zz, std::sin(th) * std::sin(th), 1e-15);
  EXPECT_NEAR(s.rz, -std::cos(th) * std::sin(th), 1e-15);
}

// The 3-D rotation about the axis normal to the r-z plane is the axisymmetric one: (r, z, theta)
// = (x, y, z) and W_rz = W_xy = -w.z.
TEST(HughesWinget3, RotationAboutOneAxisIsThePlanarRotation) {
  AxisymTensor a{3.0, -1.0, 2.0, 0.7};
  SymTensor3 b{3.0, -1.0, 2.0, 0.7, 0.0, 0.0};
  rotate_hughes_winget(a, 0.37);
  rotate_hughes_winget(b, Spin3{0.0, 0.0, -0.37});
  EXPECT_NEAR(b.xx, a.rr, 1e-14);
  EXPECT_NEAR(b.yy, a.zz, 1e-14);
  EXPECT_NEAR(b.xy, a.rz, 1e-14);
  EXPECT_EQ(b.zz, 2.0);
  EXPECT_NEAR(b.yz, 0.0, 1e-15);
  EXPECT_NEAR(b.zx, 0.0, 1e-15);
}

// Any spin is an exact rotation: trace, von Mises and s:s are kept; a rigid rotation about an
// oblique axis by many small steps matches Rodrigues' rotation of the stress.
TEST(HughesWinget3, AnySpinIsAnExactRotation) {
  SymTensor3 s{3.0, -1.0, 2.0, 0.7, -0.4, 1.1};
  const double tr = trace(s);
  const double ss = contract(s, s);
  rotate_hughes_winget(s, Spin3{0.3, -0.2, 0.5});
  EXPECT_NEAR(trace(s), tr, 1e-13);
  EXPECT_NEAR(contract(s, s), ss, 1e-12);
  // e_x e_x turned about the unit axis k by angle phi: R e_x (R e_x)^T.
  const double k[3] = {1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0)};
  const double phi = 1.2;
  const int n = 400;
  const double a = 2.0 * std::tan(0.5 * phi / n);  // each step turns by 2 atan(a/2)
  SymTensor3 t{1.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  for (int i = 0; i < n; ++i) rotate_hughes_winget(t, Spin3{a * k[0], a * k[1], a * k[2]});
  // Rodrigues: R e_x = e_x cos phi + (k x e_x) sin phi + k (k . e_x)(1 - cos phi).
  const double c = std::cos(phi);
  const double sn = std::sin(phi);
  const double r[3] = {c + k[0] * k[0] * (1 - c), k[2] * sn + k[1] * k[0] * (1 - c),
                       -k[1] * sn + k[2] * k[0] * (1 - c)};
  EXPECT_NEAR(t.xx, r[0] * r[0], 1e-12);
  EXPECT_NEAR(t.yy, r[1] * r[1], 1e-12);
  EXPECT_NEAR(t.zz, r[2] * r[2], 1e-12);
  EXPECT_NEAR(t.xy, r[0] * r[1], 1e-12);
  EXPECT_NEAR(t.yz, r[1] * r[2], 1e-12);
  EXPECT_NEAR(t.zx, r[2] * r[0], 1e-12);
}

}  // namespace
}  // namespace corlab::fem
