// The smooth master surface (spline_surface.hpp): the Catmull-Rom weights' partition of unity,
// interpolation and quadratic precision, the exact projection on a tilted plane grid and on a
// paraboloid's grid, and on a curved grid the closest point's orthogonality, a normal continuous
// across the patches and the gap's gradient (what makes the penalty force conservative) against
// finite differences.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/kernels/spline_surface.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace corlab::fem {
namespace {

// A grid of n x n control points over [0, n - 1]^2 with spacing 1, z = height(x, y), ghosts
// by linear extrapolation (a plane stays a plane beyond the edges).
struct Grid {
  static constexpr long kN = 7;
  std::vector<double> z;
  template <class Height>
  explicit Grid(Height height) {
    for (long b = -1; b <= kN; ++b)
      for (long a = -1; a <= kN; ++a)
        z.push_back(height(static_cast<double>(a), static_cast<double>(b)));
  }
  double& at(long a, long b) { return z[static_cast<std::size_t>((b + 1) * (kN + 2) + a + 1)]; }
  auto control() {
    return [this](long a, long b, double* x) {
      x[0] = static_cast<double>(a);
      x[1] = static_cast<double>(b);
      x[2] = at(a, b);
    };
  }
  static SplineDomain domain() { return {0.0, kN - 1.0, 0.0, kN - 1.0}; }
};

// The surface point of a projection.
std::array<double, 3> closest_point(const SplineProjection& f, Grid& g) {
  std::array<double, 3> x{0.0, 0.0, 0.0};
  auto control = g.control();
  for (long b = 0; b < 4; ++b)
    for (long a = 0; a < 4; ++a) {
      double q[3];
      control(f.k - 1 + a, f.l - 1 + b, q);
      for (int d = 0; d < 3; ++d) x[static_cast<std::size_t>(d)] += f.weight[a + 4 * b] * q[d];
    }
  return x;
}

TEST(SplineSurface, WeightsInterpolateWithQuadraticPrecision) {
  for (const double t : {0.0, 0.2, 0.5, 0.7, 1.0}) {
    const CatmullRomWeights c = catmull_rom(t);
    double sum = 0.0;
    double first = 0.0;
    double second = 0.0;
    double slope = 0.0;
    for (int a = 0; a < 4; ++a) {
      sum += c.w[a];
      first += c.w[a] * (a - 1);
      second += c.w[a] * (a - 1) * (a - 1);
      slope += c.dw[a] * (a - 1);
    }
    EXPECT_NEAR(sum, 1.0, 1e-15);
    EXPECT_NEAR(first, t, 1e-15);  // sum C_a (a - 1) = t
    EXPECT_NEAR(second, t * t, 1e-15);
    EXPECT_NEAR(slope, 1.0, 1e-15);
  }
  // Through the nodes: at t = 0 the node k alone, at t = 1 the node k + 1 alone.
  const CatmullRomWeights start = catmull_rom(0.0);
  const CatmullRomWeights end = catmull_rom(1.0);
  for (int a = 0; a < 4; ++a) {
    EXPECT_EQ(start.w[a], a == 1 ? 1.0 : 0.0);
    EXPECT_EQ(end.w[a], a == 2 ? 1.0 : 0.0);
  }
  // C1 across the node: the next patch's slopes at t = 0, shifted by one node.
  for (int a = 1; a < 4; ++a) EXPECT_NEAR(end.dw[a], start.dw[a - 1], 1e-15);
  EXPECT_EQ(end.dw[0], 0.0);
  EXPECT_EQ(start.dw[3], 0.0);
}

TEST(SplineSurface, ProjectsExactlyOnATiltedPlaneGrid) {
  Grid g([](double x, double y) { return 0.1 * x - 0.05 * y; });
  const double p[3] = {2.3, 3.7, -0.4};
  const SplineProjection f = project_on_spline_surface(p, 1.0, 1.0, Grid::domain(), g.control());
  const double len = std::sqrt(1.0 + 0.01 + 0.0025);
  const double n[3] = {-0.1 / len, 0.05 / len, 1.0 / len};
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(f.normal[d], n[d], 1e-13);
  EXPECT_NEAR(f.gap, (p[2] - 0.1 * p[0] + 0.05 * p[1]) / len, 1e-13);
  const std::array<double, 3> x = closest_point(f, g);
  for (int d = 0; d < 3; ++d)
    EXPECT_NEAR(x[static_cast<std::size_t>(d)] + f.gap * f.normal[d], p[d], 1e-12);
  double sum = 0.0;
  for (const double w : f.weight) sum += w;
  EXPECT_NEAR(sum, 1.0, 1e-15);
}

// A paraboloid is reproduced: the closest point lies on it exactly.
TEST(SplineSurface, ReproducesAParaboloid) {
  auto z = [](double x, double y) { return 0.02 * (x - 2.7) * (x - 2.7) + 0.03 * (y - 3.1) * y; };
  Grid g(z);
  const double p[3] = {3.6, 2.2, -0.3};
  const SplineProjection f = project_on_spline_surface(p, 1.0, 1.0, Grid::domain(), g.control());
  const std::array<double, 3> x = closest_point(f, g);
  EXPECT_NEAR(x[0], f.u, 1e-13);  // the grid's x is its parameter
  EXPECT_NEAR(x[2], z(x[0], x[1]), 1e-13);
  EXPECT_LT(f.gap, 0.0);
}

// A bowl like an indentation (depth 0.3 over a radius of 3 spacings).
double bowl(double x, double y) {
  const double r2 = (x - 3.0) * (x - 3.0) + (y - 3.2) * (y - 3.2);
  return -0.3 * std::exp(-r2 / 4.0);
}

TEST(SplineSurface, ClosestPointOnACurvedGridIsOrthogonal) {
  Grid g(bowl);
  const double p[3] = {2.45, 1.9, -0.25};
  const SplineProjection f = project_on_spline_surface(p, 4.0, 4.0, Grid::domain(), g.control());
  const std::array<double, 3> x = closest_point(f, g);
  const double r[3] = {p[0] - x[0], p[1] - x[1], p[2] - x[2]};
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(r[d], f.gap * f.normal[d], 1e-12);
  EXPECT_LT(f.gap, 0.0);
}

// Across the patches' seam u = 3 the normal does not jump (facets' normals would): the bowl
// centred on the seam puts the closest points of x = 3 -+ 1e-9 on either side of it.
TEST(SplineSurface, NormalIsContinuousAcrossPatches) {
  Grid g(bowl);
  const double below[3] = {3.0 - 1e-9, 2.1, -0.2};
  const double above[3] = {3.0 + 1e-9, 2.1, -0.2};
  const SplineProjection a =
      project_on_spline_surface(below, 2.0, 2.0, Grid::domain(), g.control());
  const SplineProjection b =
      project_on_spline_surface(above, 3.0, 2.0, Grid::domain(), g.control());
  ASSERT_NE(a.k, b.k);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(a.normal[d], b.normal[d], 1e-8);
  EXPECT_NEAR(a.gap, b.gap, 1e-8);
}

// dg/dp = n and dg/dP_ab = -w_ab n: the penalty force along n, shared by the weights, is the
// gradient of 1/2 k g^2, so the contact neither creates nor destroys energy.
TEST(SplineSurface, GapGradientIsTheNormalSharedByTheWeights) {
  Grid g(bowl);
  const double p[3] = {3.4, 2.6, -0.22};
  const SplineProjection f = project_on_spline_surface(p, 3.0, 3.0, Grid::domain(), g.control());
  constexpr double kStep = 1e-6;
  auto gap = [&](const double* q) {
    return project_on_spline_surface(q, 3.0, 3.0, Grid::domain(), g.control()).gap;
  };
  for (int d = 0; d < 3; ++d) {
    double plus[3] = {p[0], p[1], p[2]};
    double minus[3] = {p[0], p[1], p[2]};
    plus[d] += kStep;
    minus[d] -= kStep;
    EXPECT_NEAR((gap(plus) - gap(minus)) / (2.0 * kStep), f.normal[d], 1e-8);
  }
  // The control points' z (their x and y move the surface the same way).
  for (long b = 0; b < 4; ++b)
    for (long a = 0; a < 4; ++a) {
      double& z = g.at(f.k - 1 + a, f.l - 1 + b);
      z += kStep;
      const double up = gap(p);
      z -= 2.0 * kStep;
      const double down = gap(p);
      z += kStep;
      EXPECT_NEAR((up - down) / (2.0 * kStep), -f.weight[a + 4 * b] * f.normal[2], 1e-8);
    }
}

// Limit: a point beyond the domain projects on its edge (the caller sizes the domain).
TEST(SplineSurface, ClampsToTheDomain) {
  Grid g([](double, double) { return 0.0; });
  const double p[3] = {9.0, 3.0, -0.1};
  const SplineProjection f = project_on_spline_surface(p, 5.0, 3.0, Grid::domain(), g.control());
  EXPECT_EQ(f.u, Grid::kN - 1.0);
  EXPECT_NEAR(f.v, 3.0, 1e-12);
  EXPECT_NEAR(f.gap, -0.1, 1e-12);
}

}  // namespace
}  // namespace corlab::fem
