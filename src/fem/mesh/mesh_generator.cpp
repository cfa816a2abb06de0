// Built-in impact mesh: options, their validation, and the two bodies' generators
// (src/fem/mesh: graded_distribution, block_geometry, mesh_builder, sphere_ogrid,
// substrate_layout).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/mesh/mesh_generator.hpp"

#include <algorithm>
#include <cstddef>

#include "corlab/core/error.hpp"
#include "corlab/fem/mesh/contact_estimate.hpp"
#include "corlab/fem/mesh/gmsh_reader.hpp"
#include "fem/mesh/mesh_builder.hpp"
#include "fem/mesh/sphere_ogrid.hpp"
#include "fem/mesh/substrate_layout.hpp"

namespace corlab::fem {
namespace {

/// The second sphere (substrate.shape = sphere): the sphere generator's mesh of radius R2 with
/// its lowest point at z = 0, mirrored about z = 0 so that its top point is at the origin, added
/// as the target body. Its surface nodes from the top point outwards (r increasing up to the
/// equator) are the contact's master surface.
void add_target_sphere(const MeshOptions& o, Mesh& mesh) {
  MeshOptions so = o;
  so.sphere_radius = o.target_radius;
  so.gap = 0.0;
  Mesh s;
  meshing::MeshBuilder builder(s);
  meshing::generate_sphere(so, builder, s);
  const int offset = mesh.num_nodes();
  for (int n = 0; n < s.num_nodes(); ++n) {
    mesh.r.push_back(s.r[static_cast<std::size_t>(n)]);
    mesh.z.push_back(-s.z[static_cast<std::size_t>(n)]);
    mesh.node_body.push_back(Body::kSubstrate);
  }
  for (const auto& q : s.quads) {
    // Mirroring turns each quad clockwise: counter_clockwise puts it back.
    mesh.quads.push_back(
        counter_clockwise(mesh, {q[0] + offset, q[1] + offset, q[2] + offset, q[3] + offset}));
    mesh.element_body.push_back(Body::kSubstrate);
  }
  for (const int n : s.sphere_surface_nodes) mesh.substrate_surface_nodes.push_back(n + offset);
}

}  // namespace

void validate(const MeshOptions& o) {
  require_positive("mesh.sphere_radius", o.sphere_radius, "[m]");
  require_non_negative("mesh.gap", o.gap, "[m]");
  const bool block = o.target == SubstrateShape::kFlat;
  if (block) {
    require_positive("mesh.substrate_radius", o.substrate_radius, "[m]");
    require_positive("mesh.substrate_depth", o.substrate_depth, "[m]");
  }
  if (o.target == SubstrateShape::kSphere) {
    require_positive("mesh.target_radius", o.target_radius, "[m]");
    if (o.h_contact > 0.05 * o.target_radius)
      throw_invalid("mesh.h_contact", o.h_contact, "<= R2 / 20 (too coarse for the second sphere)");
  }
  require_positive("mesh.h_contact", o.h_contact, "[m]");
  require_positive("mesh.zone_radius", o.zone_radius, "[m]");
  require_positive("mesh.zone_depth", o.zone_depth, "[m]");
  if (!(o.growth >= 1.0 && o.growth <= 2.0)) throw_invalid("mesh.growth", o.growth, "in [1, 2]");
  require_positive("mesh.h_max", o.h_max, "[m]");
  if (o.h_max < o.h_contact) throw_invalid("mesh.h_max", o.h_max, ">= the contact element size");
  if (o.h_contact > 0.05 * o.sphere_radius)
    throw_invalid("mesh.h_contact", o.h_contact, "<= R / 20 (too coarse for the sphere)");
  // The graded mesh's element count grows with log(R/h), not R/h (a 190 mm second sphere at
  // h = 6.4 um: 17k elements); the bound catches a unit slip (mm for m), not a fine mesh.
  const double max_elements_per_edge = 1e5;
  if (o.sphere_radius / o.h_contact > max_elements_per_edge ||
      o.target_radius / o.h_contact > max_elements_per_edge ||
      (block && (o.substrate_radius / o.h_contact > max_elements_per_edge ||
                 o.substrate_depth / o.h_contact > max_elements_per_edge)))
    throw_invalid("mesh.h_contact", o.h_contact, "coarser (more than 1e5 elements per edge)");
}

MeshOptions mesh_options_for(const ImpactConfig& config) {
  const double a = predicted_contact_radius(config);
  MeshOptions o;
  o.sphere_radius = config.sphere.radius;
  o.gap = config.impact.gap;
  o.substrate_radius = config.substrate.radius;
  o.substrate_depth = config.substrate.depth;
  o.h_contact = config.mesh.h_min;
  if (config.mesh.contact_elements > 0.0)
    o.h_contact = std::min(o.h_contact, a / config.mesh.contact_elements);
  o.zone_radius = config.mesh.refine_factor * a;
  o.zone_depth = config.mesh.refine_depth * a;
  o.growth = config.mesh.growth;
  o.h_max = std::max(config.mesh.h_max, o.h_contact);
  o.transitions = config.mesh.transitions != 0.0;
  o.target = config.substrate.shape;
  o.target_radius = config.substrate.radius;
  return o;
}

double sphere_mesh_elements(const MeshOptions& options) {
  return meshing::sphere_block_elements(options);
}

Mesh generate_impact_mesh(const MeshOptions& options) {
  validate(options);
  Mesh mesh;
  meshing::MeshBuilder builder(mesh);
  meshing::generate_sphere(options, builder, mesh);
  if (options.target == SubstrateShape::kFlat) meshing::generate_substrate(options, builder, mesh);
  if (options.target == SubstrateShape::kSphere) add_target_sphere(options, mesh);
  for (int n = 0; n < mesh.num_nodes(); ++n)
    if (mesh.r[static_cast<std::size_t>(n)] == 0.0) mesh.axis_nodes.push_back(n);
  return mesh;
}

Mesh build_impact_mesh(const ImpactConfig& config) {
  if (!config.mesh.file.empty()) return read_gmsh(config.mesh.file);
  return generate_impact_mesh(mesh_options_for(config));
}

}  // namespace corlab::fem
