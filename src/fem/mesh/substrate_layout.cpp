// The substrate: tensor grid, three blocks around the zone, their explicit cost and the choice.
// SPDX-License-Identifier: BSD-3-Clause
#include "fem/mesh/substrate_layout.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include "corlab/core/units.hpp"
#include "corlab/fem/mesh/mesh_quality.hpp"
#include "fem/mesh/block_geometry.hpp"
#include "fem/mesh/coarsening_layer.hpp"
#include "fem/mesh/graded_distribution.hpp"

namespace corlab::fem::meshing {
namespace {

/// Quality the three-block substrate must have, else the tensor grid is used: corner angles
/// >= 40 deg and widths >= 0.7 h (a square zone gives 45 deg and 0.72 h at the diagonal).
constexpr double kMinBlockAngle = 40.0 * units::kDegree;
constexpr double kMinBlockWidth = 0.7;

/// Graded intervals at least this many h long are coarse enough to run on to the base and to
/// r = W in a plain tensor product (generate_substrate_coarsened_tensor).
constexpr double kCornerSize = 3.0;

/// The point at radius r [m] and depth d [m] below the surface (z = +0, not -0, at the surface).
Point at_depth(double r, double d) { return {r, d == 0.0 ? 0.0 : -d}; }

/// Index of the first interval of xr (from `first` on) at least kCornerSize h long [-].
std::size_t first_coarse(const std::vector<double>& x, std::size_t first, double h) {
  std::size_t i = first;
  while (i + 1 < x.size() && x[i + 1] - x[i] < kCornerSize * h) ++i;
  return i;
}

/// Tensor-product substrate coarsened by 3:1 transitions (`mesh.transitions` = 1; used where
/// the tensor grid is). Radii xr and depths xd are graded away from the uniform zone
/// (nr x nd intervals of h); p and q are the first radial and depth intervals beyond it that are
/// kCornerSize h long. Three parts (coarsening_layer: each layer merges its intervals 3:1 from
/// the axis, resp. the surface, on, wherever the transition is well shaped):
///   - under the zone out to xr[p], row by row downwards: its h-wide columns and the graded
///     ones next to them;
///   - the zone's depth, column by column outwards: its h-high rows, joined at xr[p] by the
///     graded rows down to xd[q];
///   - the corner beyond xr[p] and xd[q]: a plain tensor product of coarse intervals.
/// So the fine columns and rows do not run on to the base and to r = W at the contact's step, as
/// in a plain tensor grid.
void generate_substrate_coarsened_tensor(const MeshOptions& o, MeshBuilder& builder, Mesh& mesh) {
  const double h = o.h_contact;
  const auto xr = graded_positions(o.substrate_radius, h, o.zone_radius, o.growth, o.h_max);
  const auto xd = graded_positions(o.substrate_depth, h, o.zone_depth, o.growth, o.h_max);
  const std::size_t nd = uniform_count(xd, h);
  const std::size_t p = first_coarse(xr, uniform_count(xr, h), h);
  const std::size_t q = first_coarse(xd, nd, h);
  const auto under = [&](std::size_t i, std::size_t j) { return at_depth(xr[i], xd[j]); };
  const auto beside = [&](std::size_t j, std::size_t i) { return at_depth(xr[i], xd[j]); };
  builder.start_body(Body::kSubstrate);
  std::vector<std::size_t> cols = all_edges(p);  // under the zone, downwards
  for (std::size_t j = nd; j + 1 < xd.size(); ++j)
    cols = coarsening_layer(builder, cols, j, o.h_max, under);
  std::vector<std::size_t> rows = all_edges(nd);  // the zone's depth, outwards
  for (std::size_t i = 0; i + 1 < xr.size(); ++i) {
    for (std::size_t j = nd + 1; i == p && j <= q; ++j) rows.push_back(j);
    rows = coarsening_layer(builder, rows, i, o.h_max, beside);
  }
  for (std::size_t i = p; i + 1 < xr.size(); ++i)  // the corner
    for (std::size_t j = q; j + 1 < xd.size(); ++j)
      builder.quad({under(i, j + 1), under(i + 1, j + 1), under(i + 1, j), under(i, j)});
  for (const double r : xr) mesh.substrate_surface_nodes.push_back(builder.node(at_depth(r, 0.0)));
  for (const std::size_t i : cols)
    mesh.base_nodes.push_back(builder.node(at_depth(xr[i], xd.back())));
  for (std::size_t i = p + 1; i < xr.size(); ++i)
    mesh.base_nodes.push_back(builder.node(at_depth(xr[i], xd.back())));
}

/// Plain tensor-product substrate (`mesh.transitions` = 0; its cost also decides the layout): the
/// zone's h-wide columns run down to the base and its h-high rows out to r = W.
void generate_substrate_plain_tensor(const MeshOptions& o, MeshBuilder& builder, Mesh& mesh) {
  const auto xr =
      graded_positions(o.substrate_radius, o.h_contact, o.zone_radius, o.growth, o.h_max);
  const auto xd = graded_positions(o.substrate_depth, o.h_contact, o.zone_depth, o.growth, o.h_max);
  const std::size_t ni = xr.size() - 1;
  const std::size_t nj = xd.size() - 1;
  std::vector<Point> pts((ni + 1) * (nj + 1));
  for (std::size_t i = 0; i <= ni; ++i)
    for (std::size_t j = 0; j <= nj; ++j)  // j = 0 at the base, j = nj at the top
      pts[i * (nj + 1) + j] = at_depth(xr[i], xd[nj - j]);
  builder.start_body(Body::kSubstrate);
  const auto ids = builder.block(pts, ni, nj);
  for (std::size_t i = 0; i <= ni; ++i) {
    mesh.substrate_surface_nodes.push_back(ids[i * (nj + 1) + nj]);
    mesh.base_nodes.push_back(ids[i * (nj + 1)]);
  }
}

/// The plain tensor grid of `o` in a mesh of its own. The choice between the blocks and the
/// tensor grid (generate_substrate) weighs its cost also when the transitions are on, so that
/// the option changes the tensor grid only, never which cases get the blocks.
Mesh plain_tensor(const MeshOptions& o) {
  Mesh tensor;
  MeshBuilder builder(tensor);
  generate_substrate_plain_tensor(o, builder, tensor);
  return tensor;
}

/// The uniform zone's (nr + 1) x (nd + 1) points, at exact multiples of h (index i * (nd + 1) + j).
std::vector<Point> zone_points(std::size_t nr, std::size_t nd, double h) {
  std::vector<Point> zone((nr + 1) * (nd + 1));
  for (std::size_t i = 0; i <= nr; ++i)
    for (std::size_t j = 0; j <= nd; ++j)  // j = 0 at z = -Z_d, j = nd at the surface
      zone[i * (nd + 1) + j] = {static_cast<double>(i) * h,
                                j == nd ? 0.0 : -static_cast<double>(nd - j) * h};
  return zone;
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
  const std::vector<Point> zone = zone_points(nr, nd, h);
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
  auto outer = line_points(far, {width, 0.0}, uniform_fractions(nd));  // (W, -D) -> (W, 0)
  auto base = line_points({0.0, -depth}, far, uniform_fractions(nr));  // (0, -D) -> (W, -D)
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

/// Explicit cost of a candidate substrate per unit of simulated time, in updates of its smallest
/// element (explicit_cost of mesh_quality.hpp, levels against its own shortest element).
double substrate_cost(const Mesh& mesh) {
  const double shortest = mesh_quality(mesh, Body::kSubstrate).min_characteristic_length;
  return explicit_cost(mesh, Body::kSubstrate, shortest).updates;
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

}  // namespace

void generate_substrate(const MeshOptions& o, MeshBuilder& builder, Mesh& mesh) {
  if (well_shaped_substrate_blocks(o)) {
    generate_substrate_blocks(o, builder, mesh);
    return;
  }
  MeshOptions square = o;
  square.zone_depth = std::max(o.zone_depth, o.zone_radius);
  if (const auto blocks = well_shaped_substrate_blocks(square)) {
    if (substrate_cost(*blocks) < substrate_cost(plain_tensor(o))) {
      generate_substrate_blocks(square, builder, mesh);
      return;
    }
  }
  if (o.transitions) {
    generate_substrate_coarsened_tensor(o, builder, mesh);
  } else {
    generate_substrate_plain_tensor(o, builder, mesh);
  }
}

}  // namespace corlab::fem::meshing
