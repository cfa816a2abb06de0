#pragma once
/// @file mesh_builder.hpp
/// Adds the generated blocks to a Mesh, one body at a time, sharing nodes between the blocks of a
/// body. Private to the mesh generator (src/fem/mesh).

#include <cstddef>
#include <map>
#include <utility>
#include <vector>

#include "corlab/fem/mesh/mesh.hpp"
#include "fem/mesh/block_geometry.hpp"

namespace corlab::fem::meshing {

/// Adds nodes and elements to a mesh, merging nodes at bitwise-equal coordinates within a body.
class MeshBuilder {
 public:
  explicit MeshBuilder(Mesh& mesh) : mesh_(mesh) {}
  /// Nodes and elements added from now on belong to `body` (and merge only with its nodes).
  void start_body(Body body);
  /// The node at p (added when the body has none there).
  int node(Point p);
  /// Adds a block of (ni+1) x (nj+1) points (index i * (nj+1) + j); returns its node ids.
  std::vector<int> block(const std::vector<Point>& pts, std::size_t ni, std::size_t nj);

 private:
  Mesh& mesh_;
  Body body_ = Body::kSphere;
  std::map<std::pair<double, double>, int> index_;
};

}  // namespace corlab::fem::meshing
