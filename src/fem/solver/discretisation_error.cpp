// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/discretisation_error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <optional>
#include <string>
#include <system_error>
#include <thread>
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

std::vector<double> error_bar_ratios(const ImpactConfig& config) {
  if (!uses_3d_model(config) || !config.mesh.file.empty())
    return {kErrorBarRatios.begin(), kErrorBarRatios.end()};
  std::vector<double> ratios(kErrorBarRatios3d.begin(), kErrorBarRatios3d.end());
  const HexResolution r = hex_resolution(with_resolved_3d_mesh(config));
  const double across = r.contact_radius / r.h_contact;  // elements across a at the run's mesh
  // A relative margin keeps a/4's companion at 2h (a/2 to round-off).
  std::erase_if(ratios,
                [&](double q) { return across / q < kMinCompanionContactElements * (1 - 1e-9); });
  return ratios;
}

namespace {

/// One of the runs of an estimate: the run itself (ratio 1) or a companion.
struct EstimateRun {
  double ratio = 1.0;
  ImpactResult result;
  std::string invalid;       ///< why the companion's mesh is not a valid config (InputError)
  std::exception_ptr error;  ///< anything else the run threw
};

/// Takes one of the caller's spare threads (SimulationControl::spare_threads) if there is one.
bool take_spare(std::atomic<int>* spare) {
  if (spare == nullptr) return false;
  int n = spare->load();
  while (n > 0) {
    if (spare->compare_exchange_weak(n, n - 1)) return true;
  }
  return false;
}

/// Runs runs[k]: the run itself (k = 0, with the caller's control) or a companion (`quiet`).
void run_estimate_run(const ImpactConfig& config,
                      const SimulationControl& control,
                      const SimulationControl& quiet,
                      std::size_t k,
                      EstimateRun& run) {
  try {
    if (k == 0) {
      run.result = simulate(config, control);
      return;
    }
    try {
      run.result = simulate(coarsened(config, run.ratio), quiet);
    } catch (const InputError& err) {
      // no coarser mesh allowed (e.g. beyond R / 20): the estimate uses the grids it has
      run.invalid = err.what();
    }
  } catch (...) {
    run.error = std::current_exception();
  }
}

/// The run's result (runs[0]) with e_coarse, the error bars and their reason from its
/// companions (runs[1..]); e's bar by `e_estimator` (error_bar_estimator).
ImpactResult combine_estimate(std::vector<EstimateRun>& runs,
                              std::string reason,
                              std::string_view e_estimator) {
  ImpactResult fine = std::move(runs.front().result);
  if (fine.status == RunStatus::kCancelled) return fine;
  // The grids the estimator reads: the run's own (ratio 1) and its coarser companions.
  std::vector<double> e{fine.e};
  std::vector<double> e_t{fine.e_t};
  std::vector<double> omega{fine.omega};
  std::vector<double> ratios{1.0};
  for (std::size_t k = 1; k < runs.size(); ++k) {
    const double ratio = runs[k].ratio;
    if (!runs[k].invalid.empty()) {
      if (reason.empty())
        reason = fmt::format("no companion mesh at {:.3g}h: {}", ratio, runs[k].invalid);
      continue;
    }
    const ImpactResult& coarse = runs[k].result;
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
  fine.e_error = error_bar(e_estimator, e, ratios);
  // The tangential results of an oblique (3-D) impact: their estimator on the same grids. A
  // normal impact has neither: its e_t is NaN (so is e_t_error) and its spin is round-off, left
  // without a bar.
  fine.e_t_error = error_bar(kErrorBar3dTangential, e_t, ratios);
  if (std::isfinite(fine.e_t)) fine.omega_error = error_bar(kErrorBar3dTangential, omega, ratios);
  if (!std::isfinite(fine.e_error)) fine.e_error_reason = reason;
  fine.suspect = suspect_reason(fine);  // e above 1 is now judged against its error bar
  return fine;
}

}  // namespace

std::string_view error_bar_estimator(const ImpactConfig& config) {
  return uses_3d_model(config) ? kErrorBar3dNormal : kDefaultErrorBar;
}

ImpactResult simulate_with_error_estimate(const ImpactConfig& config,
                                          const SimulationControl& control) {
  if (!config.mesh.file.empty()) {
    ImpactResult fine = simulate(config, control);
    if (fine.status != RunStatus::kCancelled) {
      fine.e_error_reason = "mesh.file is set: the estimate coarsens only the built-in mesh";
    }
    return fine;
  }
  // The companions need e only: they end at the first short window after the last contact.
  SimulationControl quiet;
  quiet.cancel = control.cancel;
  quiet.e_only = true;
  // The run itself first, then its companions dearest first; on a spare thread of the caller's
  // pool (a sweep's tail) two at a time. Each run is single-threaded and deterministic, so the
  // result does not depend on which thread ran what.
  const std::vector<double> companions = error_bar_ratios(config);
  std::string reason;
  if (uses_3d_model(config) && companions.size() < kErrorBarRatios3d.size()) {
    const HexResolution r = hex_resolution(with_resolved_3d_mesh(config));
    reason = fmt::format(
        "{} of the 3-D companions left out: fewer than {:g} elements across the contact radius "
        "(a/h = {:.3g} at the run's mesh)",
        kErrorBarRatios3d.size() - companions.size(), kMinCompanionContactElements,
        r.contact_radius / r.h_contact);
  }
  std::vector<EstimateRun> runs(1 + companions.size());
  for (std::size_t k = 0; k < companions.size(); ++k) runs[k + 1].ratio = companions[k];
  // The run itself on this thread (its control's callbacks stay on the caller's thread), the
  // companions from `next` on whichever thread is free.
  std::atomic<std::size_t> next{1};
  const auto run_next = [&]() -> bool {
    const std::size_t k = next++;
    if (k >= runs.size()) return false;
    if (control.cancel != nullptr && control.cancel->load()) {
      runs[k].result.status = RunStatus::kCancelled;  // not started
    } else {
      run_estimate_run(config, control, quiet, k, runs[k]);
    }
    return true;
  };
  std::optional<std::thread> helper;
  // A spare thread helps while more companions wait than this thread is about to take (`keep`).
  const auto borrow = [&](std::size_t keep) {
    if (helper || next.load() + keep >= runs.size() || !take_spare(control.spare_threads)) return;
    try {
      helper.emplace([&run_next] {
        while (run_next()) {
        }
      });
    } catch (const std::system_error&) {
      ++*control.spare_threads;  // no thread to be had: this one runs them all
    }
  };
  borrow(0);
  run_estimate_run(config, control, quiet, 0, runs.front());
  do {
    borrow(1);
  } while (run_next());
  if (helper) {
    helper->join();
    ++*control.spare_threads;
  }
  for (const EstimateRun& run : runs) {
    if (run.error) std::rethrow_exception(run.error);
  }
  return combine_estimate(runs, reason, error_bar_estimator(config));
}

}  // namespace corlab::fem
