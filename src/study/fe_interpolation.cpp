// A monotone cubic in ln v between FE speeds (fe_interpolation.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/study/fe_interpolation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace corlab::study {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double bar(const CurveNode& n) { return std::isfinite(n.e_error) ? n.e_error : 0.0; }

// Fritsch-Carlson slopes de/d(ln v) at each node.
std::vector<double> monotone_slopes(std::span<const CurveNode> nodes) {
  const std::size_t n = nodes.size();
  std::vector<double> h(n - 1);
  std::vector<double> delta(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    h[i] = std::log(nodes[i + 1].velocity / nodes[i].velocity);
    delta[i] = (nodes[i + 1].e - nodes[i].e) / h[i];
  }
  std::vector<double> m(n);
  if (n == 2) {
    m[0] = m[1] = delta[0];
    return m;
  }
  // The ends: the three-point slope, kept to the data's shape (Moler 2004, "pchip").
  const auto end_slope = [](double h0, double h1, double d0, double d1) {
    const double s = ((2 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
    if (s * d0 <= 0.0) return 0.0;
    if (d0 * d1 < 0.0 && std::abs(s) > 3 * std::abs(d0)) return 3 * d0;
    return s;
  };
  m[0] = end_slope(h[0], h[1], delta[0], delta[1]);
  m[n - 1] = end_slope(h[n - 2], h[n - 3], delta[n - 2], delta[n - 3]);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    // Harmonic mean weighted by the intervals (Fritsch & Butland); 0 at a local extremum.
    if (delta[i - 1] * delta[i] <= 0.0) {
      m[i] = 0.0;
      continue;
    }
    const double w1 = 2 * h[i] + h[i - 1];
    const double w2 = h[i] + 2 * h[i - 1];
    m[i] = (w1 + w2) / (w1 / delta[i - 1] + w2 / delta[i]);
  }
  // Fritsch & Carlson's limit: alpha^2 + beta^2 <= 9 on each interval.
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (delta[i] == 0.0) {
      m[i] = m[i + 1] = 0.0;
      continue;
    }
    const double a = m[i] / delta[i];
    const double b = m[i + 1] / delta[i];
    const double r = a * a + b * b;
    if (r > 9.0) {
      const double t = 3.0 / std::sqrt(r);
      m[i] = t * a * delta[i];
      m[i + 1] = t * b * delta[i];
    }
  }
  return m;
}

}  // namespace

Interpolated interpolate_curve(std::span<const CurveNode> nodes, double velocity) {
  if (nodes.size() < 2 || !(velocity >= nodes.front().velocity) ||
      !(velocity <= nodes.back().velocity)) {
    return {kNaN, kNaN, kNaN};
  }
  const auto upper =
      std::upper_bound(nodes.begin(), nodes.end(), velocity,
                       [](double v, const CurveNode& node) { return v < node.velocity; });
  const std::size_t i = std::min<std::size_t>(
      static_cast<std::size_t>(std::max<std::ptrdiff_t>(upper - nodes.begin(), 1)) - 1,
      nodes.size() - 2);
  const CurveNode& a = nodes[i];
  const CurveNode& b = nodes[i + 1];
  const std::vector<double> m = monotone_slopes(nodes);
  const double h = std::log(b.velocity / a.velocity);
  const double t = std::log(velocity / a.velocity) / h;
  // Cubic Hermite basis on [0, 1].
  const double h00 = (1 + 2 * t) * (1 - t) * (1 - t);
  const double h10 = t * (1 - t) * (1 - t);
  const double h01 = t * t * (3 - 2 * t);
  const double h11 = t * t * (t - 1);
  const double cubic = h00 * a.e + h10 * h * m[i] + h01 * b.e + h11 * h * m[i + 1];
  const double linear = (1 - t) * a.e + t * b.e;
  // Two points tell nothing of the bend: up to half the step between them at the middle.
  // |e''| h^2 min(t, 1 - t), e'' [-] the larger second divided difference in ln v at the
  // interval's two nodes (at an end node: its neighbour's): four times the straight line's error
  // |e''| h^2 t (1 - t) / 2 at the middle, and rising linearly from a node, as the cubic's error
  // does where its slope there is off by up to |e''| h.
  const auto second_difference = [&nodes](std::size_t k) {
    k = std::clamp<std::size_t>(k, 1, nodes.size() - 2);
    const double h0 = std::log(nodes[k].velocity / nodes[k - 1].velocity);
    const double h1 = std::log(nodes[k + 1].velocity / nodes[k].velocity);
    const double d0 = (nodes[k].e - nodes[k - 1].e) / h0;
    const double d1 = (nodes[k + 1].e - nodes[k].e) / h1;
    return std::abs(2 * (d1 - d0) / (h0 + h1));
  };
  const double interpolation =
      nodes.size() == 2 ? 2 * std::min(t, 1 - t) * std::abs(b.e - a.e)
                        : std::max(std::abs(cubic - linear),
                                   std::max(second_difference(i), second_difference(i + 1)) * h *
                                       h * std::min(t, 1 - t));
  return {cubic, (1 - t) * bar(a) + t * bar(b) + interpolation, interpolation};
}

std::vector<double> refinement_speeds(std::span<const CurveNode> nodes,
                                      double tolerance,
                                      std::size_t budget) {
  std::vector<std::pair<double, double>> worst;  // (interpolation error, midpoint speed)
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
    const double mid = std::sqrt(nodes[i].velocity * nodes[i + 1].velocity);
    const double err = interpolate_curve(nodes, mid).interpolation;
    if (err > tolerance) worst.emplace_back(err, mid);
  }
  std::sort(worst.begin(), worst.end(), std::greater<>());
  if (worst.size() > budget) worst.resize(budget);
  std::vector<double> speeds;
  speeds.reserve(worst.size());
  for (const auto& [err, v] : worst) speeds.push_back(v);
  std::sort(speeds.begin(), speeds.end());
  return speeds;
}

}  // namespace corlab::study
