// The half sphere's cube-sphere O-grid (hex_mesh_generator.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/mesh/hex_mesh_generator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "corlab/core/error.hpp"
#include "corlab/core/units.hpp"
#include "corlab/fem/kernels/hex8.hpp"
#include "corlab/fem/mesh/contact_estimate.hpp"
#include "corlab/fem/mesh/gmsh_hex_reader.hpp"
#include "corlab/fem/mesh/hex_resolution.hpp"
#include "corlab/fem/mesh/mesh_generator.hpp"

namespace corlab::fem {
namespace {

using Point = std::array<double, 3>;

// E(c) = tan(pi c / 4), odd and exact at 0 and +-1 (shared block edges evaluate it alike).
double equiangular(double c) {
  const double a = std::abs(c);
  const double e = a == 1.0 ? 1.0 : std::tan(0.25 * units::kPi * a);
  return c < 0.0 ? -e : e;
}

// 0 = c_0 < ... < c_n = 1 from graded positions over `length` [m].
std::vector<double> unit_fractions(const std::vector<double>& positions) {
  std::vector<double> f(positions.size());
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = positions[i] / positions.back();
  f.front() = 0.0;
  f.back() = 1.0;
  return f;
}

// The lattice values of each direction.
struct Lattice {
  std::vector<double> x;  // [-1, 1], fine at 0
  std::vector<double> y;  // [0, 1], fine at 0
  std::vector<double> z;  // [-1, 1], uniform (sides and core)
  std::vector<double> t;  // [0, 1], fine at 1 (the surface)
};

Lattice make_lattice(const HexMeshOptions& o) {
  const double r = o.sphere_radius;
  const double arc = 0.25 * units::kPi * r;
  Lattice l;
  l.y = unit_fractions(graded_positions(arc, o.h_contact, o.zone_radius, o.growth, o.h_max));
  for (std::size_t i = l.y.size(); i-- > 1;) l.x.push_back(-l.y[i]);
  l.x.insert(l.x.end(), l.y.begin(), l.y.end());
  const double shell = r * (1.0 - o.core_fraction);
  const std::vector<double> depth =
      unit_fractions(graded_positions(shell, o.h_contact, o.zone_depth, o.growth, o.h_max));
  for (std::size_t i = depth.size(); i-- > 0;) l.t.push_back(1.0 - depth[i]);
  l.t.front() = 0.0;
  const double edge = l.y[l.y.size() - 1] - l.y[l.y.size() - 2];
  const int nz = std::max(2, static_cast<int>(std::lround(2.0 / edge)));
  for (int k = 0; k <= nz; ++k) l.z.push_back(k == nz ? 1.0 : -1.0 + 2.0 * k / nz);
  return l;
}

class SphereBuilder {
 public:
  SphereBuilder(const HexMeshOptions& o, HexMesh& mesh)
      : radius_(o.sphere_radius),
        core_(o.core_fraction * o.sphere_radius),
        centre_z_(o.gap + o.sphere_radius),
        mesh_(mesh) {}

  // Node at cube coordinates (X, Y, Z) and shell parameter t (merged by position).
  // The core's own nodes (t = 0) skip the surface point, undefined at the centre (0/0): a NaN
  // there merged the centre with an arbitrary node of the map.
  int node(double cx, double cy, double cz, double t) {
    const Point core{core_ * cx, core_ * cy, core_ * cz};
    Point p = core;
    if (t != 0.0) {
      const double ex = equiangular(cx);
      const double ey = equiangular(cy);
      const double ez = equiangular(cz);
      const double inv = radius_ / std::sqrt(ex * ex + ey * ey + ez * ez);
      const Point surface{ex * inv, ey * inv, ez * inv};
      for (std::size_t d = 0; d < 3; ++d) p[d] = core[d] + t * (surface[d] - core[d]);
    }
    const auto [it, added] = index_.try_emplace(p, mesh_.num_nodes());
    if (added) {
      mesh_.x.push_back(p[0]);
      mesh_.y.push_back(p[1]);
      mesh_.z.push_back(p[2] + centre_z_);
      mesh_.node_body.push_back(Body::kSphere);
      if (t == 1.0 && p[2] < 0.0) mesh_.sphere_surface_nodes.push_back(it->second);
      if (p[1] == 0.0) mesh_.symmetry_nodes.push_back(it->second);
    }
    return it->second;
  }

