// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/discretisation_error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "corlab/core/error.hpp"
#include "corlab/fem/mesh/hex_resolution.hpp"
#include "corlab/fem/solver/error_bar.hpp"
#include "corlab/fem/solver/run_quality.hpp"

namespace corlab::fem {

ImpactConfig coarsened(const ImpactConfig& config, double ratio) {
  if (!config.mesh.file.empty()) {
    throw_invalid("mesh.file", config.mesh.file.string(),
                  "empty (the error estimate coarsens the built-in mesh)");
  }
  // The 3-D model's default size written into the keys first, so that it is what is scaled.
  ImpactConfig c = with_resolved_3d_mesh(config);
  c.mesh.h_min *= ratio;
  c.mesh.contact_elements /= ratio;
  c.mesh.h_max *= ratio;
  // `ratio` graded layers of growth g merged into one grow by g^ratio; capped at the key's bound.
  c.mesh.growth = std::min(std::pow(c.mesh.growth, ratio), MeshConfig::kMaxGrowth);
  return c;
}

ImpactResult simulate_with_error_estimate(const ImpactConfig& config,
                                          const SimulationControl& control) {
  ImpactResult fine = simulate(config, control);
  if (fine.status == RunStatus::kCancelled) return fine;
  if (!config.mesh.file.empty()) {
    fine.e_error_reason = "mesh.file is set: the estimate coarsens only the built-in mesh";
    return fine;
  }
  SimulationControl quiet;
  quiet.cancel = control.cancel;
  // The grids the estimator reads: the run's own (ratio 1) and its coarser companions.
  std::vector<double> e{fine.e};
  std::vector<double> e_t{fine.e_t};
  std::vector<double> omega{fine.omega};
  std::vector<double> ratios{1.0};
  std::string reason;
  for (const double ratio : kErrorBarRatios) {
    ImpactResult coarse;
    try {
      coarse = simulate(coarsened(config, ratio), quiet);
    } catch (const InputError& err) {
      // no coarser mesh allowed (e.g. beyond R / 20): the estimate uses the grids it has
      if (reason.empty())
        reason = fmt::format("no companion mesh at {:.3g}h: {}", ratio, err.what());
      continue;
    }
    fine.wall_s += coarse.wall_s;
    if (coarse.status == RunStatus::kCancelled) {
      fine.status = RunStatus::kCancelled;
      fine.status_detail = "interrupted";
      return fine;
    }
    if (ratio == kErrorRefinementRatio) fine.e_coarse = coarse.e;
    if (coarse.status != RunStatus::kSeparated) {
      if (reason.empty()) {
        reason = fmt::format("the companion run at {:.3g}h ended as {}{}", ratio,
                             to_string(coarse.status),
                             coarse.status_detail.empty() ? "" : " (" + coarse.status_detail + ")");
      }
      continue;
    }
    e.push_back(coarse.e);
    e_t.push_back(coarse.e_t);
    omega.push_back(coarse.omega);
    ratios.push_back(ratio);
  }
  if (fine.status != RunStatus::kSeparated) {
    fine.e_error_reason =
        fmt::format("the run ended as {}{}", to_string(fine.status),
                    fine.status_detail.empty() ? "" : " (" + fine.status_detail + ")");
    return fine;
  }
  fine.e_error = error_bar(kDefaultErrorBar, e, ratios);
  // The tangential results of an oblique impact: the same estimator on the same grids. A normal
  // impact has neither: its e_t is NaN (so is e_t_error) and its spin is round-off, left
  // without a bar.
  fine.e_t_error = error_bar(kDefaultErrorBar, e_t, ratios);
  if (std::isfinite(fine.e_t)) fine.omega_error = error_bar(kDefaultErrorBar, omega, ratios);
  if (!std::isfinite(fine.e_error)) fine.e_error_reason = reason;
  fine.suspect = suspect_reason(fine);  // e above 1 is now judged against its error bar
  return fine;
}

}  // namespace corlab::fem
