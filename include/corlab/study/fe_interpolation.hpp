// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file fe_interpolation.hpp
/// e(v) between FE speeds (`corlab predict --model fe --tolerance`): a monotone cubic through the
/// computed points in ln v (Fritsch & Carlson 1980, SIAM J. Numer. Anal. 17(2):238-246: each
/// interval's slopes limited so that the cubic never overshoots its data), with an uncertainty
/// that is the FE error bars interpolated linearly plus an interpolation error
/// |e''| h^2 min(t, 1 - t) (h the interval in ln v, t the position in it, e'' the larger second
/// divided difference at its two nodes), or |cubic - linear| where larger: four times the
/// straight line's error at the middle, rising linearly from each node as the cubic's error does
/// where its slope is off. It is zero at a computed speed and largest between two, grows with the
/// curve's bend and the gap, and covers the cubic's error on the smooth test curves of
/// tests/unit/study/fe_interpolation_test.cpp (an estimate, not a proven bound).
/// The end slopes are Moler's three-point ones ("pchip", Numerical Computing with MATLAB, 2004,
/// section 3.4); between only two points the interpolation error is taken as up to half their
/// difference (two points say nothing of the bend).

#include <span>
#include <vector>

namespace corlab::study {

/// One computed speed: v [m/s], e [-] and its error bar [-] (NaN: none, counted as 0).
struct CurveNode {
  double velocity = 0.0;
  double e = 0.0;
  double e_error = 0.0;
};

/// e and its uncertainty at one speed [-].
struct Interpolated {
  double e = 0.0;
  double e_error = 0.0;        ///< the nodes' error bars and the interpolation's, summed
  double interpolation = 0.0;  ///< the interpolation's part, |cubic - linear|
};

/// The interpolant through `nodes` (increasing velocity > 0, finite e; at least 2) at `velocity`
/// [m/s]; NaN e and e_error outside [first, last] (no extrapolation).
Interpolated interpolate_curve(std::span<const CurveNode> nodes, double velocity);

/// The speeds to compute next so that the interpolation's part stays within `tolerance` [-]: the
/// midpoint in ln v of every interval whose midpoint exceeds it, at most `budget` of them, the
/// worst first (returned in increasing order).
std::vector<double> refinement_speeds(std::span<const CurveNode> nodes,
                                      double tolerance,
                                      std::size_t budget);

}  // namespace corlab::study
