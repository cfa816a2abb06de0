// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file far_boundary.hpp
/// The flat substrate's far boundary (docs/theory/mesh.md, "Far boundary"): its faces away from
/// the contact, where substrate.boundary chooses fixed or absorbing (absorbing_boundary.hpp). A
/// face is far when all its nodes lie on one of the substrate's outer planes: in the
/// axisymmetric mesh the side r = r_max and the base z = z_min; in the 3-D half block the sides
/// x = x_min, x = x_max, y = y_max (not the symmetry plane y = 0) and the base z = z_min. The
/// substrate is a box in both generators and in a Gmsh file's substrate that is one; a face on
/// an outer plane is on the boundary, so no face count is needed.

#include <array>
#include <vector>

#include "corlab/fem/mesh/hex_mesh.hpp"
#include "corlab/fem/mesh/mesh.hpp"

namespace corlab::fem {

/// One far face: its nodes, the axis of its normal (axisymmetric 0 = r, 1 = z; 3-D 0 = x,
/// 1 = y, 2 = z) and the substrate element it bounds (mesh index).
template <std::size_t N>
struct FarFace {
  std::array<int, N> nodes{};
  int normal_axis = 0;
  int element = 0;
};

/// The far segments of the axisymmetric mesh's substrate (none without a substrate body).
std::vector<FarFace<2>> far_boundary(const Mesh& mesh);

/// The far quads of the 3-D mesh's block (none without a block).
std::vector<FarFace<4>> far_boundary(const HexMesh& mesh);

}  // namespace corlab::fem
