// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file error_bar.hpp
/// Error bars of a run's restitution coefficient from the same case on systematically coarser
/// meshes (docs/theory/error_bars.md): pure functions of the values e_i [-] and the meshes'
/// size ratios h_i / h_1 [-] (h_1 = 1, the run's own mesh, first). The estimators:
///   - scatter (corlab's, the default): e(h) is taken as the converged value plus a scatter
///     whose standard deviation grows in proportion to h (the mesh's layout around the contact
///     changes with h: e does not converge monotonically); sigma^2 = mean over the coarser grids
///     of (e_i - e_1)^2 / (1 + h_i^2), and U = 2.5 sigma sqrt(1 + 1/4), the spread expected of
///     e(h/2) - e(h). The factor 2.5 was calibrated for >= 95 % coverage on one seeded sample
///     and checked on another (docs/theory/error_bars.md), with the coarser grids at sqrt 2, 2
///     and 2 sqrt 2 (the axisymmetric model's companions); the 3-D model's e_t and omega take it
///     too, on their companions.
///   - scatter_coarse: the same with the factor 2.0, calibrated the same way with the coarser
///     grids at 2, 2 sqrt 2, 4 and 4 sqrt 2 (sigma from four values): issue 43's candidate for
///     companions at 0.4 of the cost, not used by the solver (its median bar was 3.96 x the
///     median change on the CI corners, where issue 28's criterion allows 3 x).
///   - scatter_3d_e_n: the scatter estimator with the factor 1.5: the 3-D model's e_n, which
///     converges systematically, so that the companions' spread over-states its next change
///     (docs/theory/error_bars.md, "The 3-D model").
///   - scatter_3d: issue 39's candidate for the 3-D model's e_t and omega, not used by the
///     solver. The same sigma; U = F sigma sqrt(1 + 1/2), the spread of e(h / sqrt 2) - e_1 (the
///     3-D bar's reference), with F the scatter model's own 95 % point for the grids given
///     (scatter_model_factor: 2.78 for sqrt 2, 2^(3/4) and 2 h), not a factor calibrated on a
///     sample. On three seeded samples of 24 it held e_t in 71 of 72 cases (scatter: 67) and omega
///     in 70 (70), at 2.2-5.0 and 2.6-4.6 times the median change (scatter: 1.8-4.0, 2.2-3.3).
///   - two_grid: the two-grid GCI with p = 2 and Fs = 3 (Roache 1998): U = |e_1 - e_2h|.
///   - least_squares: after Eca & Hoekstra 2014 (J. Comput. Phys. 262:104-130), built for
///     scattered convergence: least-squares fits e_i = e_0 + alpha h_i^p (observed p), else with
///     p = 1, p = 2 or both, a data-range parameter Delta = (max e_i - min e_i) / (n - 1), and
///     U = Fs |e_1 - e_0| + sigma + |e_1 - fit_1| (Fs = 1.25 for a good fit with 0.5 <= p < 2.1,
///     3 otherwise), or 3 sigma / Delta times that sum where the fit's standard deviation sigma
///     exceeds the data range.
/// Every function returns NaN where a value of e is not finite or the grids are too few.

#include <span>
#include <string_view>
#include <vector>

namespace corlab::fem {

/// One least-squares fit e(h) = e_0 + a_1 h^p1 (+ a_2 h^p2) over the grids.
struct ConvergenceFit {
  double e0 = 0.0;     ///< the fit's value at h = 0 [-]
  double order = 0.0;  ///< p (of the first term) [-]
  double sigma = 0.0;  ///< standard deviation of the fit's residuals [-]
  double fit_1 = 0.0;  ///< the fit's value at h_1 = 1 [-]
  bool valid = false;  ///< enough grids and a solvable system
};

/// Fit with the order free (searched in (0, 8]); `weights` one per grid (sum 1).
ConvergenceFit fit_free_order(std::span<const double> e,
                              std::span<const double> h,
                              std::span<const double> weights);

/// Fit with the given orders (one or two terms).
ConvergenceFit fit_fixed_orders(std::span<const double> e,
                                std::span<const double> h,
                                std::span<const double> weights,
                                std::span<const double> orders);

/// The factor F [-] for which |e(reference h) - e_1| <= F sigma_hat sqrt(1 + reference^2) holds
/// with probability `coverage` [-] when e(h_i) = e* + sigma h_i z_i exactly (z_i independent
/// standard normal; sigma_hat the scatter estimator's, from the grids h, h[0] = 1): the
/// `coverage` quantile of 2^18 draws from a fixed seed, so a function of its arguments (within
/// about 0.3 % of the exact quantile). NaN with fewer than two grids; InputError for a reference
/// that is not > 0 or a coverage outside (0, 1).
double scatter_model_factor(std::span<const double> h, double reference, double coverage);

/// The width [-] of the bar F sigma_hat sqrt(1 + reference^2) (F = scatter_model_factor) under
/// the same model: the median bar over the median |e(reference h) - e_1|, over the same draws.
/// 3.6 on the 3-D model's companions (sqrt 2, 2^(3/4) and 2 h, reference 1/sqrt 2): where a
/// quantity's next change is scatter of this kind, a bar holding 95 % is that much wider than the
/// change (docs/theory/error_bars.md, "The 3-D model"). NaN and InputError as
/// scatter_model_factor.
double scatter_model_width(std::span<const double> h, double reference, double coverage);

/// The estimators by name, the default first: "scatter", "scatter_coarse", "two_grid",
/// "least_squares", "scatter_3d_e_n", "scatter_3d".
const std::vector<std::string_view>& error_bar_estimators();

/// The error bar U of e_1 [-]: e_1 +/- U. `e` and `h` as in the file comment (h[0] = 1); `name`
/// one of error_bar_estimators(); InputError for another name, unequal lengths, h[0] != 1 or a
/// ratio that is not finite and > 0 (NaN, as the file comment says, only for a value of e).
double error_bar(std::string_view name, std::span<const double> e, std::span<const double> h);

}  // namespace corlab::fem
