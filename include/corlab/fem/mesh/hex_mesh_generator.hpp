// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file hex_mesh_generator.hpp
/// The structured hexahedral mesh of the 3-D impact model (docs/theory/mesh.md, "3-D mesh"):
/// the half sphere (y >= 0) as a cube-sphere O-grid, a core cube and five shell blocks (bottom,
/// top, -x, +x, +y) whose nodes all come from one map of cube-shell coordinates to the ball,
/// graded so that the elements at the lowest point are h_contact wide in every direction.
///
/// A node is named by cube coordinates (X, Y, Z) in [-1, 1]^3 and a shell parameter t in [0, 1]:
///   p = (1 - t) s (X, Y, Z) + t R normalise(E(X), E(Y), E(Z)),  E(c) = tan(pi c / 4),
/// s = core_fraction R the core's half-width. On a block's outer face (t = 1) the map is the
/// equiangular cube-sphere projection; t = 0 is the core cube. Blocks that share a face evaluate
/// it from the same coordinates, so their nodes coincide exactly and are merged by value.
///
/// Grading: X (and Y from 0) fine at 0, the lowest point's tangential size h_contact on the
/// surface (arc R pi/4 dX) for `zone_radius`, then growing by `growth` up to h_max; t fine at
/// the surface (radial size h_contact for `zone_depth`); the sides' and core's Z uniform at the
/// bottom face's edge size.

#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/mesh/hex_mesh.hpp"

namespace corlab::fem {

/// What the 3-D generator needs [m].
struct HexMeshOptions {
  double sphere_radius = 35e-3;  ///< R
  double gap = 0.0;              ///< lowest point's height above z = 0
  double h_contact = 1e-3;       ///< element size at the lowest point
  double zone_radius = 5e-3;     ///< arc from the lowest point kept at h_contact
  double zone_depth = 3e-3;      ///< depth below the surface kept at h_contact
  double growth = 1.2;           ///< size ratio of neighbouring elements outside the zone [-]
  double h_max = 5e-3;           ///< largest element size
  double core_fraction = 0.45;   ///< core half-width / R [-]
  /// The deformable flat (a half block below z = 0), or none (the rigid flat).
  bool block = false;
  double block_half_width = 70e-3;  ///< x in [-w, w], y in [0, w]
  double block_depth = 70e-3;       ///< z in [-depth, 0]; the base is fixed
  /// Extra length of the fine zone towards +x: the contact's tangential travel.
  double travel = 0.0;
};

/// Throws InputError naming the first invalid option.
void validate(const HexMeshOptions& options);

/// The options of a configuration: h_contact = min(mesh.h_min, a / mesh.contact_elements), the
/// zone refine_factor a wide and max(refine_depth a, 2 h_contact) deep, a the predicted contact
/// radius at the normal speed velocity cos(angle) (contact_estimate.hpp); the gap is 0 (the
/// solver crosses it in free flight). On the deformable flat (substrate.shape = flat) the block
/// is substrate.radius wide and substrate.depth deep, its fine zone extended along +x by the
/// travel v_t x 1.5 Hertz contact times.
HexMeshOptions hex_mesh_options_for(const ImpactConfig& config);

/// The half block of the deformable flat (Body::kSubstrate) appended to `mesh`: a tensor grid
/// graded from the contact (h_contact over [-zone_radius, zone_radius + travel] in x,
/// [0, zone_radius] in y, zone_depth in z, then growing by `growth` up to h_max); top_faces,
/// base_nodes and its symmetry nodes set.
void append_hex_block(const HexMeshOptions& options, HexMesh& mesh);

/// The half sphere (Body::kSphere) resting with its lowest point at z = gap, centre on the z
/// axis; symmetry_nodes and sphere_surface_nodes set.
HexMesh generate_hex_sphere(const HexMeshOptions& options);

/// The element count of generate_hex_impact_mesh(options), exactly, from the 1-D node
/// distributions alone (no node is built): the work caps' count before meshing [-]. Throws
/// InputError as validate() does.
double hex_impact_elements(const HexMeshOptions& options);

/// The impact's mesh: the half sphere, and the flat's half block when options.block.
HexMesh generate_hex_impact_mesh(const HexMeshOptions& options);

/// The impact's mesh of a configuration: the half sphere built in, or read from mesh.file
/// (gmsh_hex_reader.hpp), and the flat's half block of hex_mesh_options_for(config).
HexMesh build_hex_impact_mesh(const ImpactConfig& config);

}  // namespace corlab::fem
