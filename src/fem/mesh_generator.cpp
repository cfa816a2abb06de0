#include "corlab/fem/mesh_generator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <utility>

#include "corlab/core/error.hpp"
#include "corlab/fem/contact_estimate.hpp"
#include "corlab/fem/gmsh_reader.hpp"
#include "corlab/fem/mesh_quality.hpp"

namespace corlab::fem {
namespace {

constexpr double kPi = std::numbers::pi;
/// Smallest spacing allowed on edges whose distribution is derived from another edge, as a
/// fraction of h (the smallest element sets the explicit time step; 0.95 keeps the ring
/// elements next to the axis, where the radial lines converge, at ~h wide).
constexpr double kMinSpacingFraction = 0.95;
/// The core's first spacing along the axis (A -> A') as a multiple of the ring's last radial
/// spacing, and the smallest spacing on the core's right edge (K -> K') as a multiple of the
/// minimum spacing. The core's columns lean by up to ~35 deg near its bottom edge (they fan out
/// from A -> K to the longer top edge A' -> K'); slightly taller rows there keep these sheared
/// elements' characteristic length (the stable step) at ~0.97 of the contact squares' instead
/// of 0.9 (measured: docs/theory/mesh.md).
constexpr double kCoreFirstSpacing = 1.25;
constexpr double kCoreRightSpacing = 1.1;
/// Bottom-block arc angle limits [rad] and corner angle of the ring blocks at the core corners.
constexpr double kMinBottomAngle = 10.0 * kPi / 180.0;
constexpr double kMaxBottomAngle = 60.0 * kPi / 180.0;
constexpr double kRingCornerAngle = 120.0 * kPi / 180.0;
/// Depth of the uniform-h layer under the sphere's lowest point as a fraction of zone_depth (the
/// substrate's: by default 0.5 a, where the elastic stresses peak, Johnson 1985, fig. 4.6).
constexpr double kSphereUniformDepthFraction = 1.0;
/// Ring thickness limits as fractions of R.
constexpr double kMinRingFraction = 0.12;
constexpr double kMaxRingFraction = 0.2;
constexpr double kTopRingFraction = 0.5;
/// Quality the three-block substrate must have, else the tensor grid is used: corner angles
/// >= 40 deg and widths >= 0.7 h (a square zone gives 45 deg and 0.72 h at the diagonal).
constexpr double kMinBlockAngle = 40.0 * kPi / 180.0;
constexpr double kMinBlockWidth = 0.7;
/// Subcycling levels and level margin of the cost model that picks the substrate layout (the
/// solver's defaults; see explicit_cost).
constexpr int kCostLevels = 4;
constexpr double kCostLevelMargin = 0.8;

struct Point {
  double r = 0.0;
  double z = 0.0;
};

Point operator+(Point a, Point b) { return {a.r + b.r, a.z + b.z}; }
Point operator-(Point a, Point b) { return {a.r - b.r, a.z - b.z}; }
Point operator*(double s, Point a) { return {s * a.r, s * a.z}; }
double norm(Point a) { return std::hypot(a.r, a.z); }

/// Sizes of a distribution from positions.
std::vector<double> spacings(const std::vector<double>& x) {
  std::vector<double> s(x.size() - 1);
  for (std::size_t i = 0; i + 1 < x.size(); ++i) s[i] = x[i + 1] - x[i];
  return s;
}

std::vector<double> positions_from_sizes(const std::vector<double>& sizes) {
  std::vector<double> x(sizes.size() + 1, 0.0);
  for (std::size_t i = 0; i < sizes.size(); ++i) x[i + 1] = x[i] + sizes[i];
  return x;
}

/// Rescales the sizes flagged `graded` so that the total is `length`; when none is graded, all.
void fit_length(std::vector<double>& sizes, const std::vector<bool>& graded, double length) {
  double fixed = 0.0;
  double free = 0.0;
  for (std::size_t i = 0; i < sizes.size(); ++i) (graded[i] ? free : fixed) += sizes[i];
  if (free <= 0.0 || fixed >= length) {
    const double f = length / (fixed + free);
    for (double& s : sizes) s *= f;
    return;
  }
  const double f = (length - fixed) / free;
  for (std::size_t i = 0; i < sizes.size(); ++i)
    if (graded[i]) sizes[i] *= f;
}

/// Grows sizes from `start` (uniform for `uniform_length`) by `growth` up to `cap`; appends to
/// `sizes` until their sum reaches `target`.
void grow_sizes(double start,
                double uniform_length,
                double growth,
                double cap,
                double target,
                std::vector<double>& sizes,
                std::vector<bool>& graded) {
  double x = 0.0;
  double s = start;
  while (x < target * (1.0 - 1e-12)) {
    const bool uniform = x + 0.5 * start < uniform_length;
    if (!uniform) s = std::max(start, std::min(s * growth, cap));
    sizes.push_back(uniform ? start : s);
    graded.push_back(!uniform);
    x += sizes.back();
  }
}

/// Picks between keeping the last (overshooting) size and dropping it, so that the rescaling of
/// the graded part is closest to 1, then rescales.
std::vector<double> close_distribution(std::vector<double> sizes,
                                       std::vector<bool> graded,
                                       double length) {
  auto factor = [&](std::size_t n) {
    double fixed = 0.0;
    double free = 0.0;
    for (std::size_t i = 0; i < n; ++i) (graded[i] ? free : fixed) += sizes[i];
    if (free <= 0.0 || fixed >= length) return length / (fixed + free);
    return (length - fixed) / free;
  };
  if (sizes.size() > 1) {
    const double keep = factor(sizes.size());
    const double drop = factor(sizes.size() - 1);
    if (std::abs(std::log(drop)) < std::abs(std::log(keep))) {
      sizes.pop_back();
      graded.pop_back();
    }
  }
  fit_length(sizes, graded, length);
  return sizes;
}

/// Two-sided graded sizes over `length`: starts at s0 (uniform over `uniform_length`), ends at
/// s1, grows by `growth` from both ends up to `cap`.
std::vector<double> two_sided_sizes(
    double length, double s0, double uniform_length, double s1, double growth, double cap) {
  std::vector<double> left;
  std::vector<double> right;
  std::vector<bool> left_graded;
  double x = 0.0;
  double a = s0;
  double b = s1;
  bool first_right = true;
  while (x < length * (1.0 - 1e-12)) {
    const bool uniform = x + 0.5 * s0 < uniform_length;
    if (uniform) {
      left.push_back(s0);
      left_graded.push_back(false);
      x += s0;
      continue;
    }
    // next candidates
    const double next_a = std::max(s0, std::min(a * growth, cap));
    const double next_b = first_right ? s1 : std::min(b * growth, cap);
    if (next_b <= next_a) {
      right.push_back(next_b);
      b = next_b;
      first_right = false;
      x += next_b;
    } else {
      left.push_back(next_a);
      left_graded.push_back(true);
      a = next_a;
      x += next_a;
    }
  }
  std::vector<double> sizes = left;
  std::vector<bool> graded = left_graded;
  for (auto it = right.rbegin(); it != right.rend(); ++it) {
    sizes.push_back(*it);
    graded.push_back(true);
  }
  // rescale the graded part (dropping one interval if that is closer)
  if (sizes.size() > 2) {
    double fixed = 0.0;
    double free = 0.0;
    for (std::size_t i = 0; i < sizes.size(); ++i) (graded[i] ? free : fixed) += sizes[i];
    // drop the largest graded interval when that makes the factor closer to one
    auto largest = std::max_element(sizes.begin(), sizes.end());
    const std::size_t k = static_cast<std::size_t>(largest - sizes.begin());
    if (graded[k] && free - sizes[k] > 0.0 && fixed < length) {
      const double keep = (length - fixed) / free;
      const double drop = (length - fixed) / (free - sizes[k]);
      if (std::abs(std::log(drop)) < std::abs(std::log(keep))) {
        sizes.erase(sizes.begin() + static_cast<std::ptrdiff_t>(k));
        graded.erase(graded.begin() + static_cast<std::ptrdiff_t>(k));
      }
    }
  }
  fit_length(sizes, graded, length);
  return sizes;
}

/// Normalised positions (0..1) of a distribution.
std::vector<double> fractions(const std::vector<double>& x) {
  std::vector<double> f(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) f[i] = x[i] / x.back();
  f.back() = 1.0;
  return f;
}

/// Positions on an edge of `length` with the same count as `f` (fractions): f scaled, blended
/// towards uniform just enough that no interval is below `min_size` (when possible).
std::vector<double> fit_fractions(const std::vector<double>& f, double length, double min_size) {
  const std::size_t n = f.size() - 1;
  auto blend = [&](double w) {
    std::vector<double> x(f.size());
    for (std::size_t i = 0; i <= n; ++i)
      x[i] = length * ((1.0 - w) * f[i] + w * static_cast<double>(i) / static_cast<double>(n));
    x.back() = length;
    return x;
  };
  auto smallest = [](const std::vector<double>& x) {
    double m = x[1] - x[0];
    for (std::size_t i = 1; i + 1 < x.size(); ++i) m = std::min(m, x[i + 1] - x[i]);
    return m;
  };
  std::vector<double> x = blend(0.0);
  if (smallest(x) >= min_size) return x;
  if (smallest(blend(1.0)) < min_size) return blend(1.0);
  double lo = 0.0;
  double hi = 1.0;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (smallest(blend(mid)) >= min_size ? hi : lo) = mid;
  }
  return blend(hi);
}

/// Splits the largest intervals in half until the distribution has `n` intervals.
std::vector<double> split_to_count(const std::vector<double>& x, std::size_t n) {
  std::vector<double> sizes = spacings(x);
  while (sizes.size() < n) {
    const auto it = std::max_element(sizes.begin(), sizes.end());
    const double half = 0.5 * *it;
    *it = half;
    sizes.insert(it, half);
  }
  return positions_from_sizes(sizes);
}

/// A curve as a dense polyline, evaluated by arc length.
class Curve {
 public:
  explicit Curve(std::vector<Point> pts) : pts_(std::move(pts)), s_(pts_.size(), 0.0) {
    for (std::size_t i = 1; i < pts_.size(); ++i) s_[i] = s_[i - 1] + norm(pts_[i] - pts_[i - 1]);
  }
  double length() const { return s_.back(); }
  Point at(double s) const {
    if (s <= 0.0) return pts_.front();
    if (s >= s_.back()) return pts_.back();
    const auto it = std::upper_bound(s_.begin(), s_.end(), s);
    const std::size_t i = static_cast<std::size_t>(it - s_.begin());
    const double t = (s - s_[i - 1]) / (s_[i] - s_[i - 1]);
    return (1.0 - t) * pts_[i - 1] + t * pts_[i];
  }
  /// Points at the given arc-length positions, endpoints exact.
  std::vector<Point> sample(const std::vector<double>& x) const {
    std::vector<Point> out(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) out[i] = at(x[i]);
    out.front() = pts_.front();
    out.back() = pts_.back();
    return out;
  }

