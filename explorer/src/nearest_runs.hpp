// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file nearest_runs.hpp
/// The FE dataset's runs nearest a material pair (docs/user/explorer.md). By dimensional analysis
/// e depends on the dimensionless inputs only (docs/theory/dataset.md), so a run whose inputs
/// other than the speed match the pair's is the pair's own FE result at the speed with the same
/// k1 = E*/(rho v^2). The distance is taken in those inputs, each scaled to the span the dataset
/// covers: ln k2, ln(E_sphere/E_substrate), nu of each body, H/E of each body, and for a yielding
/// sphere ln(sigma_y,sphere/sigma_y,substrate); an elastic sphere against a yielding one (or the
/// reverse) adds 1.

#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "corlab/materials/material.hpp"

namespace corlab::explorer {

/// One run of data/fe_restitution/dataset.csv (the columns of the same names) [SI, -].
struct DatasetRun {
  long design_index = 0;
  std::string case_id;
  double k1 = 0.0;
  double k2 = 0.0;
  double modulus_ratio = 0.0;
  double sphere_yield_ratio = 0.0;  ///< infinite for an elastic sphere
  double nu_sphere = 0.0;
  double nu_substrate = 0.0;
  double hardening_ratio_sphere = 0.0;
  double hardening_ratio_substrate = 0.0;
  double density_ratio = 0.0;
  double velocity = 0.0;  ///< the run's own speed [m/s]
  double e = 0.0;
  double e_error = 0.0;  ///< two-grid discretisation-error estimate of e (nan: none)
};

/// Reads the runs from JSON columns (explorer_api.hpp, load_dataset); keeps the rows with
/// status "ok" and included true. Throws InputError naming a missing or malformed column.
std::vector<DatasetRun> runs_from_columns(const nlohmann::json& columns);

/// The `count` runs nearest the pair whose speed mapped onto the pair (same k1) lies within
/// [v_min, v_max] [m/s], nearest first, as JSON objects (the run's inputs, e, e_error, its
/// distance and the pair's speed of equal k1 "velocity_pair").
nlohmann::json nearest_runs(std::span<const DatasetRun> runs,
                            const Material& sphere,
                            const Material& substrate,
                            double v_min,
                            double v_max,
                            std::size_t count);

}  // namespace corlab::explorer
