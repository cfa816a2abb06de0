// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file gsl_solvers.hpp
/// Thin wrappers of GSL's Brent root finder and Brent minimiser for std::function objectives.

#include <functional>

namespace corlab::dem::detail {

/// Root of f in [lo, hi] (f(lo), f(hi) of opposite signs) to |x error| <= abs_tol + rel_tol |x|.
/// Throws std::runtime_error if the bracket is invalid or 200 iterations do not converge.
double brent_root(const std::function<double(double)>& f,
                  double lo,
                  double hi,
                  double abs_tol = 0.0,
                  double rel_tol = 1e-14);

/// Minimiser of f on [lo, hi] by golden-section search (robust for unimodal f) to |x| tolerance
/// rel_tol |x| + 1e-12 (hi - lo), at most 500 iterations.
double golden_minimum(const std::function<double(double)>& f,
                      double lo,
                      double hi,
                      double rel_tol = 1e-7);

}  // namespace corlab::dem::detail
