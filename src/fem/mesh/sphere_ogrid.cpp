// The sphere's O-grid: sizes and angles, the core's curved edges, the four blocks, surface nodes.
// Points (docs/theory/mesh.md): P (lowest), Q (phi = alpha), Q' (phi = beta) and T (top) on the
// surface; A, K, K', A' the core's corners inside them.
// SPDX-License-Identifier: BSD-3-Clause
#include "fem/mesh/sphere_ogrid.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "corlab/core/units.hpp"
#include "fem/mesh/block_geometry.hpp"
#include "fem/mesh/coarsening_layer.hpp"
#include "fem/mesh/graded_distribution.hpp"

namespace corlab::fem::meshing {
namespace {

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
constexpr double kMinBottomAngle = 10.0 * units::kDegree;
constexpr double kMaxBottomAngle = 60.0 * units::kDegree;
constexpr double kRingCornerAngle = 120.0 * units::kDegree;
/// Depth of the uniform-h layer under the sphere's lowest point as a fraction of zone_depth (the
/// substrate's: by default 0.5 a, where the elastic stresses peak, Johnson 1985, fig. 4.6).
constexpr double kSphereUniformDepthFraction = 1.0;
/// Ring thickness limits as fractions of R.
constexpr double kMinRingFraction = 0.12;
constexpr double kMaxRingFraction = 0.2;
constexpr double kTopRingFraction = 0.5;

/// Sizes and angles of the O-grid that do not depend on the top ring's thickness.
struct SphereLayout {
  double radius = 0.0;          // R [m]
  double zc = 0.0;              // height of the centre [m]
  double h = 0.0;               // contact element size [m]
  double min_size = 0.0;        // smallest spacing on derived edges [m]
  double uniform_depth = 0.0;   // depth of the uniform-h layer under P [m]
  double alpha = 0.0;           // polar angle of Q [rad]
  double gamma = 0.0;           // arc angle of the top block, T -> Q' [rad]
  double beta = 0.0;            // polar angle of Q', pi - gamma [rad]
  double d_ring = 0.0;          // ring thickness of the bottom and right blocks [m]
  double d_top0 = 0.0;          // top ring thickness before the core's limits [m]
  double rho_top_min = 0.0;     // smallest distance of the core's top edge from the centre [m]
  std::vector<double> arc_b;    // arc-length positions P -> Q [m]
  std::vector<double> depth_b;  // positions through the ring, from the surface [m]
  std::size_t ns = 0;           // intervals on the bottom and top blocks' arcs
  std::size_t nt = 0;           // intervals through the ring
};

/// Unit vectors at polar angle phi: outward radial and tangent (towards larger phi).
Point e_out(double phi) { return {std::sin(phi), -std::cos(phi)}; }
Point e_tan(double phi) { return {std::cos(phi), std::sin(phi)}; }

/// Directions from a core corner at polar angle phi (K, K') at the ring corner angle from the
/// outward radial, towards larger phi (ahead) or smaller phi (back).
Point corner_ahead(double phi) {
  const double ca = std::cos(kRingCornerAngle);
  const double sa = std::sin(kRingCornerAngle);
  return ca * e_out(phi) + sa * e_tan(phi);
}
Point corner_back(double phi) {
  const double ca = std::cos(kRingCornerAngle);
  const double sa = std::sin(kRingCornerAngle);
  return ca * e_out(phi) - sa * e_tan(phi);
}

/// Whether a position x [m] lies within a limit [m] (up to round-off in the distributions).
bool within(double x, double limit) { return x <= (1.0 + 1e-9) * limit; }

/// The core's bottom edge A -> K for ring thickness d: horizontal at the axis, at the ring corner
/// angle at K.
Curve core_bottom(const SphereLayout& s, double d) {
  return hermite(polar(s.zc, s.radius - d, 0.0), {1.0, 0.0}, polar(s.zc, s.radius - d, s.alpha),
                 -1.0 * corner_back(s.alpha));
}

/// The bottom ring (alpha, d_ring, the arc and depth distributions) and the top block's angle.
SphereLayout sphere_layout(const MeshOptions& o) {
  SphereLayout s;
  s.radius = o.sphere_radius;
  s.zc = o.gap + s.radius;
  s.h = o.h_contact;
  s.min_size = kMinSpacingFraction * s.h;
  // bottom ring block: arc P (phi = 0) -> Q (phi = alpha), depth d_ring
  s.alpha = std::clamp(o.zone_radius / s.radius, kMinBottomAngle, kMaxBottomAngle);
  s.arc_b = graded_positions(s.radius * s.alpha, s.h, o.zone_radius, o.growth, o.h_max);
  s.ns = s.arc_b.size() - 1;
  s.uniform_depth = kSphereUniformDepthFraction * o.zone_depth;
  // ring thickness: thin enough that the core's bottom edge (n_s intervals) stays long enough
  // for spacings >= kMinSpacingFraction h (the radial columns converge towards the centre)
  s.d_ring = std::clamp(s.uniform_depth, kMinRingFraction * s.radius, kMaxRingFraction * s.radius);
  const double needed = 1.05 * kMinSpacingFraction * s.h * static_cast<double>(s.ns);
  while (s.d_ring > 4.0 * s.h && core_bottom(s, s.d_ring).length() < needed) s.d_ring *= 0.9;
  s.depth_b = graded_positions(s.d_ring, s.h, s.uniform_depth, o.growth, o.h_max);
  s.nt = s.depth_b.size() - 1;
  // top block arc: n_s intervals of roughly square elements (radial size d_top / n_t)
  s.d_top0 = std::max(s.d_ring, kTopRingFraction * s.radius);
  const double s_top_target = std::max(s.h, s.d_top0 / static_cast<double>(s.nt));
  s.gamma = std::clamp(static_cast<double>(s.ns) * s_top_target / s.radius, kPi / 4.0,
                       kPi - s.alpha - kPi / 3.0);
  s.beta = kPi - s.gamma;
  // the core's top edge carries n_s intervals too: keep it long enough for spacings ~h
  s.rho_top_min = std::min(1.0 - kMinRingFraction,
                           1.2 * static_cast<double>(s.ns) * s.h / (s.gamma * s.radius)) *
                  s.radius;
  return s;
}

/// What the top ring thickness d_top sets: K', A', the core's right edge K -> K', and the right
/// block's arc and the core's axis positions, split to the same count n_r.
struct CoreRight {
  Point k2;
  Point a2;
  Curve right;
  std::vector<double> arc_r;   // right block arc positions
  double zone_arc;             // the refined zone's part of the arc Q -> Q' (uniform h) [m]
  std::vector<double> axis_x;  // core axis positions
  std::size_t nr;
};

CoreRight core_right(const SphereLayout& s, const MeshOptions& o, double d_top) {
  const Point a = polar(s.zc, s.radius - s.d_ring, 0.0);
  const Point k = polar(s.zc, s.radius - s.d_ring, s.alpha);
  const Point k2 = polar(s.zc, s.radius - d_top, s.beta);
  const Point a2 = polar(s.zc, s.radius - d_top, kPi);
  // right block: arc Q -> Q' (i), radial (j): Q->K to Q'->K'
  const double s_q = spacings(s.arc_b).back();
  const double s_top = s.radius * s.gamma / static_cast<double>(s.ns);
  const double right_uniform = std::max(0.0, o.zone_radius - s.radius * s.alpha);
  auto arc = positions_from_sizes(
      two_sided_sizes(s.radius * (s.beta - s.alpha), s_q, right_uniform, s_top, o.growth, o.h_max));
  // core axis A -> A': continues the depth refinement below the ring, then grows
  const double depth_last = spacings(s.depth_b).back();
  const double s_top_radial = depth_last * d_top / s.d_ring;
  auto axis = positions_from_sizes(two_sided_sizes(norm(a2 - a), kCoreFirstSpacing * depth_last,
                                                   std::max(0.0, s.uniform_depth - s.d_ring),
                                                   s_top_radial, o.growth, o.h_max));
  const std::size_t n = std::max(arc.size(), axis.size()) - 1;
  return CoreRight{k2,
                   a2,
                   hermite(k, corner_ahead(s.alpha), k2, -1.0 * corner_back(s.beta)),
                   split_to_count(arc, n),
                   right_uniform,
                   split_to_count(axis, n),
                   n};
}

/// The top ring thickness d_top sets K' and A': as thick as d_top0 and rho_top_min allow, thinner
/// when the core's right edge K -> K' is too short for its n_r intervals of >= min_size.
CoreRight fit_core_right(const SphereLayout& s, const MeshOptions& o) {
  double d_top = std::max(s.d_ring, std::min(s.d_top0, s.radius - s.rho_top_min));
  CoreRight core = core_right(s, o, d_top);
  while (d_top > s.d_ring &&
         core.right.length() < 1.05 * s.min_size * static_cast<double>(core.nr)) {
    d_top = std::max(s.d_ring, 0.9 * d_top);
    core = core_right(s, o, d_top);
  }
  return core;
}

/// The bottom ring block's edges: arc P -> Q (south), A -> K (north, n_s intervals like the
/// arc), P -> A (west, the axis) and Q -> K (east).
struct RingEdges {
  std::vector<Point> pq;
  std::vector<Point> ak;
  std::vector<Point> pa;
  std::vector<Point> qk;
};

RingEdges ring_edges(const SphereLayout& s) {
  const double zc = s.zc;
  const double radius = s.radius;
  const auto depth_f = fractions(s.depth_b);
  const Curve gamma_bottom = core_bottom(s, s.d_ring);
  RingEdges e;
  e.pq = arc_points(zc, radius, 0.0, s.alpha, s.arc_b);
  e.ak = gamma_bottom.sample(fit_fractions(fractions(s.arc_b), gamma_bottom.length(), s.min_size));
  e.pa = line_points(polar(zc, radius, 0.0), polar(zc, radius - s.d_ring, 0.0), depth_f);
  e.qk = line_points(polar(zc, radius, s.alpha), polar(zc, radius - s.d_ring, s.alpha), depth_f);
  return e;
}

/// Sweeps layers first .. last - 1 of a block along the sphere's arc (grid `pts`, index
/// i * (nt + 1) + j: i along the arc, j inwards), merging the depth rows `rows` 3:1 wherever the
/// thick-layer transition is well shaped and `refined(i)` (layer i within the refined zone) is
/// false. Returns the rows that reach line `last`.
template <typename Refined>
std::vector<std::size_t> skin_sweep(MeshBuilder& builder,
                                    const std::vector<Point>& pts,
                                    std::size_t nt,
                                    std::size_t first,
                                    std::size_t last,
                                    std::vector<std::size_t> rows,
                                    double h_max,
                                    double h,
                                    Refined refined) {
  const auto along = [&](std::size_t j, std::size_t i) { return pts[i * (nt + 1) + j]; };
  for (std::size_t i = first; i < last; ++i) {
    rows = coarsening_layer(builder, rows, i, refined(i) ? 0.0 : h_max, along, h,
                            TransitionDepth::kThickLayer);
  }
  return rows;
}

/// What the bottom ring's transitions leave: the arc's columns that reach A -> K and the depth
/// rows that reach Q -> K (indices into the ring's grid).
struct RingSweep {
  std::vector<std::size_t> cols;
  std::vector<std::size_t> rows;
};

/// Adds the bottom ring block, i along the arc P -> Q and j inwards from it. With o.transitions
/// it is coarsened 3:1 (coarsening_layer, as the substrate is) wherever the transition is well
/// shaped, in two parts split at the refined zone's edge (arc length zone_radius from P):
///   - under the contact, row by row inwards: below the refined depth three columns become one;
///     the contact's h-wide columns would otherwise run on through the ring and the core to the
///     top of the sphere at nearly the contact's stable step;
///   - beyond the zone, layer by layer along the arc: three depth rows become one; the rows, h
///     thick at the surface, would otherwise run on round the sphere as thin, long and heavy
///     skin elements with nearly the contact's stable step (which also stopped mass scaling).
RingSweep add_bottom_ring(const MeshOptions& o,
                          const SphereLayout& s,
                          const RingEdges& ring,
                          MeshBuilder& builder) {
  const std::size_t nt = s.nt;
  const std::vector<Point> pts = coons(ring.pq, ring.ak, ring.pa, ring.qk);
  if (!o.transitions) {
    builder.block(pts, s.ns, nt);
    return {all_edges(s.ns), all_edges(nt)};
  }
  const auto point = [&](std::size_t i, std::size_t j) { return pts[i * (nt + 1) + j]; };
  std::size_t nz = 0;  // the arc's intervals within the refined zone
  while (nz < s.ns && within(s.arc_b[nz + 1], o.zone_radius)) ++nz;
  RingSweep out{all_edges(nz), all_edges(nt)};
  for (std::size_t j = 0; j < nt; ++j) {
    // rows within the refined depth keep their columns, as the substrate's zone does; h: the
    // transitions' elements are as wide as the substrate's, although the ring's columns narrow
    // to min_size inwards
    const bool refined = within(s.depth_b[j + 1], s.uniform_depth);
    out.cols = coarsening_layer(builder, out.cols, j, refined ? 0.0 : o.h_max, point, s.h);
  }
  // beyond the zone (layers nz .. ns - 1), each layer's far line is a column that reaches A -> K
  out.rows = skin_sweep(builder, pts, nt, nz, s.ns, out.rows, o.h_max, s.h,
                        [](std::size_t) { return false; });
  for (std::size_t i = nz + 1; i <= s.ns; ++i) out.cols.push_back(i);
  return out;
}

/// The other blocks' edges, each shared edge once, named by their end points.
struct SphereEdges {
  std::vector<Point> ak;    // A -> K: core south, at the ring's columns that reach it
  std::vector<Point> qk;    // Q -> K: bottom block east, right block west
  std::vector<Point> qq2;   // arc Q -> Q': right block south
  std::vector<Point> kk2;   // K -> K': right block north, core east
  std::vector<Point> q2k2;  // Q' -> K': right and top blocks' east
  std::vector<Point> tq2;   // arc T -> Q': top block south
  std::vector<Point> a2k2;  // A' -> K': top block north, core north
  std::vector<Point> ta2;   // T -> A': top block west
  std::vector<Point> aa2;   // A -> A': core west (the axis)
};

/// Arc-length positions T -> Q' of the top block: n uniform intervals (as many as the core's
/// columns) [m].
std::vector<double> top_arc_positions(const SphereLayout& s, std::size_t n) {
  std::vector<double> arc_t(n + 1);
  for (std::size_t k = 0; k <= n; ++k)
    arc_t[k] = s.radius * s.gamma * static_cast<double>(k) / static_cast<double>(n);
  return arc_t;
}

/// The edges of the right and top blocks and the core: arcs on the sphere, radial lines, the
/// core's curved edges; `cols`: the ring's columns that reach A -> K.
SphereEdges sphere_edges(const SphereLayout& s,
                         const CoreRight& core,
                         const RingEdges& ring,
                         const std::vector<std::size_t>& cols,
                         const std::vector<double>& arc_t) {
  const double zc = s.zc;
  const double radius = s.radius;
  const Point pnt_q2 = polar(zc, radius, s.beta);
  const auto depth_f = fractions(s.depth_b);
  const Curve gamma_top = hermite(core.a2, {1.0, 0.0}, core.k2, -1.0 * corner_ahead(s.beta));
  SphereEdges e;
  for (const std::size_t i : cols) e.ak.push_back(ring.ak[i]);
  e.qk = ring.qk;
  e.qq2 = arc_points(zc, radius, s.alpha, s.beta, core.arc_r);
  e.kk2 = core.right.sample(
      fit_fractions(fractions(core.arc_r), core.right.length(), kCoreRightSpacing * s.min_size));
  e.q2k2 = line_points(pnt_q2, core.k2, depth_f);
  const std::size_t n = arc_t.size() - 1;
  e.tq2.resize(n + 1);
  for (std::size_t k = 0; k <= n; ++k) e.tq2[k] = polar(zc, radius, kPi - arc_t[k] / radius);
  e.tq2.back() = pnt_q2;
  e.a2k2 = gamma_top.sample(fit_fractions(fractions(arc_t), gamma_top.length(), s.min_size));
  e.ta2 = line_points(polar(zc, radius, kPi), core.a2, depth_f);
  e.aa2 = line_points(ring.pa.back(), core.a2, fractions(core.axis_x));
  return e;
}

/// Adds the right block, i along the arc Q -> Q' and j inwards from it, from the ring's depth
/// rows that reach Q -> K (`rows`). With o.transitions its layers go on merging three rows into
/// one along the arc, as the ring's beyond the zone do (add_bottom_ring), except where the arc is
/// still within the refined zone (fast impacts, whose zone reaches past phi = 60 deg). Returns
/// the rows that reach Q' -> K'.
std::vector<std::size_t> add_right_block(const MeshOptions& o,
                                         const SphereLayout& s,
                                         const CoreRight& core,
                                         const SphereEdges& e,
                                         std::vector<std::size_t> rows,
                                         MeshBuilder& builder) {
  const std::size_t nt = s.nt;
  const std::vector<Point> pts = coons(e.qq2, e.kk2, e.qk, e.q2k2);
  if (!o.transitions) {
    builder.block(pts, core.nr, nt);
    return rows;
  }
  return skin_sweep(builder, pts, nt, 0, core.nr, std::move(rows), o.h_max, s.h,
                    [&](std::size_t i) { return within(core.arc_r[i + 1], core.zone_arc); });
}

/// The points of `pts` at the indices `keep`.
std::vector<Point> points_at(const std::vector<Point>& pts, const std::vector<std::size_t>& keep) {
  std::vector<Point> out;
  out.reserve(keep.size());
  for (const std::size_t k : keep) out.push_back(pts[k]);
  return out;
}

}  // namespace

double sphere_block_elements(const MeshOptions& o) {
  const SphereLayout s = sphere_layout(o);
  const auto ns = static_cast<double>(s.ns);
  const auto nt = static_cast<double>(s.nt);
  const auto nr = static_cast<double>(fit_core_right(s, o).nr);
  return nt * (2.0 * ns + nr) + ns * nr;  // bottom, top and right rings; the core
}

void generate_sphere(const MeshOptions& o, MeshBuilder& builder, Mesh& mesh) {
  const SphereLayout s = sphere_layout(o);
  const CoreRight core = fit_core_right(s, o);
  const RingEdges ring = ring_edges(s);
  const std::size_t nr = core.nr;

  builder.start_body(Body::kSphere);
  const RingSweep sweep = add_bottom_ring(o, s, ring, builder);
  const std::size_t nc = sweep.cols.size() - 1;  // the core's and the top block's columns
  const std::vector<double> arc_t = top_arc_positions(s, nc);
  const SphereEdges e = sphere_edges(s, core, ring, sweep.cols, arc_t);
  const std::vector<std::size_t> rows = add_right_block(o, s, core, e, sweep.rows, builder);
  const std::size_t nq = rows.size() - 1;  // the top block's rows
  const auto ids_t =
      builder.block(coons(e.tq2, e.a2k2, points_at(e.ta2, rows), points_at(e.q2k2, rows)), nc, nq);
  builder.block(coons(e.ak, e.a2k2, e.aa2, e.kk2), nc, nr);

  // surface nodes from the lowest point (bottom, right, then top block arcs), up to the first
  // node past the equator
  const double alpha = s.alpha;
  const double beta = s.beta;
  const auto& arc_b = s.arc_b;
  const auto& arc_r = core.arc_r;
  std::vector<int>& surf = mesh.sphere_surface_nodes;
  std::vector<std::pair<int, double>> arc_nodes;  // (node, polar angle)
  for (std::size_t i = 0; i <= s.ns; ++i)
    arc_nodes.emplace_back(builder.node(ring.pq[i]), alpha * arc_b[i] / arc_b.back());
  for (std::size_t i = 1; i <= nr; ++i)
    arc_nodes.emplace_back(builder.node(e.qq2[i]),
                           alpha + (beta - alpha) * arc_r[i] / arc_r.back());
  for (std::size_t i = nc; i-- > 0;)
    arc_nodes.emplace_back(ids_t[i * (nq + 1)], kPi - arc_t[i] / s.radius);
  for (const auto& [node, phi] : arc_nodes) {
    surf.push_back(node);
    if (phi > 0.5 * kPi) break;
  }
}

}  // namespace corlab::fem::meshing
