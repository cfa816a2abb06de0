// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file relative_error.hpp
/// Relative errors of model values against reference values and their statistics (n, RMS, worst,
/// bias): the one implementation behind the fits' goodness of fit, the reproduction's errors of
/// eq. 19 (fit.json), and, through Python (corlab.relative_error_stats), the FE dataset's model
/// scores (model_scores.json) and corlab2026's held-out scores (model_fit.json).

#include <cstddef>
#include <limits>
#include <span>
#include <vector>

namespace corlab::study {

/// Statistics of relative errors r [-]. With n = 0, every statistic is NaN.
struct RelativeErrorStats {
  std::size_t n = 0;                                        ///< finite relative errors counted
  double rms = std::numeric_limits<double>::quiet_NaN();    ///< sqrt(mean r^2) [-]
  double worst = std::numeric_limits<double>::quiet_NaN();  ///< r of the largest |r|, signed [-]
  double bias = std::numeric_limits<double>::quiet_NaN();   ///< mean r [-]
  /// Index of `worst` in the input (the first of equal magnitudes); 0 when n = 0.
  std::size_t worst_index = 0;
};

/// r_i = (model_i - reference_i) / reference_i [-] (not finite where reference_i is 0 or either
/// value is not finite). Throws InputError when the sizes differ.
std::vector<double> relative_errors(std::span<const double> model,
                                    std::span<const double> reference);

/// Statistics of relative errors; the ones that are not finite are left out. The sums run in
/// numpy's pairwise order (numpy.mean), so the scores computed by numpy before stay the same.
RelativeErrorStats relative_error_stats(std::span<const double> relative_errors);

/// Statistics of the relative errors of `model` against `reference` (pairs whose relative error
/// is not finite left out; worst_index indexes the pairs). Throws InputError when the sizes
/// differ.
RelativeErrorStats relative_error_stats(std::span<const double> model,
                                        std::span<const double> reference);

}  // namespace corlab::study
