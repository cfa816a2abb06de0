// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file dataset_spec.hpp
/// The dataset's design written as a `corlab sweep` spec: Sobol points of the box
/// (impact_box.hpp), one [[cases]] table each, over a [base] at the paper's resolution. The spec
/// is what `corlab sweep` runs (resumable, MPI); `corlab dataset design` writes it and a test
/// checks that the committed studies/dataset/fe_restitution.toml and fe_restitution_pairs.toml
/// are what it writes.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "corlab/dataset/impact_box.hpp"
#include "corlab/study/sweep_spec.hpp"

namespace corlab::dataset {

/// What the design is.
struct DatasetDesign {
  std::string name = "fe_restitution";  ///< [study] name
  std::size_t points = 2048;            ///< Sobol points 0 .. points-1 (2^m: stratified)
  ImpactBox box;
};

/// The particle-particle and particle-wall design (issue 26): pair_box(), named
/// fe_restitution_pairs (studies/dataset/fe_restitution_pairs.toml).
DatasetDesign pair_design();

/// One design point: its Sobol index and coordinates, the box point and its sweep settings.
struct DesignPoint {
  std::size_t index = 0;
  std::vector<double> u;  ///< design coordinates in [0, 1)^box_dimension(box)
  DimensionlessImpact point;
  study::Settings settings;
};

/// Requires `points` in [1, study::kMaxRunsLimit] (the most runs a sweep spec may hold): InputError
/// naming `field` (e.g. "--points").
void validate_design_points(std::size_t points, std::string_view field);

/// The points of the design, in Sobol order (validate_design_points first).
std::vector<DesignPoint> design_points(const DatasetDesign& design);

/// Settings every run shares: the box's E_substrate and densities (rho_substrate only for a
/// pair box, whose cases set rho_sphere), the paper's contact mesh
/// (0.25 mm, finer where the contact is small: h <= a / 12) and a step budget for the
/// quasi-static runs just above first yield at the smallest k2.
study::Settings dataset_base_settings(const ImpactBox& box);

/// The spec text; `command` (the command line that wrote it) goes into its header comment as one
/// line of text (line breaks and other control characters escaped: a file name given to --out
/// stays a comment). Every string value is a TOML basic string (toml++'s escaping).
std::string dataset_spec_toml(const DatasetDesign& design, std::string_view command);

}  // namespace corlab::dataset
