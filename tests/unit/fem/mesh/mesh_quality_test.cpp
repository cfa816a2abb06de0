// Element quality measures (mesh_quality.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/mesh/mesh_quality.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

namespace corlab::fem {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(QuadQuality, Rectangle) {
  // 2 x 1 rectangle at r in [1, 3], z in [0, 1]
  const QuadQuality q = quad_quality({1.0, 3.0, 3.0, 1.0}, {0.0, 0.0, 1.0, 1.0});
  EXPECT_NEAR(q.min_angle, 0.5 * kPi, 1e-14);
  EXPECT_NEAR(q.max_angle, 0.5 * kPi, 1e-14);
  EXPECT_NEAR(q.aspect_ratio, 2.0, 1e-14);
  EXPECT_NEAR(q.min_jacobian, 0.5, 1e-14);  // (2/2) * (1/2)
  EXPECT_NEAR(q.area, 2.0, 1e-14);
  EXPECT_NEAR(q.width, 1.0, 1e-14);
  EXPECT_NEAR(q.characteristic_length, 2.0 / std::sqrt(5.0), 1e-14);
  EXPECT_NEAR(q.volume, kPi * (9.0 - 1.0) * 1.0, 1e-12);  // annulus ring
}

TEST(QuadQuality, ParallelogramAndInvertedQuad) {
  const QuadQuality p = quad_quality({0.0, 1.0, 1.5, 0.5}, {0.0, 0.0, 0.5, 0.5});
  EXPECT_NEAR(p.min_angle, kPi / 4.0, 1e-14);
  EXPECT_NEAR(p.max_angle, 3.0 * kPi / 4.0, 1e-14);
  EXPECT_GT(p.min_jacobian, 0.0);
  // clockwise ordering: negative Jacobian at every corner
  const QuadQuality c = quad_quality({0.0, 0.0, 1.0, 1.0}, {0.0, 1.0, 1.0, 0.0});
  EXPECT_LT(c.min_jacobian, 0.0);
  EXPECT_LT(c.area, 0.0);
  // a dart (reflex corner): one corner Jacobian negative, angle above pi
  const QuadQuality d = quad_quality({0.0, 2.0, 0.5, 0.0}, {0.0, 0.0, 0.5, 2.0});
  EXPECT_LT(d.min_jacobian, 0.0);
  EXPECT_GT(d.max_angle, kPi);
}

TEST(MeshQuality, PerBodyTotals) {
  Mesh m;
  m.r = {0, 1, 1, 0, 0, 2, 2, 0};
  m.z = {0, 0, 1, 1, 2, 2, 3, 3};
  m.quads = {{0, 1, 2, 3}, {4, 5, 6, 7}};
  m.element_body = {Body::kSubstrate, Body::kSphere};
  m.node_body = {Body::kSubstrate, Body::kSubstrate, Body::kSubstrate, Body::kSubstrate,
                 Body::kSphere,    Body::kSphere,    Body::kSphere,    Body::kSphere};
  const MeshQuality s = mesh_quality(m, Body::kSphere);
  EXPECT_EQ(s.elements, 1);
  EXPECT_EQ(s.nodes, 4);
  EXPECT_NEAR(s.area, 2.0, 1e-14);
  EXPECT_NEAR(s.volume, kPi * 4.0, 1e-12);  // cylinder r = 2, height 1
  EXPECT_NEAR(s.max_aspect_ratio, 2.0, 1e-14);
  EXPECT_NEAR(s.min_edge, 1.0, 1e-14);
  EXPECT_NEAR(s.max_edge, 2.0, 1e-14);
  const MeshQuality w = mesh_quality(m, Body::kSubstrate);
  EXPECT_NEAR(w.area, 1.0, 1e-14);
  EXPECT_NEAR(w.volume, kPi, 1e-12);
  EXPECT_EQ(mesh_quality(Mesh{}, Body::kSphere).elements, 0);
}

// Three substrate squares of sides 1, 3 and 25 mm and a sphere square: levels against the 1 mm
// square's length s/sqrt(2) are 0, 1 (2 <= 0.8 x 3 < 4) and 4 (the cap; 16 <= 0.8 x 25).
TEST(ExplicitCost, LevelsFromTheShortestElement) {
  Mesh m;
  const std::array<double, 4> sides{1e-3, 3e-3, 25e-3, 1e-3};
  double r0 = 0.0;
  for (std::size_t k = 0; k < sides.size(); ++k) {
    const double s = sides[k];
    const int n = static_cast<int>(m.r.size());
    m.r.insert(m.r.end(), {r0, r0 + s, r0 + s, r0});
    m.z.insert(m.z.end(), {0.0, 0.0, s, s});
    m.quads.push_back({n, n + 1, n + 2, n + 3});
    const Body body = k < 3 ? Body::kSubstrate : Body::kSphere;
    m.element_body.push_back(body);
    m.node_body.insert(m.node_body.end(), 4, body);
    r0 += s;
  }
  const double shortest = mesh_quality(m, Body::kSubstrate).min_characteristic_length;
  EXPECT_NEAR(shortest, 1e-3 / std::sqrt(2.0), 1e-15);
  const ExplicitCost c = explicit_cost(m, Body::kSubstrate, shortest);
  EXPECT_EQ(c.elements_at_level, (std::array<int, kCostLevels + 1>{1, 1, 0, 0, 1}));
  EXPECT_DOUBLE_EQ(c.updates, 1.0 + 0.5 + 1.0 / 16.0);
  const ExplicitCost sphere = explicit_cost(m, Body::kSphere, shortest);
  EXPECT_EQ(sphere.elements_at_level[0], 1);
  EXPECT_DOUBLE_EQ(sphere.updates, 1.0);
}

}  // namespace
}  // namespace corlab::fem
