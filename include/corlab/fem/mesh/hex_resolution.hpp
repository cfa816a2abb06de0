// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file hex_resolution.hpp
/// The 3-D model's element size at the contact: the user's (mesh.h_min, mesh.contact_elements)
/// or, when neither key is set, the model's default of kDefaultContactElements elements across
/// the predicted contact radius (docs/theory/solver3d.md, "Default resolution").

#include <string>

#include "corlab/fem/config/impact_config.hpp"

namespace corlab::fem {

/// Elements across the predicted contact radius a that the 3-D model chooses [-]: at a/4 Kharaz's
/// e_t is within 0.002 of a/6 (9.5 deg) and a/3 within 0.002 of a/4 (10 deg), inside their error
/// bars (docs/theory/solver3d.md).
inline constexpr double kDefaultContactElements = 4.0;
/// The coarsest default [-]: where a/4 is finer than the mesh limits allow, the model takes the
/// finest size they allow down to a/3; coarser, it asks for a key instead.
inline constexpr double kMinDefaultContactElements = 3.0;
/// Largest (sphere radius, substrate half-width or depth) / h of a 3-D mesh [-]
/// (hex_mesh_generator.hpp's limit).
inline constexpr double kMaxSizeOverElement = 2000.0;
/// The model's default block (neither substrate size key nor substrate.boundary set): half-width
/// and depth this fraction of the wave's travel c_p t_c during the contact (c_p the block's,
/// t_c Hertz's at the normal speed), with the viscous-spring far boundary [-]. Measured with
/// Kharaz's pair (docs/theory/solver3d.md, "Default block"): at 0.14 c_p t_c (10 mm) e_n is
/// 0.0025 below the half-space's, and e_t at 9.5 deg within 0.0011 of a fixed 20 mm block's.
inline constexpr double kDefaultBlockWaveFraction = 0.14;

/// The grading the 3-D model chooses with its resolution (mesh.growth at its default, which is
/// the axisymmetric model's 1.15): the size ratio of neighbouring elements outside the fine zone
/// [-]. Measured on Kharaz's pair at 4, 10 and 40 deg (docs/theory/solver3d.md, "Default
/// resolution"): e_n, e_t and omega within 0.13 of their error bars of 1.15's, with 2.1-2.4
/// times fewer elements (1.3: e_t at 10 deg 0.19 of its bar; 1.5: omega at 40 deg 0.38).
inline constexpr double kDefaultGrowth3d = 1.25;

/// How the element size at the contact was chosen.
struct HexResolution {
  double h_contact = 0.0;       ///< element size at the contact [m]
  double contact_radius = 0.0;  ///< the predicted contact radius a at the normal speed [m]
  bool model_choice = false;    ///< true: the model's default (no resolution key set)
  std::string reason;           ///< one line: the rule, a/h and its measured basis
  /// The flat's half-width and depth the model chose [m] (0: substrate.radius and .depth): with
  /// the resolution, neither size key nor substrate.boundary set, kDefaultBlockWaveFraction c_p
  /// t_c, at most the default 70 mm and 2000 h.
  double block_size = 0.0;
  /// The far boundary the run uses: the config's, or viscous_spring with the model's block.
  SubstrateBoundary boundary = SubstrateBoundary::kFixed;
  /// The grading the run uses: mesh.growth, or kDefaultGrowth3d with the model's resolution
  /// where mesh.growth is at its default [-].
  double growth = 0.0;
};

/// Whether the 3-D model chooses the resolution: solver.model = 3d with mesh.h_min and
/// mesh.contact_elements at their defaults.
bool uses_default_3d_resolution(const ImpactConfig& config);

/// The element size at the contact of `config`: min(mesh.h_min, a / mesh.contact_elements) when
/// a key is set, else the model's default (a / 4, or the finest size the limits allow down to
/// a / 3). Throws InputError naming the key and value to set where no default mesh is feasible.
HexResolution hex_resolution(const ImpactConfig& config);

/// The sphere's tangential travel over the contact [m]: v sin(angle) x 1.5 Hertz contact times
/// at the normal speed (the length the 3-D block's fine zone is extended by along +x).
double contact_travel(const ImpactConfig& config);

/// `config` with the resolution written into the keys (mesh.h_min = h, mesh.contact_elements =
/// 0, mesh.growth; the model's block size and boundary), so that a coarsened companion
/// (discretisation_error.hpp) scales the chosen size; `config` itself where a key is set.
ImpactConfig with_resolved_3d_mesh(const ImpactConfig& config);

}  // namespace corlab::fem
