// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file fe_curve.hpp
/// e(v) of a pair from the FE solver on demand (`corlab predict --model fe`, Python
/// `corlab.predict_curve`): one axisymmetric run with its discretisation error estimate
/// (discretisation_error.hpp) per speed, at the default mesh, the speeds run in parallel
/// (parallel_for, the costliest first) and each run answered from the result cache when it was
/// computed before (result_cache.hpp).
///
/// The geometry is the solver's default, the paper's: a sphere of R1 = 35 mm on a 70 mm x 70 mm
/// flat, or on a free second sphere of R2 = R1 / (R1/R2). e does not depend on the size: by
/// dimensional analysis it is a function of the dimensionless inputs only (impact_box.hpp,
/// tests/verification/dataset_invariance_test.cpp).

#include <atomic>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "corlab/fem/config/impact_config.hpp"
#include "corlab/materials/material.hpp"
#include "corlab/study/result_cache.hpp"

namespace corlab::study {

/// The two bodies of a curve.
struct FePair {
  Material sphere;     ///< body 1, elastic unless it has a yield stress
  Material substrate;  ///< body 2 (unused for a rigid flat)
  fem::SubstrateShape shape = fem::SubstrateShape::kFlat;
  double radius_ratio = 0.0;  ///< R1/R2 for shape kSphere, in (0, 1e3]; 0 otherwise [-]
};

/// The target named `shape`: "flat", "sphere" or "rigid"; empty: a sphere for a radius ratio
/// R1/R2 > 0, else a flat. A sphere needs R1/R2 > 0, the others 0: InputError naming
/// `ratio_field` (or `shape_field` for an unknown name) otherwise.
fem::SubstrateShape resolve_fe_shape(std::string_view shape,
                                     double radius_ratio,
                                     std::string_view shape_field = "shape",
                                     std::string_view ratio_field = "radius_ratio");

/// The run of one speed v [m/s]: ImpactConfig{} with the pair's materials and shape. A flat that
/// does not yield is a half-space: large enough that no elastic wave returns from its boundary
/// before the bodies part (its e is the elastic-wave loss; fe_curve.cpp, as_half_space), with
/// coarser far elements. Throws InputError for an invalid shape and radius ratio (validate() is
/// the caller's).
fem::ImpactConfig fe_curve_config(const FePair& pair, double velocity);

/// What a run is keyed by in the cache: its config (config_to_json, every key), the error
/// estimator and the SIMD level its hot loops run at [JSON].
nlohmann::json fe_run_key(const fem::ImpactConfig& config);

/// The answer at one speed.
struct FePoint {
  double velocity = 0.0;  ///< v [m/s]
  double e = 0.0;         ///< CoR [-]; NaN unless status is "separated"
  double e_error = 0.0;   ///< discretisation error bar of e [-]; NaN when there is none
  /// How the run ended (run_status.hpp names), or "invalid" for a speed the solver refuses.
  std::string status;
  std::string detail;   ///< why there is no e or no error bar (empty when both are there)
  bool cached = false;  ///< answered from the cache
  /// What answered: "fe", or a closed-form model's name (`--model auto`, auto_restitution.hpp).
  std::string answered_by = "fe";
  double wall_s = 0.0;  ///< the runs' wall time when computed [s]
};

struct FeCurveOptions {
  int jobs = 0;                               ///< speeds run at once (0: one per core)
  ResultCache* cache = nullptr;               ///< null: no cache
  std::FILE* progress = nullptr;              ///< progress line (study::ProgressBar); null: none
  const std::atomic<bool>* cancel = nullptr;  ///< set: no new run starts, running ones stop
};

/// e and its error bar at each of `velocities` [m/s], in their order. A pair the solver refuses
/// at every speed (a material key out of range) throws that InputError; a speed it refuses alone
/// (e.g. beyond the step budget) is a row with status "invalid" and the message. A cancelled run
/// is a row with status "cancelled" (not cached).
std::vector<FePoint> fe_curve(const FePair& pair,
                              const std::vector<double>& velocities,
                              const FeCurveOptions& options);

/// Speeds computed first by fe_curve_refined, log-spaced over the asked range [-].
inline constexpr std::size_t kRefinementStart = 5;
/// Most speeds fe_curve_refined computes [-].
inline constexpr std::size_t kRefinementMax = 33;

/// e(v) at `velocities` [m/s] from FE runs at fewer speeds: kRefinementStart log-spaced over
/// their range, then the midpoints (ln v) of the intervals whose interpolation error
/// (fe_interpolation.hpp) exceeds `tolerance` [-], until none does or kRefinementMax speeds ran.
/// A speed that was computed is its FE point; another is the interpolant's (answered_by
/// "fe-interpolated", status "interpolated", e_error the interpolated FE error bars plus the
/// interpolation error; detail says when the tolerance was not reached there). InputError for a
/// tolerance that is not a finite number > 0.
std::vector<FePoint> fe_curve_refined(const FePair& pair,
                                      const std::vector<double>& velocities,
                                      double tolerance,
                                      const FeCurveOptions& options);

}  // namespace corlab::study
