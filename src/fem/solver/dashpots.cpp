// The absorbing far boundary's dashpots of both models (dashpots.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "fem/solver/dashpots.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "corlab/fem/mesh/far_boundary.hpp"
#include "corlab/fem/mesh/hex_resolution.hpp"

namespace corlab::fem::solver {
namespace {

BoundaryImpedance substrate_impedance(const ImpactConfig& config) {
  const Material& s = config.substrate.material;
  return lysmer_impedance(s.density, s.p_wave_modulus(), s.shear_modulus());
}

/// The nodes with a non-zero coefficient of the dense per-node arrays (dashpots, springs).
template <std::size_t D>
Dashpots<D> gather(const std::vector<std::array<double, D>>& dense,
                   const std::vector<std::array<double, D>>& springs) {
  Dashpots<D> d;
  for (std::size_t n = 0; n < dense.size(); ++n) {
    bool any = false;
    for (const double c : dense[n]) any = any || c != 0.0;
    if (!any) continue;
    d.node.push_back(static_cast<int>(n));
    d.c.push_back(dense[n]);
    d.k.push_back(springs[n]);
  }
  return d;
}

/// The springs' stiffness per area at a node `distance` [m] from the contact's first point (0
/// without the viscous-spring boundary).
BoundaryStiffness node_springs(const ImpactConfig& config, double distance) {
  if (config.substrate.boundary != SubstrateBoundary::kViscousSpring) return {};
  return spring_stiffness(config.substrate.material.shear_modulus(), distance);
}

/// The area [m^2] of the planar quad a-b-c-d (half the diagonals' cross product).
double quad_area(const HexMesh& m, const std::array<int, 4>& q) {
  const auto p = [&m](int n, std::size_t a) {
    const auto i = static_cast<std::size_t>(n);
    return a == 0 ? m.x[i] : (a == 1 ? m.y[i] : m.z[i]);
  };
  std::array<double, 3> d1{};
  std::array<double, 3> d2{};
  for (std::size_t a = 0; a < 3; ++a) {
    d1[a] = p(q[2], a) - p(q[0], a);
    d2[a] = p(q[3], a) - p(q[1], a);
  }
  const double cx = d1[1] * d2[2] - d1[2] * d2[1];
  const double cy = d1[2] * d2[0] - d1[0] * d2[2];
  const double cz = d1[0] * d2[1] - d1[1] * d2[0];
  return 0.5 * std::sqrt(cx * cx + cy * cy + cz * cz);
}

}  // namespace

Dashpots<2> axisymmetric_dashpots(const ImpactConfig& config,
                                  const Mesh& mesh,
                                  const std::vector<double>& impedance_scale) {
  if (!absorbing_boundary(config)) return {};
  const BoundaryImpedance z = substrate_impedance(config);
  std::vector<std::array<double, 2>> dense(static_cast<std::size_t>(mesh.num_nodes()), {0.0, 0.0});
  std::vector<std::array<double, 2>> springs = dense;
  for (const FarFace<2>& f : far_boundary(mesh)) {
    const auto a = static_cast<std::size_t>(f.nodes[0]);
    const auto b = static_cast<std::size_t>(f.nodes[1]);
    const std::array<double, 2> area =
        ring_segment_areas(mesh.r[a], mesh.z[a], mesh.r[b], mesh.z[b]);
    const double s = impedance_scale[static_cast<std::size_t>(f.element)];
    for (std::size_t k = 0; k < 2; ++k) {
      const auto n = static_cast<std::size_t>(f.nodes[k]);
      const auto axis = static_cast<std::size_t>(f.normal_axis);
      const auto c = face_dashpot<2>(axis, s * area[k], z);
      const auto kn =
          face_spring<2>(axis, area[k], node_springs(config, std::hypot(mesh.r[n], mesh.z[n])));
      for (std::size_t ax = 0; ax < 2; ++ax) {
        dense[n][ax] += c[ax];
        springs[n][ax] += kn[ax];
      }
    }
  }
  return gather(dense, springs);
}

Dashpots<3> hex_dashpots(const ImpactConfig& run, const HexMesh& mesh) {
  ImpactConfig config = run;  // the boundary the run uses: the key's or the model's choice
  config.substrate.boundary = hex_resolution(run).boundary;
  if (!absorbing_boundary(config)) return {};
  const BoundaryImpedance z = substrate_impedance(config);
  std::vector<std::array<double, 3>> dense(static_cast<std::size_t>(mesh.num_nodes()),
                                           {0.0, 0.0, 0.0});
  std::vector<std::array<double, 3>> springs = dense;
  for (const FarFace<4>& f : far_boundary(mesh)) {
    const auto axis = static_cast<std::size_t>(f.normal_axis);
    const double area = 0.25 * quad_area(mesh, f.nodes);
    const auto c = face_dashpot<3>(axis, area, z);
    for (const int node : f.nodes) {
      const auto n = static_cast<std::size_t>(node);
      const double distance =
          std::sqrt(mesh.x[n] * mesh.x[n] + mesh.y[n] * mesh.y[n] + mesh.z[n] * mesh.z[n]);
      const auto kn = face_spring<3>(axis, area, node_springs(config, distance));
      for (std::size_t ax = 0; ax < 3; ++ax) {
        dense[n][ax] += c[ax];
        springs[n][ax] += kn[ax];
      }
    }
  }
  return gather(dense, springs);
}

}  // namespace corlab::fem::solver