 private:
  std::vector<Point> pts_;
  std::vector<double> s_;
};

constexpr int kCurveSamples = 4000;

/// Cubic Hermite curve from p0 (unit tangent t0) to p1 (unit tangent t1), tangents scaled by the
/// chord length.
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

/// Points on a circle (centre (0, zc), radius R) at angles phi measured from the downward
/// direction: (R sin phi, zc - R cos phi).
Point polar(double zc, double radius, double phi) {
  if (phi == 0.0) return {0.0, zc - radius};
  if (phi >= kPi) return {0.0, zc + radius};
  return {radius * std::sin(phi), zc - radius * std::cos(phi)};
}

/// Structured block by discrete transfinite interpolation between four edge point lists:
/// south (j = 0) and north (j = nj) indexed by i, west (i = 0) and east (i = ni) by j; corner
/// points must agree. Returns (ni+1) x (nj+1) points, index i * (nj + 1) + j.
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

/// Adds nodes and elements to a mesh, merging nodes at bitwise-equal coordinates within a body.
class MeshBuilder {
 public:
  explicit MeshBuilder(Mesh& mesh) : mesh_(mesh) {}
  void start_body(Body body) {
    body_ = body;
    index_.clear();
  }
  int node(Point p) {
    const auto [it, inserted] = index_.try_emplace({p.r, p.z}, mesh_.num_nodes());
    if (inserted) {
      mesh_.r.push_back(p.r);
      mesh_.z.push_back(p.z);
      mesh_.node_body.push_back(body_);
    }
    return it->second;
  }
  /// Adds a block of (ni+1) x (nj+1) points (index i * (nj+1) + j); returns its node ids.
  std::vector<int> block(const std::vector<Point>& pts, std::size_t ni, std::size_t nj) {
    std::vector<int> ids(pts.size());
    for (std::size_t k = 0; k < pts.size(); ++k) ids[k] = node(pts[k]);
    for (std::size_t i = 0; i < ni; ++i) {
      for (std::size_t j = 0; j < nj; ++j) {
        const std::array<int, 4> q{ids[i * (nj + 1) + j], ids[(i + 1) * (nj + 1) + j],
                                   ids[(i + 1) * (nj + 1) + j + 1], ids[i * (nj + 1) + j + 1]};
        mesh_.quads.push_back(counter_clockwise(mesh_, q));
        mesh_.element_body.push_back(body_);
      }
    }
    return ids;
  }

