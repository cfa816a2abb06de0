// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file hex_mesh.hpp
/// 3-D hexahedral mesh of an impact: the half model (y >= 0) cut by the plane that holds the
/// impact velocity and the contact normal (x, z), z up. Coordinates [m]. Node order of each
/// hexahedron as hex8.hpp (positive volume).

#include <array>
#include <vector>

#include "corlab/fem/mesh/mesh.hpp"

namespace corlab::fem {

struct HexMesh {
  std::vector<double> x, y, z;            ///< node coordinates [m]
  std::vector<std::array<int, 8>> hexes;  ///< element nodes (hex8.hpp order)
  std::vector<Body> element_body;         ///< body of each element
  std::vector<Body> node_body;            ///< body of each node; bodies share no node
  std::vector<int> symmetry_nodes;        ///< nodes on y = 0: v_y held at zero
  std::vector<int> base_nodes;            ///< substrate bottom: fully fixed
  std::vector<int> sphere_surface_nodes;  ///< sphere surface nodes below its centre (slaves)
  /// Substrate top-surface quads (contact masters), counter-clockwise seen from +z, row by row:
  /// face (i, j) is top_faces[j (top_x.size() - 1) + i].
  std::vector<std::array<int, 4>> top_faces;
  std::vector<double> top_x;  ///< the top grid's x lines at the start [m] (increasing)
  std::vector<double> top_y;  ///< its y lines [m] (increasing from 0)

  int num_nodes() const { return static_cast<int>(x.size()); }
  int num_elements() const { return static_cast<int>(hexes.size()); }
};

}  // namespace corlab::fem
