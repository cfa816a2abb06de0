// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file numerics.hpp
/// Small numerical kernels for the energy-integral CoR models and their tests: composite
/// Gauss-Legendre quadrature, adaptive Simpson quadrature and a bracketing root finder.
/// Header-only templates; no allocation.

#include <array>
#include <cmath>
#include <utility>

namespace corlab::restitution::detail {

/// 8-point Gauss-Legendre nodes (positive half) and weights on [-1, 1].
inline constexpr std::array<double, 4> kGaussNodes = {0.1834346424956498, 0.5255324099163290,
                                                      0.7966664774136267, 0.9602898564975363};
inline constexpr std::array<double, 4> kGaussWeights = {0.3626837833783620, 0.3137066458778873,
                                                        0.2223810344533745, 0.1012285362903763};

/// 8-point Gauss-Legendre rule on [a, b].
template <class F>
double gauss_legendre8(const F& f, double a, double b) {
  const double mid = 0.5 * (a + b);
  const double half = 0.5 * (b - a);
  double sum = 0.0;
  for (std::size_t i = 0; i < kGaussNodes.size(); ++i) {
    const double dx = half * kGaussNodes[i];
    sum += kGaussWeights[i] * (f(mid - dx) + f(mid + dx));
  }
  return sum * half;
}

/// Composite 8-point Gauss-Legendre on [a, b] with `panels` panels whose widths grow
/// geometrically (panel edges a * (b/a)^(k/panels)); requires 0 < a < b. Suited to integrands
/// that vary on a logarithmic scale.
template <class F>
double gauss_legendre_graded(const F& f, double a, double b, int panels) {
  const double ratio = std::pow(b / a, 1.0 / panels);
  double lo = a;
  double sum = 0.0;
  for (int k = 1; k <= panels; ++k) {
    const double hi = (k == panels) ? b : lo * ratio;
    sum += gauss_legendre8(f, lo, hi);
    lo = hi;
  }
  return sum;
}

namespace internal {
template <class F>
double simpson_step(const F& f,
                    double a,
                    double b,
                    double fa,
                    double fm,
                    double fb,
                    double whole,
                    double tol,
                    int depth) {
  const double m = 0.5 * (a + b);
  const double lm = 0.5 * (a + m);
  const double rm = 0.5 * (m + b);
  const double flm = f(lm);
  const double frm = f(rm);
  const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
  const double right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
  const double delta = left + right - whole;
  if (depth <= 0 || std::abs(delta) <= 15.0 * tol) return left + right + delta / 15.0;
  return simpson_step(f, a, m, fa, flm, fm, left, 0.5 * tol, depth - 1) +
         simpson_step(f, m, b, fm, frm, fb, right, 0.5 * tol, depth - 1);
}
}  // namespace internal

/// Adaptive Simpson quadrature of f on [a, b] to absolute tolerance `tol` (Richardson-corrected,
/// recursion depth at most `max_depth`).
template <class F>
double adaptive_simpson(const F& f, double a, double b, double tol, int max_depth = 30) {
  const double fa = f(a);
  const double fb = f(b);
  const double fm = f(0.5 * (a + b));
  const double whole = (b - a) / 6.0 * (fa + 4.0 * fm + fb);
  return internal::simpson_step(f, a, b, fa, fm, fb, whole, tol, max_depth);
}

/// Root of a continuous f on [lo, hi] with f(lo) and f(hi) of opposite sign (or zero), by
/// bisection to the last representable bit (or `max_iter` steps). Returns the midpoint of the
/// final bracket.
template <class F>
double bisect_root(const F& f, double lo, double hi, int max_iter = 200) {
  double flo = f(lo);
  for (int i = 0; i < max_iter; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    const double fmid = f(mid);
    if (fmid == 0.0) return mid;
    if ((fmid < 0.0) == (flo < 0.0)) {
      lo = mid;
      flo = fmid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace corlab::restitution::detail
