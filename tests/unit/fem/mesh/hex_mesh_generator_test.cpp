// The 3-D half sphere (hex_mesh_generator.hpp): valid elements that fill the half ball, a
// surface on the sphere, the symmetry plane, and h_contact at the lowest point.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/mesh/hex_mesh_generator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>

#include "corlab/core/error.hpp"
#include "corlab/fem/kernels/hex8.hpp"

namespace corlab::fem {
namespace {

Hex8Geometry geometry(const HexMesh& m, int e) {
  double x[8];
  double y[8];
  double z[8];
  for (int c = 0; c < 8; ++c) {
    const auto n = static_cast<std::size_t>(m.hexes[static_cast<std::size_t>(e)][c]);
    x[c] = m.x[n];
    y[c] = m.y[n];
    z[c] = m.z[n];
  }
  return hex8_geometry(x, y, z);
}

// The paper's 35 mm sphere at h_contact [m], its lowest point gap [m] above z = 0.
HexMeshOptions sphere_options(double h_contact, double gap) {
  return {.sphere_radius = 35e-3,
          .gap = gap,
          .h_contact = h_contact,
          .zone_radius = 3e-3,
          .zone_depth = 2e-3,
          .growth = 1.2,
          .h_max = 5e-3,
          .core_fraction = 0.45};
}

TEST(HexSphere, FillsTheHalfBallWithValidElements) {
  const HexMeshOptions o = sphere_options(0.7e-3, 1e-4);
  const HexMesh m = generate_hex_sphere(o);
  double volume = 0.0;
  for (int e = 0; e < m.num_elements(); ++e) {
    const double v = geometry(m, e).volume;
    ASSERT_GT(v, 0.0) << "element " << e;
    volume += v;
  }
  const double r = o.sphere_radius;
  const double exact = 2.0 / 3.0 * M_PI * r * r * r;
  // Bilinear facets inscribed in the sphere: a little less than the ball, by O((h/R)^2).
  EXPECT_LT(volume, exact);
  EXPECT_GT(volume, exact * (1.0 - 5e-3));
  const double cz = o.gap + r;
  for (const int n : m.sphere_surface_nodes) {
    const auto i = static_cast<std::size_t>(n);
    EXPECT_NEAR(std::hypot(m.x[i], m.y[i], m.z[i] - cz), r, 1e-12 * r);
    EXPECT_LT(m.z[i], cz);
    EXPECT_GE(m.y[i], 0.0);
  }
  for (const int n : m.symmetry_nodes) EXPECT_EQ(m.y[static_cast<std::size_t>(n)], 0.0);
  for (double y : m.y) EXPECT_GE(y, 0.0);
  // The lowest node is at z = gap, and the surface elements around it are h_contact wide.
  const double z_min = *std::min_element(m.z.begin(), m.z.end());
  EXPECT_NEAR(z_min, o.gap, 1e-12);
  double h_near = 0.0;
  for (int e = 0; e < m.num_elements(); ++e) {
    const auto& hex = m.hexes[static_cast<std::size_t>(e)];
    const bool touches = std::any_of(
        hex.begin(), hex.end(), [&](int n) { return m.z[static_cast<std::size_t>(n)] == z_min; });
    if (touches) h_near = std::max(h_near, std::cbrt(geometry(m, e).volume));
  }
  EXPECT_GT(h_near, 0.8 * o.h_contact);
  EXPECT_LT(h_near, 1.2 * o.h_contact);
  EXPECT_EQ(m.node_body.size(), m.x.size());
  EXPECT_EQ(m.element_body.size(), m.hexes.size());
}

// The deformable flat's half block: valid elements filling w x w/2... exactly, the top faces
// facing up and tiling the top, the base fixed at z = -depth, the symmetry plane shared.
TEST(HexBlock, FillsTheHalfBlockBelowTheSphere) {
  HexMeshOptions o;
  o.h_contact = 1e-3;
  o.zone_radius = 4e-3;
  o.zone_depth = 2e-3;
  o.block = true;
  o.block_half_width = 40e-3;
  o.block_depth = 30e-3;
  o.travel = 3e-3;
  const HexMesh m = generate_hex_impact_mesh(o);
  double volume = 0.0;
  for (int e = 0; e < m.num_elements(); ++e) {
    if (m.element_body[static_cast<std::size_t>(e)] != Body::kSubstrate) continue;
    const double v = geometry(m, e).volume;
    ASSERT_GT(v, 0.0);
    volume += v;
  }
  EXPECT_NEAR(volume, 2.0 * 40e-3 * 40e-3 * 30e-3, 1e-12);
  double top = 0.0;
  for (const auto& f : m.top_faces) {
    const auto p = [&](int k) { return static_cast<std::size_t>(f[static_cast<std::size_t>(k)]); };
    for (int k = 0; k < 4; ++k) EXPECT_EQ(m.z[p(k)], 0.0);
    // Counter-clockwise seen from +z: positive signed area.
    const double area = 0.5 * ((m.x[p(2)] - m.x[p(0)]) * (m.y[p(3)] - m.y[p(1)]) -
                               (m.y[p(2)] - m.y[p(0)]) * (m.x[p(3)] - m.x[p(1)]));
    EXPECT_GT(area, 0.0);
    top += area;
  }
  EXPECT_NEAR(top, 2.0 * 40e-3 * 40e-3, 1e-12);
  EXPECT_FALSE(m.base_nodes.empty());
  for (const int n : m.base_nodes) EXPECT_EQ(m.z[static_cast<std::size_t>(n)], -30e-3);
  // h_contact over the fine band, which reaches zone + travel towards +x.
  const auto cell = [&](double x) {
    const auto it = std::upper_bound(m.top_x.begin(), m.top_x.end(), x);
    return *it - *(it - 1);
  };
  EXPECT_NEAR(cell(0.5e-3), 1e-3, 1e-12);
  EXPECT_NEAR(cell(6.5e-3), 1e-3, 1e-12);
  EXPECT_NEAR(cell(-3.5e-3), 1e-3, 1e-12);
  EXPECT_GT(cell(-8e-3), 1.1e-3);
}

TEST(HexSphere, RefusesMeshesItCannotBuild) {
  HexMeshOptions o;
  o.h_contact = 3e-3;  // > R / 20
  EXPECT_THROW(generate_hex_sphere(o), InputError);
  o.h_contact = 1e-3;
  o.growth = 3.0;
  EXPECT_THROW(generate_hex_sphere(o), InputError);
}

// The half ball is its own mirror image across x = 0, node for node and element for element, so
// a normal impact stays symmetric (no spin). With a node at the centre of the core (an even
// number of core layers) the centre once came out NaN and took an equator node's place in four
// elements: the elastic pair then spun by omega R / v = 5e-4 after a normal impact.
TEST(HexSphere, IsItsOwnMirrorImageWithANodeAtTheCentre) {
  int centred = 0;
  for (const double h : {0.7e-3, 1e-3, 1.2e-3, 1.5e-3, 1.7e-3}) {
    SCOPED_TRACE(h);
    const HexMeshOptions o = sphere_options(h, 0.0);
    const HexMesh m = generate_hex_sphere(o);
    std::map<std::array<double, 3>, int> at;
    for (int n = 0; n < m.num_nodes(); ++n) {
      const auto i = static_cast<std::size_t>(n);
      ASSERT_TRUE(std::isfinite(m.x[i]) && std::isfinite(m.y[i]) && std::isfinite(m.z[i]));
      at[{m.x[i], m.y[i], m.z[i]}] = n;
    }
    centred += at.count({0.0, 0.0, o.sphere_radius}) > 0 ? 1 : 0;
    std::set<std::array<int, 8>> elements;
    auto sorted = [](std::array<int, 8> hex) {
      std::sort(hex.begin(), hex.end());
      return hex;
    };
    for (const auto& hex : m.hexes) elements.insert(sorted(hex));
    for (const auto& hex : m.hexes) {
      std::array<int, 8> mirror{};
      for (std::size_t c = 0; c < 8; ++c) {
        const auto i = static_cast<std::size_t>(hex[c]);
        const auto it = at.find({-m.x[i], m.y[i], m.z[i]});
        ASSERT_NE(it, at.end());
        mirror[c] = it->second;
      }
      EXPECT_EQ(elements.count(sorted(mirror)), 1u);
    }
  }
  EXPECT_GT(centred, 0);  // the lattices above include one with a centre node
}

}  // namespace
}  // namespace corlab::fem
