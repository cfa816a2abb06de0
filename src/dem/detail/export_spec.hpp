// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file export_spec.hpp
/// The checks of an ExportSpec (types, labels, targets, the pairs --pair and --pair-table name)
/// and the lookup of a pair's own target, shared by the calibration (dem_export.cpp).
#include <optional>
#include <string>

#include "corlab/dem/dem_export.hpp"

namespace corlab::dem::detail {

/// Smallest and largest particle radius [m]: a nanoparticle to a boulder, where the pair's mass
/// [kg], Hertz stiffness and contact time [s] are finite and the impact ODE resolves the overlap.
inline constexpr double kMinRadius = 1e-9;
inline constexpr double kMaxRadius = 1e3;

/// Validates the spec (InputError naming the field): radii, materials, one target, friction,
/// speeds, labels (unique over the types and the wall, not 'wall', not a bare type id) and the
/// pairs --pair and --pair-table name (existing, at least one particle, each pair named once).
void validate_export_spec(const ExportSpec& spec);

/// The pair's own constant e (--pair), if the spec sets one for (i, j) (j = 0: the wall).
std::optional<double> pair_override(const ExportSpec& spec, int i, int j);
/// The pair's own Coulomb mu (--friction A/B=MU), if the spec sets one for (i, j) (j = 0: the
/// wall of the spec, whose one wall material calibrate_export gives it).
std::optional<double> pair_friction(const ExportSpec& spec, int i, int j);
/// The wall material (0, 1, ...) a pair of names (labels or ids) holds, -1 for a particle pair.
int named_wall(const ExportSpec& spec, const std::string& first, const std::string& second);
/// The walls' checks (dem_walls.cpp): each wall's material exists, planes and cylinders finite.
void validate_walls(const ExportSpec& spec);

/// The pair's own e(v) table (--pair-table), if the spec gives one for (i, j).
const PairTable* pair_table(const ExportSpec& spec, int i, int j);

}  // namespace corlab::dem::detail
