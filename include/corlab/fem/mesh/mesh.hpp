// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file mesh.hpp
/// Axisymmetric two-body mesh: an elastic sphere above an elastic-plastic substrate.
/// Coordinates (r, z) [m]: r >= 0 is the radial distance from the symmetry axis, z points up.
/// The substrate occupies 0 <= r <= substrate_radius, -substrate_depth <= z <= 0; the sphere's
/// centre is on the axis at z = gap + sphere_radius, so its lowest point is at z = gap.

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace corlab::fem {

/// Which body a node or element belongs to.
enum class Body : std::uint8_t { kSphere = 0, kSubstrate = 1 };

struct Mesh {
  std::vector<double> r;                  ///< node radial coordinate [m] (nnode)
  std::vector<double> z;                  ///< node axial coordinate [m] (nnode)
  std::vector<std::array<int, 4>> quads;  ///< element nodes, counter-clockwise in (r, z) (nelem)
  std::vector<Body> element_body;         ///< body of each element (nelem)
  std::vector<Body> node_body;            ///< body of each node (nnode); bodies share no node

  // Named node sets (node indices).
  std::vector<int> axis_nodes;  ///< nodes on r = 0: radial velocity held at zero
  std::vector<int> base_nodes;  ///< substrate bottom z = -depth: fully fixed
  /// Sphere surface nodes that may touch the substrate, ordered by increasing arc length from
  /// the lowest point (the contact slaves).
  std::vector<int> sphere_surface_nodes;
  /// Substrate top-surface nodes ordered by increasing r; consecutive pairs are the contact
  /// master segments.
  std::vector<int> substrate_surface_nodes;

  int num_nodes() const { return static_cast<int>(r.size()); }
  int num_elements() const { return static_cast<int>(quads.size()); }
};

/// Whether corners (r, z) [m] go round counter-clockwise: twice the signed area, from the
/// diagonals, is not negative.
inline bool is_counter_clockwise(const std::array<double, 4>& r, const std::array<double, 4>& z) {
  return (r[2] - r[0]) * (z[3] - z[1]) - (z[2] - z[0]) * (r[3] - r[1]) >= 0.0;
}

/// `quad` (node indices of `mesh`) in the counter-clockwise (r, z) order Mesh::quads holds: nodes
/// 1 and 3 swapped when the signed area is negative.
inline std::array<int, 4> counter_clockwise(const Mesh& mesh, std::array<int, 4> quad) {
  std::array<double, 4> r{};
  std::array<double, 4> z{};
  for (std::size_t k = 0; k < 4; ++k) {
    r[k] = mesh.r[static_cast<std::size_t>(quad[k])];
    z[k] = mesh.z[static_cast<std::size_t>(quad[k])];
  }
  if (!is_counter_clockwise(r, z)) std::swap(quad[1], quad[3]);
  return quad;
}

}  // namespace corlab::fem
