// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/mesh/mesh_quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "corlab/fem/kernels/subcycling_level.hpp"

namespace corlab::fem {

QuadQuality quad_quality(const std::array<double, 4>& r, const std::array<double, 4>& z) {
  QuadQuality q;
  double min_edge = std::numeric_limits<double>::infinity();
  double max_edge = 0.0;
  q.min_angle = std::numeric_limits<double>::infinity();
  q.min_jacobian = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < 4; ++k) {
    const std::size_t next = (k + 1) % 4;
    const std::size_t prev = (k + 3) % 4;
    const double ar = r[next] - r[k];
    const double az = z[next] - z[k];
    const double br = r[prev] - r[k];
    const double bz = z[prev] - z[k];
    const double edge = std::hypot(ar, az);
    min_edge = std::min(min_edge, edge);
    max_edge = std::max(max_edge, edge);
    // interior angle at corner k (from the edge to `next` to the edge to `prev`)
    const double cross = ar * bz - az * br;
    const double dot = ar * br + az * bz;
    const double angle = std::atan2(cross, dot);  // negative when the corner is reflex/inverted
    const double interior = angle >= 0.0 ? angle : angle + 2.0 * std::numbers::pi;
    q.min_angle = std::min(q.min_angle, interior);
    q.max_angle = std::max(q.max_angle, interior);
    // bilinear map from [-1,1]^2: the corner Jacobian det is cross / 4
    q.min_jacobian = std::min(q.min_jacobian, 0.25 * cross);
  }
  q.aspect_ratio = max_edge / min_edge;
  // area and first moment (shoelace); the centroid r gives the 2 pi r volume (Pappus)
  double area = 0.0;
  double moment_r = 0.0;
  for (std::size_t k = 0; k < 4; ++k) {
    const std::size_t next = (k + 1) % 4;
    const double c = r[k] * z[next] - r[next] * z[k];
    area += c;
    moment_r += (r[k] + r[next]) * c;
  }
  area *= 0.5;
  moment_r /= 6.0;
  q.area = area;
  q.volume = 2.0 * std::numbers::pi * moment_r;
  const double d1 = std::hypot(r[2] - r[0], z[2] - z[0]);
  const double d2 = std::hypot(r[3] - r[1], z[3] - z[1]);
  q.characteristic_length = area / std::max(d1, d2);
  q.width = area / max_edge;
  return q;
}

namespace {

/// Corner coordinates of element e [m].
void element_corners(const Mesh& mesh, int e, std::array<double, 4>& r, std::array<double, 4>& z) {
  const auto& quad = mesh.quads[static_cast<std::size_t>(e)];
  for (std::size_t k = 0; k < 4; ++k) {
    r[k] = mesh.r[static_cast<std::size_t>(quad[k])];
    z[k] = mesh.z[static_cast<std::size_t>(quad[k])];
  }
}

}  // namespace

QuadQuality element_quality(const Mesh& mesh, int e) {
  std::array<double, 4> r{};
  std::array<double, 4> z{};
  element_corners(mesh, e, r, z);
  return quad_quality(r, z);
}

MeshQuality mesh_quality(const Mesh& mesh, Body body) {
  MeshQuality m;
  bool first = true;
  for (int e = 0; e < mesh.num_elements(); ++e) {
    if (mesh.element_body[static_cast<std::size_t>(e)] != body) continue;
    std::array<double, 4> r{};
    std::array<double, 4> z{};
    element_corners(mesh, e, r, z);
    const QuadQuality q = quad_quality(r, z);
    double min_edge = std::numeric_limits<double>::infinity();
    double max_edge = 0.0;
    for (std::size_t k = 0; k < 4; ++k) {
      const double edge = std::hypot(r[(k + 1) % 4] - r[k], z[(k + 1) % 4] - z[k]);
      min_edge = std::min(min_edge, edge);
      max_edge = std::max(max_edge, edge);
    }
    if (first) {
      m.min_angle = q.min_angle;
      m.max_angle = q.max_angle;
      m.max_aspect_ratio = q.aspect_ratio;
      m.min_jacobian = q.min_jacobian;
      m.min_characteristic_length = q.characteristic_length;
      m.min_width = q.width;
      m.min_edge = min_edge;
      m.max_edge = max_edge;
      first = false;
    }
    m.min_angle = std::min(m.min_angle, q.min_angle);
    m.max_angle = std::max(m.max_angle, q.max_angle);
    m.max_aspect_ratio = std::max(m.max_aspect_ratio, q.aspect_ratio);
    m.min_jacobian = std::min(m.min_jacobian, q.min_jacobian);
    m.min_characteristic_length = std::min(m.min_characteristic_length, q.characteristic_length);
    m.min_width = std::min(m.min_width, q.width);
    m.min_edge = std::min(m.min_edge, min_edge);
    m.max_edge = std::max(m.max_edge, max_edge);
    m.area += q.area;
    m.volume += q.volume;
    ++m.elements;
  }
  for (const Body b : mesh.node_body)
    if (b == body) ++m.nodes;
  return m;
}

ExplicitCost explicit_cost(const Mesh& mesh, Body body, double shortest) {
  ExplicitCost cost;
  for (int e = 0; e < mesh.num_elements(); ++e) {
    if (mesh.element_body[static_cast<std::size_t>(e)] != body) continue;
    const double length = element_quality(mesh, e).characteristic_length;
    const int level = subcycling_level(shortest, length, kCostLevels);
    ++cost.elements_at_level[static_cast<std::size_t>(level)];
    cost.updates += std::ldexp(1.0, -level);
  }
  return cost;
}

}  // namespace corlab::fem
