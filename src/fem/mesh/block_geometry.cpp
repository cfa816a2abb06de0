// 2D block geometry: curves by arc length, Hermite curves, arcs, lines and Coons blocks.
// SPDX-License-Identifier: BSD-3-Clause
#include "fem/mesh/block_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace corlab::fem::meshing {
namespace {

constexpr int kCurveSamples = 4000;

}  // namespace

Curve::Curve(std::vector<Point> pts) : pts_(std::move(pts)), s_(pts_.size(), 0.0) {
  for (std::size_t i = 1; i < pts_.size(); ++i) s_[i] = s_[i - 1] + norm(pts_[i] - pts_[i - 1]);
}

Point Curve::at(double s) const {
  if (s <= 0.0) return pts_.front();
  if (s >= s_.back()) return pts_.back();
  const auto it = std::upper_bound(s_.begin(), s_.end(), s);
  const std::size_t i = static_cast<std::size_t>(it - s_.begin());
  const double t = (s - s_[i - 1]) / (s_[i] - s_[i - 1]);
  return (1.0 - t) * pts_[i - 1] + t * pts_[i];
}

std::vector<Point> Curve::sample(const std::vector<double>& x) const {
  std::vector<Point> out(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) out[i] = at(x[i]);
  out.front() = pts_.front();
  out.back() = pts_.back();
  return out;
}

Curve hermite(Point p0, Point t0, Point p1, Point t1) {
  const double c = norm(p1 - p0);
  std::vector<Point> pts(kCurveSamples + 1);
  for (int k = 0; k <= kCurveSamples; ++k) {
    const double t = static_cast<double>(k) / kCurveSamples;
    const double h00 = 2 * t * t * t - 3 * t * t + 1;
    const double h10 = t * t * t - 2 * t * t + t;
    const double h01 = -2 * t * t * t + 3 * t * t;
    const double h11 = t * t * t - t * t;
    pts[static_cast<std::size_t>(k)] = h00 * p0 + (h10 * c) * t0 + h01 * p1 + (h11 * c) * t1;
  }
  pts.front() = p0;
  pts.back() = p1;
  return Curve(std::move(pts));
}

Point polar(double zc, double radius, double phi) {
  if (phi == 0.0) return {0.0, zc - radius};
  if (phi >= kPi) return {0.0, zc + radius};
  return {radius * std::sin(phi), zc - radius * std::cos(phi)};
}

std::vector<Point> coons(const std::vector<Point>& south,
                         const std::vector<Point>& north,
                         const std::vector<Point>& west,
                         const std::vector<Point>& east) {
  const std::size_t ni = south.size() - 1;
  const std::size_t nj = west.size() - 1;
  auto arc_fractions = [](const std::vector<Point>& e) {
    std::vector<double> f(e.size(), 0.0);
    for (std::size_t k = 1; k < e.size(); ++k) f[k] = f[k - 1] + norm(e[k] - e[k - 1]);
    for (double& v : f) v /= f.back();
    return f;
  };
  const auto fs = arc_fractions(south);
  const auto fn = arc_fractions(north);
  const auto fw = arc_fractions(west);
  const auto fe = arc_fractions(east);
  const Point p00 = south.front();
  const Point p10 = south.back();
  const Point p01 = north.front();
  const Point p11 = north.back();
  std::vector<Point> x((ni + 1) * (nj + 1));
  for (std::size_t i = 0; i <= ni; ++i) {
    for (std::size_t j = 0; j <= nj; ++j) {
      Point p;
      if (j == 0) {
        p = south[i];
      } else if (j == nj) {
        p = north[i];
      } else if (i == 0) {
        p = west[j];
      } else if (i == ni) {
        p = east[j];
      } else {
        const double du = fn[i] - fs[i];
        const double dv = fe[j] - fw[j];
        const double u = (fs[i] + fw[j] * du) / (1.0 - du * dv);
        const double v = fw[j] + u * dv;
        p = (1.0 - v) * south[i] + v * north[i] + (1.0 - u) * west[j] + u * east[j] -
            ((1.0 - u) * (1.0 - v) * p00 + u * (1.0 - v) * p10 + (1.0 - u) * v * p01 + u * v * p11);
      }
      x[i * (nj + 1) + j] = p;
    }
  }
  return x;
}

std::vector<Point> arc_points(
    double zc, double radius, double phi0, double phi1, const std::vector<double>& s) {
  std::vector<Point> out(s.size());
  for (std::size_t k = 0; k < s.size(); ++k)
    out[k] = polar(zc, radius, phi0 + (phi1 - phi0) * s[k] / s.back());
  out.front() = polar(zc, radius, phi0);
  out.back() = polar(zc, radius, phi1);
  return out;
}

std::vector<Point> line_points(Point a, Point b, const std::vector<double>& f) {
  std::vector<Point> out(f.size());
  for (std::size_t k = 0; k < f.size(); ++k) out[k] = (1.0 - f[k]) * a + f[k] * b;
  out.front() = a;
  out.back() = b;
  return out;
}

}  // namespace corlab::fem::meshing
