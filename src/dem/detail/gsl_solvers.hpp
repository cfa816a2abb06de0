// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file gsl_solvers.hpp
/// A thin wrapper of GSL's Brent root finder for std::function objectives.

#include <functional>

namespace corlab::dem::detail {

/// Root of f in [lo, hi] (f(lo), f(hi) of opposite signs) to |x error| <= abs_tol + rel_tol |x|.
/// Throws std::runtime_error if the bracket is invalid or 200 iterations do not converge.
double brent_root(const std::function<double(double)>& f,
                  double lo,
                  double hi,
                  double abs_tol = 0.0,
                  double rel_tol = 1e-14);

}  // namespace corlab::dem::detail
