// The substrate's far faces (far_boundary.hpp) in the axisymmetric and the 3-D generated meshes:
// the side and base, never the contact surface, the axis or the symmetry plane.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/mesh/far_boundary.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>

#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/mesh/hex_mesh_generator.hpp"
#include "corlab/fem/mesh/mesh_generator.hpp"

namespace corlab::fem {
namespace {

ImpactConfig small_flat() {
  ImpactConfig c;
  c.sphere.radius = 2.5e-3;
  c.substrate.radius = 4e-3;
  c.substrate.depth = 3e-3;
  c.mesh.h_min = 0.1e-3;
  c.mesh.h_max = 0.5e-3;
  return c;
}

TEST(FarBoundary, AxisymmetricSideAndBaseOfTheSubstrate) {
  const ImpactConfig c = small_flat();
  const Mesh m = build_impact_mesh(c);
  double side = 0.0;  // length of the side's segments [m]
  double base = 0.0;
  for (const FarFace<2>& f : far_boundary(m)) {
    const auto a = static_cast<std::size_t>(f.nodes[0]);
    const auto b = static_cast<std::size_t>(f.nodes[1]);
    EXPECT_EQ(m.element_body[static_cast<std::size_t>(f.element)], Body::kSubstrate);
    const double length = std::hypot(m.r[b] - m.r[a], m.z[b] - m.z[a]);
    if (f.normal_axis == 0) {
      EXPECT_EQ(m.r[a], c.substrate.radius);
      EXPECT_EQ(m.r[b], c.substrate.radius);
      side += length;
    } else {
      ASSERT_EQ(f.normal_axis, 1);
      EXPECT_EQ(m.z[a], -c.substrate.depth);
      EXPECT_EQ(m.z[b], -c.substrate.depth);
      base += length;
    }
  }
  // Each far face once: the side's and the base's lengths are the block's.
  EXPECT_NEAR(side, c.substrate.depth, 1e-12);
  EXPECT_NEAR(base, c.substrate.radius, 1e-12);
}

TEST(FarBoundary, NoneWithoutASubstrateBody) {
  ImpactConfig c = small_flat();
  c.substrate.shape = SubstrateShape::kRigid;
  EXPECT_TRUE(far_boundary(build_impact_mesh(c)).empty());
  c.solver.model = SolverModel::kThreeD;
  c.mesh.contact_elements = 0.0;
  EXPECT_TRUE(far_boundary(build_hex_impact_mesh(c)).empty());
}

TEST(FarBoundary, HexBlockSidesFarYAndBase) {
  ImpactConfig c = small_flat();
  c.solver.model = SolverModel::kThreeD;
  c.mesh.contact_elements = 0.0;
  const HexMesh m = build_hex_impact_mesh(c);
  const double w = c.substrate.radius;
  const double d = c.substrate.depth;
  std::array<double, 3> area{};  // by normal axis [m^2]
  for (const FarFace<4>& f : far_boundary(m)) {
    EXPECT_EQ(m.element_body[static_cast<std::size_t>(f.element)], Body::kSubstrate);
    const auto n0 = static_cast<std::size_t>(f.nodes[0]);
    const auto n2 = static_cast<std::size_t>(f.nodes[2]);
    const double dx = std::abs(m.x[n2] - m.x[n0]);
    const double dy = std::abs(m.y[n2] - m.y[n0]);
    const double dz = std::abs(m.z[n2] - m.z[n0]);
    const auto axis = static_cast<std::size_t>(f.normal_axis);
    area[axis] += axis == 0 ? dy * dz : (axis == 1 ? dx * dz : dx * dy);
    for (const int n : f.nodes) {
      const auto i = static_cast<std::size_t>(n);
      // Never the symmetry plane y = 0 or the top.
      const double want = axis == 0 ? w : (axis == 1 ? w : -d);
      const double got = axis == 0 ? std::abs(m.x[i]) : (axis == 1 ? m.y[i] : m.z[i]);
      EXPECT_EQ(got, want);
    }
  }
  EXPECT_NEAR(area[0], 2.0 * w * d, 1e-12);  // x = -w and x = w, y in [0, w]
  EXPECT_NEAR(area[1], 2.0 * w * d, 1e-12);  // y = w, x in [-w, w]
  EXPECT_NEAR(area[2], 2.0 * w * w, 1e-12);  // the base
}

}  // namespace
}  // namespace corlab::fem