 private:
  Mesh& mesh_;
  Body body_ = Body::kSphere;
  std::map<std::pair<double, double>, int> index_;
};

/// Points on the sphere's arc from angle phi0 to phi1 at arc-length positions s (s.front() = 0,
/// s.back() = the arc length); the end points are exactly polar(phi0) and polar(phi1), so that
/// blocks sharing a corner share its node.
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

void generate_sphere(const MeshOptions& o, MeshBuilder& builder, Mesh& mesh) {
  const double radius = o.sphere_radius;
  const double zc = o.gap + radius;
  const double h = o.h_contact;
  const double g = o.growth;
  const double min_size = kMinSpacingFraction * h;

  // bottom ring block: arc P (phi = 0) -> Q (phi = alpha), depth d_ring
  const double alpha = std::clamp(o.zone_radius / radius, kMinBottomAngle, kMaxBottomAngle);
  const auto arc_b = graded_positions(radius * alpha, h, o.zone_radius, g, o.h_max);
  const std::size_t ns = arc_b.size() - 1;
  const double uniform_depth = kSphereUniformDepthFraction * o.zone_depth;
  // ring thickness: thin enough that the core's bottom edge (n_s intervals) stays long enough
  // for spacings >= kMinSpacingFraction h (the radial columns converge towards the centre)
  auto e_out = [](double phi) { return Point{std::sin(phi), -std::cos(phi)}; };
  auto e_tan = [](double phi) { return Point{std::cos(phi), std::sin(phi)}; };
  const double ca = std::cos(kRingCornerAngle);
  const double sa = std::sin(kRingCornerAngle);
  const Point k_to_a = ca * e_out(alpha) - sa * e_tan(alpha);
  auto bottom_curve = [&](double d) {
    return hermite(polar(zc, radius - d, 0.0), {1.0, 0.0}, polar(zc, radius - d, alpha),
                   -1.0 * k_to_a);
  };
  double d_ring = std::clamp(uniform_depth, kMinRingFraction * radius, kMaxRingFraction * radius);
  const double needed = 1.05 * kMinSpacingFraction * h * static_cast<double>(ns);
  while (d_ring > 4.0 * h && bottom_curve(d_ring).length() < needed) d_ring *= 0.9;
  const auto depth_b = graded_positions(d_ring, h, uniform_depth, g, o.h_max);
  const std::size_t nt = depth_b.size() - 1;
  const auto depth_f = fractions(depth_b);
  // top block arc: n_s intervals of roughly square elements (radial size d_top / n_t)
  const double d_top0 = std::max(d_ring, kTopRingFraction * radius);
  const double s_top_target = std::max(h, d_top0 / static_cast<double>(nt));
  const double gamma = std::clamp(static_cast<double>(ns) * s_top_target / radius, kPi / 4.0,
                                  kPi - alpha - kPi / 3.0);
  const double beta = kPi - gamma;
  // the core's top edge carries n_s intervals too: keep it long enough for spacings ~h
  const double rho_top_min =
      std::min(1.0 - kMinRingFraction, 1.2 * static_cast<double>(ns) * h / (gamma * radius)) *
      radius;
  const Point pnt_p = polar(zc, radius, 0.0);
  const Point pnt_q = polar(zc, radius, alpha);
  const Point pnt_q2 = polar(zc, radius, beta);
  const Point pnt_t = polar(zc, radius, kPi);
  const Point pnt_a = polar(zc, radius - d_ring, 0.0);
  const Point pnt_k = polar(zc, radius - d_ring, alpha);

  // core boundary curves with corner angles set at K and K': K -> A leaves K at the ring corner
  // angle from the outward radial towards smaller phi, K -> K' towards larger phi
  const Point k_to_k2 = ca * e_out(alpha) + sa * e_tan(alpha);
  const Point k2_to_k = ca * e_out(beta) - sa * e_tan(beta);
  const Point k2_to_a2 = ca * e_out(beta) + sa * e_tan(beta);
  const Curve gamma_bottom = bottom_curve(d_ring);

  // right block: arc Q -> Q' (i), radial (j): Q->K to Q'->K'
  const auto arc_b_sizes = spacings(arc_b);
  const double s_q = arc_b_sizes.back();
  const double s_top = radius * gamma / static_cast<double>(ns);
  const double right_uniform = std::max(0.0, o.zone_radius - radius * alpha);
  const auto depth_sizes = spacings(depth_b);

  // The top ring thickness d_top sets K' and A'. Thinner when the core's right edge K -> K' is
  // too short for its n_r intervals of >= min_size.
  struct CoreRight {
    Point k2;
    Point a2;
    Curve right;
    std::vector<double> arc_r;   // right block arc positions
    std::vector<double> axis_x;  // core axis positions
    std::size_t nr;
  };
  auto core_right = [&](double d_top) {
    const Point k2 = polar(zc, radius - d_top, beta);
    const Point a2 = polar(zc, radius - d_top, kPi);
    auto arc = positions_from_sizes(
        two_sided_sizes(radius * (beta - alpha), s_q, right_uniform, s_top, g, o.h_max));
    // core axis A -> A': continues the depth refinement below the ring, then grows
    const double s_top_radial = depth_sizes.back() * d_top / d_ring;
    auto axis = positions_from_sizes(
        two_sided_sizes(norm(a2 - pnt_a), kCoreFirstSpacing * depth_sizes.back(),
                        std::max(0.0, uniform_depth - d_ring), s_top_radial, g, o.h_max));
    const std::size_t n = std::max(arc.size(), axis.size()) - 1;
    return CoreRight{k2,
                     a2,
                     hermite(pnt_k, k_to_k2, k2, -1.0 * k2_to_k),
                     split_to_count(arc, n),
                     split_to_count(axis, n),
                     n};
  };
  double d_top = std::max(d_ring, std::min(d_top0, radius - rho_top_min));
  CoreRight core = core_right(d_top);
  while (d_top > d_ring && core.right.length() < 1.05 * min_size * static_cast<double>(core.nr)) {
    d_top = std::max(d_ring, 0.9 * d_top);
    core = core_right(d_top);
  }
  const Point pnt_k2 = core.k2;
  const Point pnt_a2 = core.a2;
  const Curve& gamma_right = core.right;
  const auto& arc_r = core.arc_r;
  const auto& axis_x = core.axis_x;
  const std::size_t nr = core.nr;
  const Curve gamma_top = hermite(pnt_a2, {1.0, 0.0}, pnt_k2, -1.0 * k2_to_a2);

  // bottom block edges
  const auto b_south = arc_points(zc, radius, 0.0, alpha, arc_b);  // P -> Q
  const auto b_north = gamma_bottom.sample(fit_fractions(fractions(arc_b), gamma_bottom.length(),
                                                         min_size));  // A -> K
  const auto b_west = line_points(pnt_p, pnt_a, depth_f);             // P -> A
  const auto b_east = line_points(pnt_q, pnt_k, depth_f);             // Q -> K

  const auto r_south = arc_points(zc, radius, alpha, beta, arc_r);  // Q -> Q'
  const auto r_north = gamma_right.sample(fit_fractions(fractions(arc_r), gamma_right.length(),
                                                        kCoreRightSpacing * min_size));  // K -> K'
  const auto r_west = b_east;                                                            // Q -> K
  const auto r_east = line_points(pnt_q2, pnt_k2, depth_f);                              // Q' -> K'

  // top block: arc T -> Q' (i, from the axis), radial T -> A' and Q' -> K'
  std::vector<double> arc_t(ns + 1);
  for (std::size_t k = 0; k <= ns; ++k)
    arc_t[k] = radius * gamma * static_cast<double>(k) / static_cast<double>(ns);
  std::vector<Point> t_south(ns + 1);
  for (std::size_t k = 0; k <= ns; ++k) t_south[k] = polar(zc, radius, kPi - arc_t[k] / radius);
  t_south.back() = pnt_q2;
  const auto t_north =
      gamma_top.sample(fit_fractions(fractions(arc_t), gamma_top.length(), min_size));  // A' -> K'
  const auto t_west = line_points(pnt_t, pnt_a2, depth_f);                              // T -> A'
  const auto t_east = r_east;                                                           // Q' -> K'

  // core: south A -> K (bottom), north A' -> K' (top), west A -> A' (axis), east K -> K'
  const auto c_west = line_points(pnt_a, pnt_a2, fractions(axis_x));

  builder.start_body(Body::kSphere);
  const auto ids_b = builder.block(coons(b_south, b_north, b_west, b_east), ns, nt);
  const auto ids_r = builder.block(coons(r_south, r_north, r_west, r_east), nr, nt);
  const auto ids_t = builder.block(coons(t_south, t_north, t_west, t_east), ns, nt);
  builder.block(coons(b_north, t_north, c_west, r_north), ns, nr);

  // surface nodes from the lowest point (bottom, right, then top block arcs), up to the first
  // node past the equator
  std::vector<int>& surf = mesh.sphere_surface_nodes;
  std::vector<std::pair<int, double>> arc_nodes;  // (node, polar angle)
  for (std::size_t i = 0; i <= ns; ++i)
    arc_nodes.emplace_back(ids_b[i * (nt + 1)], alpha * arc_b[i] / arc_b.back());
  for (std::size_t i = 1; i <= nr; ++i)
    arc_nodes.emplace_back(ids_r[i * (nt + 1)], alpha + (beta - alpha) * arc_r[i] / arc_r.back());
  for (std::size_t i = ns; i-- > 0;)
    arc_nodes.emplace_back(ids_t[i * (nt + 1)], kPi - arc_t[i] / radius);
  for (const auto& [node, phi] : arc_nodes) {
    surf.push_back(node);
    if (phi > 0.5 * kPi) break;
  }
}

/// Tensor-product substrate (used when the refined zone leaves no room for the graded blocks).
void generate_substrate_tensor(const MeshOptions& o, MeshBuilder& builder, Mesh& mesh) {
  const auto xr =
      graded_positions(o.substrate_radius, o.h_contact, o.zone_radius, o.growth, o.h_max);
  const auto xd = graded_positions(o.substrate_depth, o.h_contact, o.zone_depth, o.growth, o.h_max);
  const std::size_t ni = xr.size() - 1;
  const std::size_t nj = xd.size() - 1;
  std::vector<Point> pts((ni + 1) * (nj + 1));
  for (std::size_t i = 0; i <= ni; ++i)
    for (std::size_t j = 0; j <= nj; ++j)  // j = 0 at the base, j = nj at the top
      pts[i * (nj + 1) + j] = {xr[i], j == nj ? 0.0 : -xd[nj - j]};
  builder.start_body(Body::kSubstrate);
  const auto ids = builder.block(pts, ni, nj);
  for (std::size_t i = 0; i <= ni; ++i) {
    mesh.substrate_surface_nodes.push_back(ids[i * (nj + 1) + nj]);
    mesh.base_nodes.push_back(ids[i * (nj + 1)]);
  }
}

/// Number of leading intervals of size h (the uniform part of a graded distribution).
std::size_t uniform_count(const std::vector<double>& x, double h) {
  std::size_t n = 0;
  while (n + 1 < x.size() && std::abs((x[n + 1] - x[n]) - h) <= 1e-9 * h) ++n;
  return n;
}

/// Three-block substrate: the uniform h x h zone [0, Z_r] x [-Z_d, 0] plus two graded blocks around
/// it that meet on the diagonal from the zone's corner (Z_r, -Z_d) to the far corner (W, -D): the
/// right block (zone's right edge -> r = W, surface on top) and the bottom block (zone's bottom
/// edge -> base, axis on the left). Unlike a tensor grid, the zone's fine columns and rows do not
/// run on to the base and to r = W. The graded edges (surface, axis) start at h g and are capped so
/// that the diagonal's intervals stay <= h_max; the outer edges (r = W, z = -D) carry as many
/// uniform intervals as the zone edge facing them. Returns false (nothing added) when the zone
/// leaves no room for the blocks.
bool generate_substrate_blocks(const MeshOptions& o, MeshBuilder& builder, Mesh& mesh) {
  const double h = o.h_contact;
  const double width = o.substrate_radius;
  const double depth = o.substrate_depth;
  const auto xr_all = graded_positions(width, h, o.zone_radius, o.growth, o.h_max);
  const auto xd_all = graded_positions(depth, h, o.zone_depth, o.growth, o.h_max);
  const std::size_t nr = uniform_count(xr_all, h);
  const std::size_t nd = uniform_count(xd_all, h);
  const double zr = static_cast<double>(nr) * h;
  const double zd = static_cast<double>(nd) * h;
  const double diag = std::hypot(width - zr, depth - zd);
  if (nr < 4 || nd < 4 || zr >= 0.8 * width || zd >= 0.8 * depth ||
      width / static_cast<double>(nd) > o.h_max || depth / static_cast<double>(nr) > o.h_max ||
      width / static_cast<double>(nd) < h || depth / static_cast<double>(nr) < h) {
    return false;
  }
  // graded distributions along the surface (from r = Z_r) and the axis (from z = -Z_d)
  auto surf = graded_positions(width - zr, h, 0.0, o.growth,
                               std::max(h * o.growth, o.h_max * (width - zr) / diag));
  auto axis = graded_positions(depth - zd, h, 0.0, o.growth,
                               std::max(h * o.growth, o.h_max * (depth - zd) / diag));
  const std::size_t m = std::max(surf.size(), axis.size()) - 1;
  surf = split_to_count(surf, m);
  axis = split_to_count(axis, m);
  const Point corner{zr, -zd};
  const Point far{width, -depth};
  std::vector<double> uni_r(nr + 1);
  std::vector<double> uni_d(nd + 1);
  for (std::size_t k = 0; k <= nr; ++k) uni_r[k] = static_cast<double>(k) / static_cast<double>(nr);
  for (std::size_t k = 0; k <= nd; ++k) uni_d[k] = static_cast<double>(k) / static_cast<double>(nd);
  uni_r.back() = 1.0;
  uni_d.back() = 1.0;
  // zone: exact multiples of h
  std::vector<Point> zone((nr + 1) * (nd + 1));
  for (std::size_t i = 0; i <= nr; ++i)
    for (std::size_t j = 0; j <= nd; ++j)  // j = 0 at z = -Z_d, j = nd at the surface
      zone[i * (nd + 1) + j] = {static_cast<double>(i) * h,
                                j == nd ? 0.0 : -static_cast<double>(nd - j) * h};
  std::vector<Point> zone_right(nd + 1);   // (Z_r, -Z_d) -> (Z_r, 0)
  std::vector<Point> zone_bottom(nr + 1);  // (0, -Z_d) -> (Z_r, -Z_d)
  for (std::size_t j = 0; j <= nd; ++j) zone_right[j] = zone[nr * (nd + 1) + j];
  for (std::size_t i = 0; i <= nr; ++i) zone_bottom[i] = zone[i * (nd + 1)];
  const auto diagonal = line_points(corner, far, fractions(surf));  // corner -> far
  std::vector<Point> surface(m + 1);                                // (Z_r, 0) -> (W, 0)
  std::vector<Point> axis_pts(m + 1);                               // (0, -Z_d) -> (0, -D)
  for (std::size_t k = 0; k <= m; ++k) {
    surface[k] = {k == m ? width : zr + surf[k], 0.0};
    axis_pts[k] = {0.0, k == m ? -depth : -(zd + axis[k])};
  }
  // outer edges with their fixed coordinate exact (base nodes at z = -D bitwise)
  auto outer = line_points(far, {width, 0.0}, uni_d);  // (W, -D) -> (W, 0)
  auto base = line_points({0.0, -depth}, far, uni_r);  // (0, -D) -> (W, -D)
  for (Point& p : outer) p.r = width;
  for (Point& p : base) p.z = -depth;

  builder.start_body(Body::kSubstrate);
  const auto ids_zone = builder.block(zone, nr, nd);
  // right block: i along the radial direction (zone edge -> r = W), j from the diagonal (j = 0)
  // to the surface (j = nd): south = diagonal, north = surface, west = zone edge, east = outer
  const auto ids_right = builder.block(coons(diagonal, surface, zone_right, outer), m, nd);
  // bottom block: i from the axis (i = 0) to the diagonal (i = nr), j downwards (j = 0 at the
  // zone's bottom edge): south = zone bottom, north = base, west = axis, east = diagonal
  const auto ids_bottom = builder.block(coons(zone_bottom, base, axis_pts, diagonal), nr, m);
  for (std::size_t i = 0; i <= nr; ++i)
    mesh.substrate_surface_nodes.push_back(ids_zone[i * (nd + 1) + nd]);
  for (std::size_t i = 1; i <= m; ++i)
    mesh.substrate_surface_nodes.push_back(ids_right[i * (nd + 1) + nd]);
  for (std::size_t i = 0; i <= nr; ++i) mesh.base_nodes.push_back(ids_bottom[i * (m + 1) + m]);
  return true;
}

/// Explicit cost of a substrate per unit of simulated time, in updates of its smallest element:
/// the sum over its elements of 2^-L, L the element subcycling level its characteristic length
/// L_e (quad_quality) gives against the smallest, L_min: the largest L <= 4 with 2^L L_min <= 0.8
/// L_e (the solver's defaults: solver.subcycling_levels = 4, kLevelMargin = 0.8).
double explicit_cost(const Mesh& mesh) {
  std::vector<double> lengths;
  for (std::size_t e = 0; e < mesh.quads.size(); ++e) {
    std::array<double, 4> r{};
    std::array<double, 4> z{};
    for (int k = 0; k < 4; ++k) {
      const auto n = static_cast<std::size_t>(mesh.quads[e][static_cast<std::size_t>(k)]);
      r[static_cast<std::size_t>(k)] = mesh.r[n];
      z[static_cast<std::size_t>(k)] = mesh.z[n];
    }
    lengths.push_back(quad_quality(r, z).characteristic_length);
  }
  const double shortest = *std::min_element(lengths.begin(), lengths.end());
  double cost = 0.0;
  for (const double l : lengths) {
    int level = 0;
    while (level < kCostLevels && std::ldexp(shortest, level + 1) <= kCostLevelMargin * l) ++level;
    cost += std::ldexp(1.0, -level);
  }
  return cost;
}

/// The three-block substrate of `o` in a mesh of its own, or nothing when the zone leaves no room
/// for the blocks or they have an element sharper than kMinBlockAngle or thinner than
/// kMinBlockWidth x h (a zone much wider than deep makes the diagonal steep and shears them).
std::optional<Mesh> well_shaped_substrate_blocks(const MeshOptions& o) {
  Mesh blocks;
  MeshBuilder builder(blocks);
  if (!generate_substrate_blocks(o, builder, blocks)) return std::nullopt;
  const MeshQuality q = mesh_quality(blocks, Body::kSubstrate);
  if (q.min_angle < kMinBlockAngle || q.min_width < kMinBlockWidth * o.h_contact) {
    return std::nullopt;
  }
  return blocks;
}

/// Substrate: of the candidate layouts, the cheapest to integrate (explicit_cost): the three
/// blocks around the zone as given; the tensor grid of the zone as given; the three blocks around
/// a zone as deep as it is wide (uniform h deeper than asked, but the elements grow in both
/// directions away from it: cheaper for small contacts, where the tensor grid's fine columns
/// and rows run on to the base and to r = W).
void generate_substrate(const MeshOptions& o, MeshBuilder& builder, Mesh& mesh) {
  if (well_shaped_substrate_blocks(o)) {
    generate_substrate_blocks(o, builder, mesh);
    return;
  }
  MeshOptions square = o;
  square.zone_depth = std::max(o.zone_depth, o.zone_radius);
  if (const auto blocks = well_shaped_substrate_blocks(square)) {
    Mesh tensor;
    MeshBuilder tensor_builder(tensor);
    generate_substrate_tensor(o, tensor_builder, tensor);
    if (explicit_cost(*blocks) < explicit_cost(tensor)) {
      generate_substrate_blocks(square, builder, mesh);
      return;
    }
  }
  generate_substrate_tensor(o, builder, mesh);
}

}  // namespace

