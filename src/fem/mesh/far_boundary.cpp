// The substrate's far faces in either mesh (far_boundary.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/mesh/far_boundary.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace corlab::fem {
namespace {

/// One outer plane: coordinate `axis` equal to `value` [m] within `tolerance` [m].
struct Plane {
  int axis = 0;
  double value = 0.0;
  double tolerance = 0.0;
};

/// The substrate's bounding box over `coords` (one array per axis) [m]; empty lo/hi: no node.
struct Box {
  std::vector<double> lo, hi;
  double extent = 0.0;  ///< the largest side [m]
};

Box substrate_box(const std::vector<const std::vector<double>*>& coords,
                  const std::vector<Body>& node_body) {
  const std::size_t dims = coords.size();
  Box b{std::vector<double>(dims, std::numeric_limits<double>::infinity()),
        std::vector<double>(dims, -std::numeric_limits<double>::infinity())};
  bool any = false;
  for (std::size_t n = 0; n < node_body.size(); ++n) {
    if (node_body[n] != Body::kSubstrate) continue;
    any = true;
    for (std::size_t a = 0; a < dims; ++a) {
      b.lo[a] = std::min(b.lo[a], (*coords[a])[n]);
      b.hi[a] = std::max(b.hi[a], (*coords[a])[n]);
    }
  }
  if (!any) return {};
  for (std::size_t a = 0; a < dims; ++a) b.extent = std::max(b.extent, b.hi[a] - b.lo[a]);
  return b;
}

/// The plane all `nodes` lie on, or -1.
template <std::size_t N>
int plane_of(const std::array<int, N>& nodes,
             const std::vector<Plane>& planes,
             const std::vector<const std::vector<double>*>& coords) {
  for (std::size_t p = 0; p < planes.size(); ++p) {
    const Plane& pl = planes[p];
    const std::vector<double>& x = *coords[static_cast<std::size_t>(pl.axis)];
    if (std::all_of(nodes.begin(), nodes.end(), [&](int n) {
          return std::abs(x[static_cast<std::size_t>(n)] - pl.value) <= pl.tolerance;
        }))
      return static_cast<int>(p);
  }
  return -1;
}

/// Relative tolerance of "on the plane" [-]: far below any element, far above round-off.
constexpr double kOnPlane = 1e-9;

}  // namespace

std::vector<FarFace<2>> far_boundary(const Mesh& mesh) {
  const std::vector<const std::vector<double>*> coords{&mesh.r, &mesh.z};
  const Box box = substrate_box(coords, mesh.node_body);
  std::vector<FarFace<2>> faces;
  if (box.lo.empty()) return faces;
  const double tol = kOnPlane * box.extent;
  const std::vector<Plane> planes{{0, box.hi[0], tol}, {1, box.lo[1], tol}};
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const auto ue = static_cast<std::size_t>(e);
    if (mesh.element_body[ue] != Body::kSubstrate) continue;
    const auto& q = mesh.quads[ue];
    for (std::size_t k = 0; k < 4; ++k) {
      const std::array<int, 2> edge{q[k], q[(k + 1) % 4]};
      const int p = plane_of(edge, planes, coords);
      if (p >= 0) faces.push_back({edge, planes[static_cast<std::size_t>(p)].axis, e});
    }
  }
  return faces;
}

std::vector<FarFace<4>> far_boundary(const HexMesh& mesh) {
  const std::vector<const std::vector<double>*> coords{&mesh.x, &mesh.y, &mesh.z};
  const Box box = substrate_box(coords, mesh.node_body);
  std::vector<FarFace<4>> faces;
  if (box.lo.empty()) return faces;
  const double tol = kOnPlane * box.extent;
  const std::vector<Plane> planes{
      {0, box.lo[0], tol}, {0, box.hi[0], tol}, {1, box.hi[1], tol}, {2, box.lo[2], tol}};
  // The six faces of a hexahedron (hex8.hpp's node order: 0-3 the bottom, 4-7 above them).
  constexpr std::array<std::array<int, 4>, 6> kFaces{
      {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const auto ue = static_cast<std::size_t>(e);
    if (mesh.element_body[ue] != Body::kSubstrate) continue;
    const auto& h = mesh.hexes[ue];
    for (const auto& f : kFaces) {
      const std::array<int, 4> quad{
          h[static_cast<std::size_t>(f[0])], h[static_cast<std::size_t>(f[1])],
          h[static_cast<std::size_t>(f[2])], h[static_cast<std::size_t>(f[3])]};
      const int p = plane_of(quad, planes, coords);
      if (p >= 0) faces.push_back({quad, planes[static_cast<std::size_t>(p)].axis, e});
    }
  }
  return faces;
}

}  // namespace corlab::fem
