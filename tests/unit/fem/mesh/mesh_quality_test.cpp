// Element quality measures (mesh_quality.hpp).
#include "corlab/fem/mesh/mesh_quality.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace corlab::fem
