#pragma once
/// @file discretisation_error.hpp
/// Discretisation-error estimate of a run's restitution coefficient from a second run on a mesh
/// twice as coarse everywhere: h_min, h_max x 2 and the grading ratio squared (two graded layers
/// of ratio g merged into one of ratio g^2), so that the companion is the run's mesh coarsened
/// systematically, as the GCI assumes, and its estimate includes the error of the graded far
/// field (coarsening only the contact zone left that out: mesh.md, "Grading ratio outside the
/// zone"). The companion adds 11-12 % to the run's time (4x fewer elements, 2x longer steps;
/// the zone-only companion added 12-30 %; docs/dev/performance.md).
/// Two-grid Grid Convergence Index (Roache 1998, Verification and Validation in Computational
/// Science and Engineering, ch. 5):
///   GCI = Fs |e_h - e_2h| / (2^p - 1),  Fs = 3 (two grids), p = 2 (formal order)  =>  |e_h -
///   e_2h|.
/// The error bar is e_h +/- GCI, not an extrapolation: penalty contact and the moving elastic-
/// plastic front make the convergence of e non-monotone (paper case at 5 m/s: e = 0.5549,
/// 0.5367, 0.5421, 0.5349, 0.5363 at h = 1, 0.5, 0.35, 0.25, 0.2 mm), so a Richardson-extrapolated
/// value would be less reliable than the fine-mesh value itself. Verified on that series: the
/// 0.25 mm run and its companion (e = 0.5384) give 0.5349 +/- 0.0035, which brackets the 0.2 mm
/// value (tests/verification/impact_paper_case_test.cpp, MeshConvergence).

#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/solver/impact_result.hpp"
#include "corlab/fem/solver/simulate.hpp"

namespace corlab::fem {

/// Refinement ratio between the run and its error-estimate companion [-].
inline constexpr double kErrorRefinementRatio = 2.0;
/// Safety factor Fs and assumed order p of the two-grid GCI [-].
inline constexpr double kGciSafetyFactor = 3.0;
inline constexpr double kGciOrder = 2.0;

/// The config meshed `ratio` times coarser: mesh.h_min and mesh.h_max x ratio,
/// mesh.contact_elements / ratio, mesh.growth^ratio (at most MeshConfig::kMaxGrowth); the
/// geometry, the refined zone's extent and everything else unchanged. InputError for a mesh file.
ImpactConfig coarsened(const ImpactConfig& config, double ratio = kErrorRefinementRatio);

/// Two-grid GCI of e [-] from the fine and coarse values (NaN if either is not finite).
double grid_convergence_index(double e_fine, double e_coarse, double ratio = kErrorRefinementRatio);

/// Runs `config` and its coarsened companion and returns the fine run's result with e_coarse
/// and e_error set (NaN when either run did not rebound cleanly, when the coarsened mesh is
/// not a valid config, e.g. elements beyond R / 20, or for a mesh.file; e_error_reason then says
/// which). A cancel stops both.
ImpactResult simulate_with_error_estimate(const ImpactConfig& config,
                                          const SimulationControl& control = {});

}  // namespace corlab::fem
