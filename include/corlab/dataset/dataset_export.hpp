// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file dataset_export.hpp
/// From a finished (or partly finished) dataset sweep to the published dataset
/// (data/fe_restitution/): one row per design point run, its dimensionless inputs, its
/// dimensional settings, every result column, whether it is in the fitting set and why not.
///
///   dataset.csv     the rows, in design order
///   columns.json    every column of dataset.csv: name, unit, kind, description
///   configs.jsonl   per row: case_id, design_index and the full impact config (provenance)
///   summary.json    counts, exclusions by reason, CPU time, error-estimate statistics, builds

#include <cstddef>
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include "corlab/study/results_table.hpp"

namespace corlab::dataset {

/// Which runs enter the fitting set.
struct InclusionLimits {
  double energy_balance = 5e-3;  ///< largest energy-balance error [-] (issue 10: 0.5 %)
};

/// Why row `row` of a sweep's results is left out of the fitting set; empty if it is in: status
/// not ok, no finite e in (0, 1], energy balance above the limit, or the run's own suspect
/// reason (hourglass energy, contact penetration).
std::string exclusion_reason(const study::ResultsTable& results,
                             std::size_t row,
                             const InclusionLimits& limits);

/// What an export wrote.
struct ExportSummary {
  std::size_t design_points = 0;                ///< runs of the spec
  std::size_t rows = 0;                         ///< finished runs exported
  std::size_t included = 0;                     ///< of those, in the fitting set
  std::map<std::string, std::size_t> excluded;  ///< reason (its first words) -> count
  double cpu_s = 0.0;                           ///< sum of the runs' wall times, one core each [s]
  double e_error_max = 0.0;      ///< largest relative error estimate e_error / e, included rows [-]
  double e_error_median = 0.0;   ///< its median [-]
  std::set<std::string> builds;  ///< corlab_build values of the rows
};

/// Exports the sweep in `sweep_dir` (its results.csv and spec.toml) to `out_dir` (created).
/// Throws InputError for a missing or foreign results.csv (a case_id the spec does not have).
ExportSummary export_dataset(const std::filesystem::path& sweep_dir,
                             const std::filesystem::path& out_dir,
                             const InclusionLimits& limits = {});

}  // namespace corlab::dataset