  // Hexahedra of a block whose nodes are at(i, j, k) on an (ni+1) x (nj+1) x (nk+1) lattice.
  template <class At>
  void block(std::size_t ni, std::size_t nj, std::size_t nk, At at) {
    constexpr int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                   {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    for (std::size_t i = 0; i < ni; ++i)
      for (std::size_t j = 0; j < nj; ++j)
        for (std::size_t k = 0; k < nk; ++k) {
          std::array<int, 8> hex{};
          for (int c = 0; c < 8; ++c)
            hex[c] = at(i + kCorner[c][0], j + kCorner[c][1], k + kCorner[c][2]);
          add_hex(hex);
        }
  }

 private:
  void add_hex(std::array<int, 8> hex) {
    if (volume(hex) < 0.0) hex = {hex[4], hex[5], hex[6], hex[7], hex[0], hex[1], hex[2], hex[3]};
    if (!(volume(hex) > 0.0))
      throw_invalid("mesh.h_min", 0.0, "a 3-D mesh without tangled elements");
    mesh_.hexes.push_back(hex);
    mesh_.element_body.push_back(Body::kSphere);
  }

  double volume(const std::array<int, 8>& hex) const {
    double x[8];
    double y[8];
    double z[8];
    for (int c = 0; c < 8; ++c) {
      const auto n = static_cast<std::size_t>(hex[c]);
      x[c] = mesh_.x[n];
      y[c] = mesh_.y[n];
      z[c] = mesh_.z[n];
    }
    return hex8_geometry(x, y, z).volume;
  }

  double radius_;
  double core_;
  double centre_z_;
  HexMesh& mesh_;
  std::map<Point, int> index_;
};

}  // namespace

void validate(const HexMeshOptions& o) {
  require_positive("mesh.sphere_radius", o.sphere_radius, "[m]");
  require_non_negative("mesh.gap", o.gap, "[m]");
  require_positive("mesh.h_contact", o.h_contact, "[m]");
  if (o.h_contact > 0.05 * o.sphere_radius)
    throw_invalid("mesh.h_contact", o.h_contact, "<= R / 20 (too coarse for the sphere)");
  if (o.sphere_radius / o.h_contact > 2e3)
    throw_invalid("mesh.h_contact", o.h_contact, ">= R / 2000 (a 3-D mesh of that is too large)");
  require_non_negative("mesh.zone_radius", o.zone_radius, "[m]");
  require_non_negative("mesh.zone_depth", o.zone_depth, "[m]");
  if (!(o.growth >= 1.0 && o.growth <= 2.0)) throw_invalid("mesh.growth", o.growth, "in [1, 2]");
  if (!(o.h_max >= o.h_contact)) throw_invalid("mesh.h_max", o.h_max, ">= mesh.h_contact");
  if (!(o.core_fraction > 0.1 && o.core_fraction < 0.8))
    throw_invalid("mesh.core_fraction", o.core_fraction, "in (0.1, 0.8)");
  if (o.block) {
    const double need = 2.0 * (o.zone_radius + o.travel);
    if (!(o.block_half_width >= need))
      throw_invalid("substrate.radius", o.block_half_width,
                    fmt::format(">= {:.4g} [m] (twice the 3-D mesh's fine zone and the contact's "
                                "tangential travel)",
                                need));
    if (!(o.block_depth >= 2.0 * o.zone_depth))
      throw_invalid("substrate.depth", o.block_depth,
                    fmt::format(">= {:.4g} [m] (twice the fine zone's depth)", 2.0 * o.zone_depth));
    if (o.block_half_width / o.h_contact > 2e3 || o.block_depth / o.h_contact > 2e3)
      throw_invalid("mesh.h_contact", o.h_contact,
                    ">= substrate size / 2000 (a 3-D mesh of that is too large)");
  }
}

HexMeshOptions hex_mesh_options_for(const ImpactConfig& config) {
  ImpactConfig normal = config;
  normal.impact.velocity = normal_velocity(config);
  const double a = predicted_contact_radius(normal);
  HexMeshOptions o;
  o.sphere_radius = config.sphere.radius;
  o.gap = 0.0;
  const HexResolution resolution = hex_resolution(config);
  o.h_contact = resolution.h_contact;
  o.zone_radius = config.mesh.refine_factor * a;
  o.zone_depth = std::max(config.mesh.refine_depth * a, 2.0 * o.h_contact);
  o.growth = resolution.growth;
  o.h_max = std::max(config.mesh.h_max, o.h_contact);
  o.block = config.substrate.shape == SubstrateShape::kFlat;
  const bool chosen = resolution.block_size > 0.0;
  o.block_half_width = chosen ? resolution.block_size : config.substrate.radius;
  o.block_depth = chosen ? resolution.block_size : config.substrate.depth;
  o.travel = contact_travel(config);
  return o;
}

namespace {

// The block's node coordinates along each axis [m].
struct BlockLattice {
  std::vector<double> x;  // graded both ways from the fine band [-zone, zone + travel]
  std::vector<double> y;  // from the symmetry plane y = 0
  std::vector<double> z;  // down from the top z = 0
};

BlockLattice make_block_lattice(const HexMeshOptions& o) {
  const double w = o.block_half_width;
  const double right_fine = std::min(o.zone_radius + o.travel, 0.9 * w);
  BlockLattice l;
  const std::vector<double> left =
      graded_positions(w, o.h_contact, o.zone_radius, o.growth, o.h_max);
  for (std::size_t i = left.size(); i-- > 1;) l.x.push_back(-left[i]);
  const std::vector<double> right = graded_positions(w, o.h_contact, right_fine, o.growth, o.h_max);
  l.x.insert(l.x.end(), right.begin(), right.end());
  l.y = graded_positions(w, o.h_contact, o.zone_radius, o.growth, o.h_max);
  const std::vector<double> depth =
      graded_positions(o.block_depth, o.h_contact, o.zone_depth, o.growth, o.h_max);
  for (std::size_t k = depth.size(); k-- > 0;) l.z.push_back(-depth[k]);
  l.z.back() = 0.0;
  return l;
}

}  // namespace

void append_hex_block(const HexMeshOptions& o, HexMesh& mesh) {
  const BlockLattice lattice = make_block_lattice(o);
  const std::vector<double>& x = lattice.x;
  const std::vector<double>& y = lattice.y;
  const std::vector<double>& z = lattice.z;
  const std::size_t nx = x.size();
  const std::size_t ny = y.size();
  const std::size_t nz = z.size();
  const int first = mesh.num_nodes();
  auto id = [&](std::size_t i, std::size_t j, std::size_t k) {
    return first + static_cast<int>((k * ny + j) * nx + i);
  };
  for (std::size_t k = 0; k < nz; ++k)
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) {
        const int n = mesh.num_nodes();
        mesh.x.push_back(x[i]);
        mesh.y.push_back(y[j]);
        mesh.z.push_back(z[k]);
        mesh.node_body.push_back(Body::kSubstrate);
        if (j == 0) mesh.symmetry_nodes.push_back(n);
        if (k == 0) mesh.base_nodes.push_back(n);
      }
  for (std::size_t k = 0; k + 1 < nz; ++k)
    for (std::size_t j = 0; j + 1 < ny; ++j)
      for (std::size_t i = 0; i + 1 < nx; ++i) {
        mesh.hexes.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                              id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
                              id(i, j + 1, k + 1)});
        mesh.element_body.push_back(Body::kSubstrate);
      }
  for (std::size_t j = 0; j + 1 < ny; ++j)
    for (std::size_t i = 0; i + 1 < nx; ++i)
      mesh.top_faces.push_back(
          {id(i, j, nz - 1), id(i + 1, j, nz - 1), id(i + 1, j + 1, nz - 1), id(i, j + 1, nz - 1)});
  mesh.top_x = x;
  mesh.top_y = y;
}