std::vector<double> graded_positions(
    double length, double h, double uniform_length, double growth, double h_max) {
  std::vector<double> sizes;
  std::vector<bool> graded;
  grow_sizes(h, uniform_length, growth, std::max(h, h_max), length, sizes, graded);
  auto x = positions_from_sizes(close_distribution(std::move(sizes), std::move(graded), length));
  x.back() = length;  // exact end (the sum of the sizes may differ in the last bit)
  return x;
}

void validate(const MeshOptions& o) {
  require_positive("mesh.sphere_radius", o.sphere_radius, "[m]");
  require_non_negative("mesh.gap", o.gap, "[m]");
  require_positive("mesh.substrate_radius", o.substrate_radius, "[m]");
  require_positive("mesh.substrate_depth", o.substrate_depth, "[m]");
  require_positive("mesh.h_contact", o.h_contact, "[m]");
  require_positive("mesh.zone_radius", o.zone_radius, "[m]");
  require_positive("mesh.zone_depth", o.zone_depth, "[m]");
  if (!(o.growth >= 1.0 && o.growth <= 2.0)) throw_invalid("mesh.growth", o.growth, "in [1, 2]");
  require_positive("mesh.h_max", o.h_max, "[m]");
  if (o.h_max < o.h_contact) throw_invalid("mesh.h_max", o.h_max, ">= the contact element size");
  if (o.h_contact > 0.05 * o.sphere_radius)
    throw_invalid("mesh.h_contact", o.h_contact, "<= R / 20 (too coarse for the sphere)");
  const double max_elements_per_edge = 20000.0;
  if (o.sphere_radius / o.h_contact > max_elements_per_edge ||
      o.substrate_radius / o.h_contact > max_elements_per_edge ||
      o.substrate_depth / o.h_contact > max_elements_per_edge)
    throw_invalid("mesh.h_contact", o.h_contact, "coarser (more than 20000 elements per edge)");
}

