// Adds structured blocks to a mesh, merging the nodes they share within a body.
// SPDX-License-Identifier: BSD-3-Clause
#include "fem/mesh/mesh_builder.hpp"

#include <array>

namespace corlab::fem::meshing {

void MeshBuilder::start_body(Body body) {
  body_ = body;
  index_.clear();
}

int MeshBuilder::node(Point p) {
  const auto [it, inserted] = index_.try_emplace({p.r, p.z}, mesh_.num_nodes());
  if (inserted) {
    mesh_.r.push_back(p.r);
    mesh_.z.push_back(p.z);
    mesh_.node_body.push_back(body_);
  }
  return it->second;
}

std::vector<int> MeshBuilder::block(const std::vector<Point>& pts, std::size_t ni, std::size_t nj) {
  std::vector<int> ids(pts.size());
  for (std::size_t k = 0; k < pts.size(); ++k) ids[k] = node(pts[k]);
  for (std::size_t i = 0; i < ni; ++i) {
    for (std::size_t j = 0; j < nj; ++j) {
      const std::array<int, 4> q{ids[i * (nj + 1) + j], ids[(i + 1) * (nj + 1) + j],
                                 ids[(i + 1) * (nj + 1) + j + 1], ids[i * (nj + 1) + j + 1]};
      mesh_.quads.push_back(counter_clockwise(mesh_, q));
      mesh_.element_body.push_back(body_);
    }
  }
  return ids;
}

void MeshBuilder::quad(const std::array<Point, 4>& p) {
  const std::array<int, 4> q{node(p[0]), node(p[1]), node(p[2]), node(p[3])};
  mesh_.quads.push_back(counter_clockwise(mesh_, q));
  mesh_.element_body.push_back(body_);
}

void MeshBuilder::transition(const std::array<Point, 4>& fine, Point c0, Point c1, double depth) {
  for (const auto& q : transition_quads(fine, c0, c1, depth)) quad(q);
}

std::array<std::array<Point, 4>, 4> transition_quads(const std::array<Point, 4>& fine,
                                                     Point c0,
                                                     Point c1,
                                                     double depth) {
  const double length = norm(fine[3] - fine[0]);
  const auto interior = [&](Point f) {
    const Point c = c0 + (norm(f - fine[0]) / length) * (c1 - c0);
    return f + depth * (c - f);
  };
  const Point i1 = interior(fine[1]);
  const Point i2 = interior(fine[2]);
  return {{{fine[0], fine[1], i1, c0},
           {fine[1], fine[2], i2, i1},
           {fine[2], fine[3], c1, i2},
           {c0, i1, i2, c1}}};
}

}  // namespace corlab::fem::meshing