HexMesh generate_hex_sphere(const HexMeshOptions& o) {
  validate(o);
  const Lattice l = make_lattice(o);
  HexMesh mesh;
  SphereBuilder b(o, mesh);
  const std::size_t nx = l.x.size() - 1;
  const std::size_t ny = l.y.size() - 1;
  const std::size_t nz = l.z.size() - 1;
  const std::size_t nt = l.t.size() - 1;
  for (const double face : {-1.0, 1.0}) {
    // Bottom (Z = -1) and top (Z = +1) shells.
    b.block(nx, ny, nt, [&](std::size_t i, std::size_t j, std::size_t k) {
      return b.node(l.x[i], l.y[j], face, l.t[k]);
    });
    // The -x and +x shells.
    b.block(ny, nz, nt, [&](std::size_t j, std::size_t m, std::size_t k) {
      return b.node(face, l.y[j], l.z[m], l.t[k]);
    });
  }
  // The +y shell (the -y half is cut away by the symmetry plane).
  b.block(nx, nz, nt, [&](std::size_t i, std::size_t m, std::size_t k) {
    return b.node(l.x[i], 1.0, l.z[m], l.t[k]);
  });
  // The core cube.
  b.block(nx, ny, nz, [&](std::size_t i, std::size_t j, std::size_t m) {
    return b.node(l.x[i], l.y[j], l.z[m], 0.0);
  });
  std::sort(mesh.symmetry_nodes.begin(), mesh.symmetry_nodes.end());
  return mesh;
}

double hex_impact_elements(const HexMeshOptions& o) {
  validate(o);
  const Lattice l = make_lattice(o);
  const auto n = [](const std::vector<double>& v) { return static_cast<double>(v.size() - 1); };
  // generate_hex_sphere's blocks: bottom and top, -x and +x, +y shells, the core cube
  double count = n(l.x) * n(l.y) * n(l.t) * 2.0 + n(l.y) * n(l.z) * n(l.t) * 2.0 +
                 n(l.x) * n(l.z) * n(l.t) + n(l.x) * n(l.y) * n(l.z);
  if (o.block) {
    const BlockLattice b = make_block_lattice(o);
    count += n(b.x) * n(b.y) * n(b.z);
  }
  return count;
}

HexMesh generate_hex_impact_mesh(const HexMeshOptions& o) {
  HexMesh mesh = generate_hex_sphere(o);
  if (o.block) append_hex_block(o, mesh);
  return mesh;
}

HexMesh build_hex_impact_mesh(const ImpactConfig& config) {
  const HexMeshOptions o = hex_mesh_options_for(config);
  if (config.mesh.file.empty()) return generate_hex_impact_mesh(o);
  HexMesh mesh = read_gmsh_hex_sphere(config.mesh.file, config.sphere.radius);
  if (o.block) append_hex_block(o, mesh);
  return mesh;
}

}  // namespace corlab::fem