MeshOptions mesh_options_for(const ImpactConfig& config) {
  const double a = predicted_contact_radius(config);
  MeshOptions o;
  o.sphere_radius = config.sphere.radius;
  o.gap = config.impact.gap;
  o.substrate_radius = config.substrate.radius;
  o.substrate_depth = config.substrate.depth;
  o.h_contact = config.mesh.h_min;
  if (config.mesh.contact_elements > 0.0)
    o.h_contact = std::min(o.h_contact, a / config.mesh.contact_elements);
  o.zone_radius = config.mesh.refine_factor * a;
  o.zone_depth = config.mesh.refine_depth * a;
  o.growth = config.mesh.growth;
  o.h_max = std::max(config.mesh.h_max, o.h_contact);
  return o;
}

Mesh generate_impact_mesh(const MeshOptions& options) {
  validate(options);
  Mesh mesh;
  MeshBuilder builder(mesh);
  generate_sphere(options, builder, mesh);
  generate_substrate(options, builder, mesh);
  for (int n = 0; n < mesh.num_nodes(); ++n)
    if (mesh.r[static_cast<std::size_t>(n)] == 0.0) mesh.axis_nodes.push_back(n);
  return mesh;
}

Mesh build_impact_mesh(const ImpactConfig& config) {
  if (!config.mesh.file.empty()) return read_gmsh(config.mesh.file);
  return generate_impact_mesh(mesh_options_for(config));
}

}  // namespace corlab::fem
