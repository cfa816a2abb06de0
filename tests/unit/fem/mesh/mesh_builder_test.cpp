// The generator's block and quad assembly (src/fem/mesh/mesh_builder.hpp): the 3:1 transition.
// SPDX-License-Identifier: BSD-3-Clause
#include "fem/mesh/mesh_builder.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "corlab/fem/kernels/axisym_quad4.hpp"
#include "corlab/fem/kernels/stable_time_step.hpp"
#include "corlab/fem/mesh/mesh_quality.hpp"
#include "fem/mesh/coarsening_layer.hpp"

namespace corlab::fem::meshing {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

struct Corners {
  std::array<double, 4> r{};
  std::array<double, 4> z{};
};

Corners corners(const Mesh& m, std::size_t e) {
  Corners c;
  for (std::size_t k = 0; k < 4; ++k) {
    c.r[k] = m.r[static_cast<std::size_t>(m.quads[e][k])];
    c.z[k] = m.z[static_cast<std::size_t>(m.quads[e][k])];
  }
  return c;
}

// Three fine intervals of w = 1 on top (z = 0), one of 3 at the bottom of a layer 2 (then 2.2)
// deep, at r >= 1 (off the axis): four elements, two new interior nodes, the layer's area
// exactly, every element counter-clockwise and no shorter (stable step) than a square of side w;
// at 2 the corners are 45/135 deg, at 2.2 they are within 40-140 deg and every element is
// >= 0.7 w wide (area / longest edge), so well_shaped_transition accepts it.
TEST(MeshBuilder, TransitionThreeToOneIsWellShaped) {
  for (const double depth : {2.0, 2.2}) {
    Mesh m;
    MeshBuilder b(m);
    b.start_body(Body::kSubstrate);
    b.transition({Point{1.0, 0.0}, Point{2.0, 0.0}, Point{3.0, 0.0}, Point{4.0, 0.0}},
                 Point{1.0, -depth}, Point{4.0, -depth});
    ASSERT_EQ(m.quads.size(), 4u);
    EXPECT_EQ(m.num_nodes(), 8);
    double area = 0.0;
    for (std::size_t e = 0; e < m.quads.size(); ++e) {
      const Corners c = corners(m, e);
      const QuadQuality q = quad_quality(c.r, c.z);
      area += q.area;
      EXPECT_GT(q.min_jacobian, 0.0) << e;
      EXPECT_GE(planar_characteristic_length(quad4_geometry(c.r.data(), c.z.data())),
                1.0 / std::sqrt(2.0) - 1e-12)
          << e;
      const double bound = depth == 2.0 ? 45.0 : 40.0;
      EXPECT_GE(q.min_angle, bound * kDegree - 1e-12) << depth << " " << e;
      EXPECT_LE(q.max_angle, (180.0 - bound) * kDegree + 1e-12) << depth << " " << e;
      if (depth > 2.0) {
        EXPECT_GE(q.width, 0.7) << e;
      }
    }
    EXPECT_NEAR(area, 3.0 * depth, 1e-12);
  }
}

// The shape test that decides where a coarsening sweep merges: a layer 2.2 w thick passes; 2 w
// (its trapezoid 0.67 w wide) and 4 w (corners of 27 deg) do not; neither do unequal fine
// intervals (1, 1, 2) whose narrow quads get too thin.
TEST(MeshBuilder, WellShapedTransitionOnlyInItsWindow) {
  const std::array<Point, 4> fine{Point{1.0, 0.0}, Point{2.0, 0.0}, Point{3.0, 0.0},
                                  Point{4.0, 0.0}};
  EXPECT_TRUE(well_shaped_transition(fine, {1.0, -2.2}, {4.0, -2.2}));
  EXPECT_FALSE(well_shaped_transition(fine, {1.0, -2.0}, {4.0, -2.0}));
  EXPECT_FALSE(well_shaped_transition(fine, {1.0, -4.0}, {4.0, -4.0}));
  const std::array<Point, 4> uneven{Point{1.0, 0.0}, Point{2.0, 0.0}, Point{3.0, 0.0},
                                    Point{5.0, 0.0}};
  EXPECT_FALSE(well_shaped_transition(uneven, {1.0, -4.4}, {5.0, -4.4}));
  // h: the same layer scaled to 0.95 (fine intervals narrower than h = 1, as in the sphere's
  // ring) passes on its own terms but not when its elements must be 0.7 h wide
  const std::array<Point, 4> narrow{Point{0.95, 0.0}, Point{1.9, 0.0}, Point{2.85, 0.0},
                                    Point{3.8, 0.0}};
  EXPECT_TRUE(well_shaped_transition(narrow, {0.95, -2.09}, {3.8, -2.09}));
  EXPECT_FALSE(well_shaped_transition(narrow, {0.95, -2.09}, {3.8, -2.09}, 1.0));
  EXPECT_TRUE(well_shaped_transition(fine, {1.0, -2.2}, {4.0, -2.2}, 1.0));
  // either orientation of the layer (fine edge below or on the left) is judged alike
  EXPECT_TRUE(
      well_shaped_transition({Point{0.0, 1.0}, Point{0.0, 2.0}, Point{0.0, 3.0}, Point{0.0, 4.0}},
                             {2.2, 1.0}, {2.2, 4.0}));
}

// Thick layers (sweeps along the sphere's skin, whose layers outgrow the rows they would merge):
// the plain template fails from about 2.4 w on (corners below 40 deg), but with its interior
// nodes placed by thick_layer_depth it stays well shaped at any thickness: the coarse side's
// quads keep a 2.24 w layer's shape, the fine side's quads stretch as the plain elements beside
// them do. Up to 2.24 w it is the plain template.
TEST(MeshBuilder, ThickLayerTransitionIsWellShapedAtAnyThickness) {
  const std::array<Point, 4> fine{Point{1.0, 0.0}, Point{2.0, 0.0}, Point{3.0, 0.0},
                                  Point{4.0, 0.0}};
  for (const double t : {2.0, 2.2}) {
    EXPECT_EQ(thick_layer_depth(fine, {1.0, -t}, {4.0, -t}), kHalfwayDepth) << t;
  }
  for (const double t : {2.5, 3.0, 4.0, 8.0, 20.0}) {
    const Point c0{1.0, -t};
    const Point c1{4.0, -t};
    EXPECT_FALSE(well_shaped_transition(fine, c0, c1)) << t;
    const double depth = thick_layer_depth(fine, c0, c1);
    EXPECT_NEAR((1.0 - depth) * t, 1.12, 1e-12) << t;
    EXPECT_TRUE(well_shaped_transition(fine, c0, c1, 0.0, depth)) << t;
    Mesh m;
    MeshBuilder b(m);
    b.start_body(Body::kSubstrate);
    b.transition(fine, c0, c1, depth);
    ASSERT_EQ(m.quads.size(), 4u);
    double area = 0.0;
    for (std::size_t e = 0; e < m.quads.size(); ++e) {
      const Corners c = corners(m, e);
      area += quad_quality(c.r, c.z).area;
      EXPECT_GE(planar_characteristic_length(quad4_geometry(c.r.data(), c.z.data())),
                1.0 / std::sqrt(2.0) - 1e-12)
          << t << " " << e;
    }
    EXPECT_NEAR(area, 3.0 * t, 1e-9) << t;
  }
}

// The template's fine edge is shared node for node with a block built on it, the interior nodes
// lie halfway across, and a second transition on the coarse side reuses the coarse nodes.
TEST(MeshBuilder, TransitionSharesItsEdgeNodes) {
  Mesh m;
  MeshBuilder b(m);
  b.start_body(Body::kSubstrate);
  b.block({Point{0.0, 0.0}, Point{0.0, 1.0}, Point{1.0, 0.0}, Point{1.0, 1.0}, Point{2.0, 0.0},
           Point{2.0, 1.0}, Point{3.0, 0.0}, Point{3.0, 1.0}},
          3, 1);
  const int before = m.num_nodes();
  b.transition({Point{0.0, 0.0}, Point{1.0, 0.0}, Point{2.0, 0.0}, Point{3.0, 0.0}},
               Point{0.0, -2.0}, Point{3.0, -2.0});
  EXPECT_EQ(m.num_nodes(), before + 4);  // two interior, two coarse
  EXPECT_EQ(m.r[static_cast<std::size_t>(before)], 1.0);
  EXPECT_EQ(m.z[static_cast<std::size_t>(before)], -1.0);
  EXPECT_EQ(b.node({3.0, -2.0}), before + 3);
}

}  // namespace
}  // namespace corlab::fem::meshing
