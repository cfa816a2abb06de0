// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file discretisation_error.hpp
/// Discretisation-error estimate of a run's restitution coefficient from companion runs on
/// meshes coarser everywhere by sqrt 2, 2 and 2 sqrt 2 (the 3-D model: sqrt 2, 2^(3/4) and 2,
/// those that keep the contact resolved; error_bar_ratios): h_min and h_max x r and the grading
/// ratio to the power r (r graded layers of ratio g merged into one of ratio g^r), so that each
/// companion is the run's mesh coarsened systematically, the graded far field included. The
/// error bar is e +/- e_error with e_error from the scatter estimator (error_bar.hpp,
/// docs/theory/error_bars.md): e does not converge monotonically with h (paper case at 5 m/s:
/// e = 0.5549, 0.5367, 0.5421, 0.5349, 0.5398 at h = 1, 0.5, 0.35, 0.25, 0.18 mm), which the
/// two-grid GCI this replaced did not cover (37 of a seeded sample of 48 cases held e(h/2)
/// within it, against 46 for this one). The companions add 55-76 % to a run
/// (docs/dev/performance.md). The 3-D model's e (= e_n) takes the scatter estimator with a smaller
/// factor (kErrorBar3dNormal), its e_t and omega the scatter estimator (kErrorBar3dTangential);
/// each 3-D bar bounds the change to the mesh sqrt 2 finer, not the distance to the converged
/// value.

#include <array>
#include <string_view>
#include <vector>

#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/solver/impact_result.hpp"
#include "corlab/fem/solver/simulate.hpp"

namespace corlab::fem {

/// The mesh ratio whose companion's e is reported as e_coarse [-].
inline constexpr double kErrorRefinementRatio = 2.0;
/// The companions' mesh ratios [-], cheapest last.
inline constexpr std::array<double, 3> kErrorBarRatios{1.4142135623730951, 2.0, 2.8284271247461903};
/// The 3-D model's companions' mesh ratios [-]: sqrt 2, 2^(3/4) and 2, cheapest last. Closer
/// to the run than the axisymmetric ones, so that at the default a/4 all three keep
/// kMinCompanionContactElements; 2^(3/4) costs about 1/8 of the run (elements ~ r^-3, steps ~
/// 1/r), and where 2h is beyond R / 20 it leaves two companions instead of one.
inline constexpr std::array<double, 3> kErrorBarRatios3d{1.4142135623730951, 1.681792830507429,
                                                         2.0};
/// The fewest elements across the predicted contact radius a 3-D companion keeps [-]: coarser,
/// the contact is outside the range where e converges (Ma et al.'s alumina on aluminium at 1 m/s,
/// a/4: e = 0.7811 at a/4, 0.7927 at a/2.83, 0.7907 at a/2, 0.8676 at a/1.41; the last made the
/// bar +/- 0.048 where the axisymmetric solver's converged e is 0.0020 away;
/// docs/theory/error_bars.md, "The 3-D model").
inline constexpr double kMinCompanionContactElements = 2.0;
/// The estimator simulate_with_error_estimate uses (error_bar_estimators()) for every bar of the
/// axisymmetric model.
inline constexpr std::string_view kDefaultErrorBar = "scatter";
/// The 3-D model's estimator of e_t and omega (only an oblique impact has them): the scatter
/// estimator. Its candidate "scatter_3d" (the scatter model's own 95 % bar on the change to
/// h / sqrt 2) held more of the finer values on three seeded samples (e_t 71 of 72 against 67) but
/// missed issue 39's width (3.9 and 4.4 times the median change on the validation sample), and
/// was not adopted (docs/theory/error_bars.md, "The 3-D model").
inline constexpr std::string_view kErrorBar3dTangential = "scatter";
/// The 3-D model's estimator of e (= e_n): the scatter estimator with a smaller factor, 1.5 (e_n
/// converges systematically; docs/theory/error_bars.md, "The 3-D model").
inline constexpr std::string_view kErrorBar3dNormal = "scatter_3d_e_n";

/// The estimator of e's bar for `config`: kErrorBar3dNormal for the 3-D model, else
/// kDefaultErrorBar.
std::string_view error_bar_estimator(const ImpactConfig& config);

/// The config meshed `ratio` times coarser (< 1: finer): mesh.h_min and mesh.h_max x ratio,
/// mesh.contact_elements / ratio, mesh.growth^ratio (at most MeshConfig::kMaxGrowth); the
/// geometry, the refined zone's extent and everything else unchanged. InputError for a mesh file.
ImpactConfig coarsened(const ImpactConfig& config, double ratio = kErrorRefinementRatio);

/// The companions' mesh ratios for `config` [-]: kErrorBarRatios; for the 3-D model those of
/// kErrorBarRatios3d whose mesh keeps at least kMinCompanionContactElements elements across the
/// predicted contact radius (none where the run's own mesh has fewer than 2 sqrt 2). InputError as
/// hex_resolution.
std::vector<double> error_bar_ratios(const ImpactConfig& config);

/// Runs `config` and its coarsened companions and returns the run's result with e_coarse (the
/// companion at 2h) and e_error set. A companion that is not a valid config (elements beyond
/// R / 20) or does not rebound cleanly is left out of the estimate, and so is a 3-D one with too
/// few elements across the contact (error_bar_ratios); e_error is NaN when the run
/// itself did not rebound, when no companion is left, or for a mesh.file (e_error_reason then
/// says why). A cancel stops them all. The companions run for e only (SimulationControl::e_only:
/// they end one short window after their last contact); while control.spare_threads is > 0 (a
/// sweep's tail) one of those threads runs them alongside the run, with the same results.
ImpactResult simulate_with_error_estimate(const ImpactConfig& config,
                                          const SimulationControl& control = {});

}  // namespace corlab::fem
