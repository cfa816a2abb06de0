// The substrate: tensor grid, three blocks around the zone, their explicit cost and the choice.
#include "fem/mesh/substrate_layout.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include "corlab/fem/mesh/mesh_quality.hpp"
#include "fem/mesh/block_geometry.hpp"
#include "fem/mesh/graded_distribution.hpp"

namespace corlab::fem::meshing {
namespace {

/// Quality the three-block substrate must have, else the tensor grid is used: corner angles
/// >= 40 deg and widths >= 0.7 h (a square zone gives 45 deg and 0.72 h at the diagonal).
constexpr double kMinBlockAngle = 40.0 * kPi / 180.0;
constexpr double kMinBlockWidth = 0.7;

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
    Mesh tensor;
    MeshBuilder tensor_builder(tensor);
    generate_substrate_tensor(o, tensor_builder, tensor);
    if (substrate_cost(*blocks) < substrate_cost(tensor)) {
      generate_substrate_blocks(square, builder, mesh);
      return;
    }
  }
  generate_substrate_tensor(o, builder, mesh);
}

}  // namespace corlab::fem::meshing
