// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file golden_section.hpp
/// The one golden-section minimiser of corlab (the DEM calibration's force-law exponent, the
/// error bar's free convergence order).

#include <functional>

namespace corlab {

/// Minimiser of f on [lo, hi] by golden-section search (robust for a unimodal f: each step keeps
/// one of the two interior points and evaluates one new) to |x| tolerance
/// rel_tol |x| + 1e-12 (hi - lo), at most 500 iterations. Units are the caller's.
double golden_section_minimum(const std::function<double(double)>& f,
                              double lo,
                              double hi,
                              double rel_tol = 1e-7);

}  // namespace corlab
