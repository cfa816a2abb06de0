// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file mesh_generator.hpp
/// Built-in structured quad mesh of the axisymmetric impact model (see docs/theory/mesh.md):
///  - substrate: tensor-product grid, uniform size h in the refined zone r < zone_radius,
///    z > -zone_depth, geometric growth (ratio `growth`) outside up to h_max;
///  - sphere: multi-block O-grid (bottom, right and top ring blocks around a curved core) built by
///    transfinite (Coons) interpolation, size h at the lowest point along the arc and in depth,
///    growing away from it.
/// Both bodies follow the conventions of mesh.hpp.

#include <vector>

#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/mesh/mesh.hpp"

namespace corlab::fem {

/// Geometry and sizing of the generated mesh (all lengths in metres).
struct MeshOptions {
  double sphere_radius = 35e-3;     ///< R [m]
  double gap = 0.1e-3;              ///< lowest sphere point above the substrate, z = gap [m]
  double substrate_radius = 70e-3;  ///< W [m]
  double substrate_depth = 70e-3;   ///< D [m]
  double h_contact = 0.25e-3;       ///< element size in the refined zone [m]
  double zone_radius =
      8e-3;  ///< radial extent of the uniform zone (and arc length on the sphere) [m]
  double zone_depth = 8e-3;  ///< depth of the uniform zone below the contact [m]
  double growth = 1.15;      ///< size ratio of neighbouring elements outside the zone [-]
  double h_max = 5e-3;       ///< largest element size [m]
  /// Build the tensor-grid substrate, the sphere's bottom ring below the refined depth and its
  /// skin beyond the refined zone with 3:1 transitions (docs/theory/mesh.md, "3:1 transitions",
  /// "Skin transitions"): fewer elements where the zone's fine columns and rows would run on.
  bool transitions = true;
  /// What the sphere hits: the substrate block (flat), nothing (rigid: the sphere alone), or a
  /// second sphere of radius target_radius whose top point is at the origin (sphere).
  SubstrateShape target = SubstrateShape::kFlat;
  double target_radius = 35e-3;  ///< R2 [m] (target sphere only)
};

/// Throws InputError naming the first invalid field ("mesh.h_contact", ...).
void validate(const MeshOptions& options);

/// Options for a configuration: h = min(mesh.h_min, a_pred / mesh.contact_elements) (the bound only
/// when contact_elements > 0), zone_radius = mesh.refine_factor x a_pred, zone_depth =
/// mesh.refine_depth x a_pred, with a_pred = predicted_contact_radius(config)
/// (contact_estimate.hpp).
MeshOptions mesh_options_for(const ImpactConfig& config);

/// The sphere's O-grid elements (sphere_radius) without transitions, from its 1-D distributions
/// alone, nothing built: an upper bound of its count [-] (config_limits' work caps).
double sphere_mesh_elements(const MeshOptions& options);

/// Generates both bodies (sphere elements first, then the target's: the substrate block or the
/// second sphere, mirrored about z = 0; none for the rigid flat).
Mesh generate_impact_mesh(const MeshOptions& options);

/// The mesh of a configuration: read_gmsh(config.mesh.file) when a file is given (the geometry
/// is then the file's: sphere.radius, substrate.radius/depth and impact.gap are not applied), else
/// generate_impact_mesh(mesh_options_for(config)).
Mesh build_impact_mesh(const ImpactConfig& config);

/// Node positions 0 = x_0 < x_1 < ... < x_n = length [m] of a graded 1D distribution: intervals
/// of size h up to `uniform_length`, then growing by the factor `growth` per interval up to
/// `h_max`; the graded intervals are rescaled (by the factor closest to 1) to end exactly at
/// `length`. Returns n + 1 positions.
std::vector<double> graded_positions(
    double length, double h, double uniform_length, double growth, double h_max);

}  // namespace corlab::fem
