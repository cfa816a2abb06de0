// Hughes-Winget incremental rotation (objective_rate.hpp).
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

}  // namespace
}  // namespace corlab::fem
