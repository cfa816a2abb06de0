// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file hex_master_surface.hpp
/// What the 3-D model's slaves meet on the deformable flat: the smooth surface through the
/// block's top nodes (spline_surface.hpp's Catmull-Rom spline over the structured top grid), and
/// one slave's contact with it. Private to src/fem/solver.

#include <array>
#include <cstddef>
#include <vector>

#include "corlab/fem/mesh/hex_mesh.hpp"

namespace corlab::fem::hex_solver {

/// The block's top as a grid of control points: node (a, b) of the top grid (a along x, b along
/// y from the symmetry plane) at a + nu b. Beyond the grid's edges the patches take ghost points:
/// across the symmetry plane y = 0 the mirror images of rows 1 and 2 (the full model's surface,
/// smooth across the plane), across the far edges the edge's node again.
struct MasterSurface {
  std::size_t nu = 0;     ///< nodes along x [-]
  std::size_t nv = 0;     ///< nodes along y [-]
  std::vector<int> node;  ///< the grid's node ids
};

/// The top grid of mesh.top_faces (empty on the rigid flat).
MasterSurface make_master_surface(const HexMesh& mesh);

/// A control point of the surface: the node it is, and -1 in `mirror` where it is that node's
/// mirror image across y = 0 (its y coordinate, velocity and force flip) [-].
struct ControlNode {
  int node = -1;
  double mirror = 1.0;
};

/// The control point (a, b) of the surface, a from -1 to nu, b from -2 to nv.
ControlNode control_node(const MasterSurface& surface, long a, long b);

/// Where one slave meets what it hits: gap, normal, and the master nodes with their weights
/// (none on the rigid flat, the default).
struct SlaveContact {
  double gap = 0.0;                    ///< signed normal distance [m] (< 0: penetration)
  double normal[3] = {0.0, 0.0, 1.0};  ///< outward unit normal of the master [-]
  std::array<ControlNode, 16> masters{};
  double weight[16] = {};  ///< each master's share of the slave's force [-] (sum 1)
};

}  // namespace corlab::fem::hex_solver
