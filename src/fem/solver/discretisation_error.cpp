#include "corlab/fem/solver/discretisation_error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "corlab/core/error.hpp"

namespace corlab::fem {

ImpactConfig coarsened(const ImpactConfig& config, double ratio) {
  if (!config.mesh.file.empty()) {
    throw_invalid("mesh.file", config.mesh.file.string(),
                  "empty (the error estimate coarsens the built-in mesh)");
  }
  ImpactConfig c = config;
  c.mesh.h_min *= ratio;
  c.mesh.contact_elements /= ratio;
  c.mesh.h_max *= ratio;
  // `ratio` graded layers of growth g merged into one grow by g^ratio; capped at the key's bound.
  c.mesh.growth = std::min(std::pow(c.mesh.growth, ratio), MeshConfig::kMaxGrowth);
  return c;
}

double grid_convergence_index(double e_fine, double e_coarse, double ratio) {
  if (!std::isfinite(e_fine) || !std::isfinite(e_coarse)) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return kGciSafetyFactor * std::abs(e_fine - e_coarse) / (std::pow(ratio, kGciOrder) - 1.0);
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
  ImpactResult coarse;
  try {
    coarse = simulate(coarsened(config), quiet);
  } catch (const InputError& err) {
    // no coarser mesh is allowed (e.g. beyond R / 20): no error bar, e_error NaN, said why
    fine.e_error_reason = std::string("no companion mesh at 2h: ") + err.what();
    return fine;
  }
  if (coarse.status == RunStatus::kCancelled) {
    fine.status = RunStatus::kCancelled;
    fine.status_detail = "interrupted";
    return fine;
  }
  fine.e_coarse = coarse.e;
  fine.e_error = grid_convergence_index(fine.e, coarse.e);
  if (!std::isfinite(fine.e_error)) {
    const ImpactResult& failed = fine.status != RunStatus::kSeparated ? fine : coarse;
    fine.e_error_reason =
        fmt::format("{} ended as {}{}", &failed == &fine ? "the run" : "the companion run at 2h",
                    to_string(failed.status),
                    failed.status_detail.empty() ? "" : " (" + failed.status_detail + ")");
  }
  fine.wall_s += coarse.wall_s;
  return fine;
}

}  // namespace corlab::fem
