// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file mesh_builder.hpp
/// Adds the generated blocks to a Mesh, one body at a time, sharing nodes between the blocks of a
/// body. Private to the mesh generator (src/fem/mesh).

#include <array>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

#include "corlab/fem/mesh/mesh.hpp"
#include "fem/mesh/block_geometry.hpp"

namespace corlab::fem::meshing {

/// transition_quads' interior nodes halfway across the layer: the plain template.
inline constexpr double kHalfwayDepth = 0.5;

/// The four quads of the 3:1 transition between a fine edge f0 -> f3 (three intervals) and the
/// coarse edge c0 -> c1 opposite it (one interval; c0 faces f0), around two interior nodes, each
/// the fraction `depth` of the way from f1 (f2) to the point of the coarse edge at f1's (f2's)
/// fraction of the edge (halfway by default). With equal fine intervals, a layer twice as thick
/// and depth 1/2, its corners are 45/135 deg.
std::array<std::array<Point, 4>, 4> transition_quads(const std::array<Point, 4>& fine,
                                                     Point c0,
                                                     Point c1,
                                                     double depth = kHalfwayDepth);

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
  /// Adds one quad with corners p (either orientation).
  void quad(const std::array<Point, 4>& p);
  /// Adds the 3:1 transition of transition_quads.
  void transition(const std::array<Point, 4>& fine,
                  Point c0,
                  Point c1,
                  double depth = kHalfwayDepth);

 private:
  Mesh& mesh_;
  Body body_ = Body::kSphere;
  std::map<std::pair<double, double>, int> index_;
};

}  // namespace corlab::fem::meshing
