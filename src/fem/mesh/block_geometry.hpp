// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file block_geometry.hpp
/// 2D geometry of the generated mesh's structured blocks in the (r, z) section [m]: points, curves
/// evaluated by arc length (Hermite curves for the sphere's core), points on arcs and lines, and
/// transfinite (Coons) interpolation of a block from its four edges. Private to the mesh generator
/// (src/fem/mesh).

#include <cmath>
#include <numbers>
#include <vector>

namespace corlab::fem::meshing {

inline constexpr double kPi = std::numbers::pi;

/// A point of the (r, z) section [m], or a direction.
struct Point {
  double r = 0.0;
  double z = 0.0;
};

inline Point operator+(Point a, Point b) { return {a.r + b.r, a.z + b.z}; }
inline Point operator-(Point a, Point b) { return {a.r - b.r, a.z - b.z}; }
inline Point operator*(double s, Point a) { return {s * a.r, s * a.z}; }
inline double norm(Point a) { return std::hypot(a.r, a.z); }

/// A curve as a dense polyline, evaluated by arc length.
class Curve {
 public:
  explicit Curve(std::vector<Point> pts);
  double length() const { return s_.back(); }
  Point at(double s) const;
  /// Points at the given arc-length positions, endpoints exact.
  std::vector<Point> sample(const std::vector<double>& x) const;

 private:
  std::vector<Point> pts_;
  std::vector<double> s_;
};

/// Cubic Hermite curve from p0 (unit tangent t0) to p1 (unit tangent t1), tangents scaled by the
/// chord length.
Curve hermite(Point p0, Point t0, Point p1, Point t1);

/// Points on a circle (centre (0, zc), radius R) at angles phi measured from the downward
/// direction: (R sin phi, zc - R cos phi).
Point polar(double zc, double radius, double phi);

/// Structured block by discrete transfinite interpolation between four edge point lists:
/// south (j = 0) and north (j = nj) indexed by i, west (i = 0) and east (i = ni) by j; corner
/// points must agree. Returns (ni+1) x (nj+1) points, index i * (nj + 1) + j.
std::vector<Point> coons(const std::vector<Point>& south,
                         const std::vector<Point>& north,
                         const std::vector<Point>& west,
                         const std::vector<Point>& east);

/// Points on the sphere's arc from angle phi0 to phi1 at arc-length positions s (s.front() = 0,
/// s.back() = the arc length); the end points are exactly polar(phi0) and polar(phi1), so that
/// blocks sharing a corner share its node.
std::vector<Point> arc_points(
    double zc, double radius, double phi0, double phi1, const std::vector<double>& s);

/// Points on the segment a -> b at fractions f (0..1) of its length, end points exact.
std::vector<Point> line_points(Point a, Point b, const std::vector<double>& f);

}  // namespace corlab::fem::meshing
