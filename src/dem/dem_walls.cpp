// The walls of a DEM export (planes, cylinders; one wall material each) and the calibration of
// every wall material's pairs.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dem/dem_walls.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "corlab/core/error.hpp"
#include "corlab/core/number.hpp"
#include "corlab/core/text.hpp"
#include "corlab/dem/dem_export.hpp"
#include "dem/detail/export_spec.hpp"

namespace corlab::dem {
namespace {

constexpr std::string_view kShapes =
    "plane:PX,PY,PZ,NX,NY,NZ[,HALF] (a point and the normal into the particles [m]), "
    "cylinder:AXIS,C1,C2,R,LO,HI (x|y|z, particles inside [m]) or floor";

std::vector<double> numbers(std::string_view text, std::string_view whole, std::size_t from) {
  std::vector<double> out;
  std::size_t start = from;
  while (start <= text.size()) {
    const auto comma = text.find(',', start);
    const auto end = comma == std::string_view::npos ? text.size() : comma;
    out.push_back(
        parse_finite(fmt::format("wall shape {}", whole), trim(text.substr(start, end - start))));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return out;
}

bool same_material(const Material& a, const Material& b) {
  return a.youngs_modulus == b.youngs_modulus && a.poisson_ratio == b.poisson_ratio &&
         a.density == b.density && a.yield_stress == b.yield_stress;
}

// The spec with one wall material (k) as its wall, and the pair entries that name it (or, k = 0,
// no other wall): what calibrate_pairs takes.
ExportSpec one_wall(const ExportSpec& spec, int k) {
  ExportSpec sub = spec;
  sub.extra_walls.clear();
  sub.walls.clear();
  sub.pair_friction.clear();
  if (k > 0) {
    const LabelledMaterial& m = spec.extra_walls[static_cast<std::size_t>(k - 1)];
    sub.wall = m.material;
    sub.wall_label = wall_label(spec, k);
    sub.wall_only = true;
  }
  const auto keep = [&](const std::string& first, const std::string& second) {
    const int w = detail::named_wall(spec, first, second);
    return w == k || (w < 0 && k == 0);
  };
  const auto rename = [&](std::string& name) {
    if (k > 0 && name == wall_label(spec, k)) name = "wall";
  };
  sub.pair_restitution.clear();
  for (auto p : spec.pair_restitution) {
    if (!keep(p.first, p.second)) continue;
    rename(p.first);
    rename(p.second);
    sub.pair_restitution.push_back(p);
  }
  sub.pair_tables.clear();
  for (auto t : spec.pair_tables) {
    if (!keep(t.first, t.second)) continue;
    rename(t.first);
    rename(t.second);
    sub.pair_tables.push_back(t);
  }
  return sub;
}

}  // namespace

Wall parse_wall_shape(std::string_view text) {
  Wall w;
  const std::string whole(text);
  if (trim(text) == "floor") return w;
  const auto colon = text.find(':');
  const std::string_view kind = colon == std::string_view::npos ? text : text.substr(0, colon);
  if (kind == "plane") {
    const auto v = numbers(text, whole, colon + 1);
    if (v.size() != 6 && v.size() != 7) throw_invalid("wall shape", whole, kShapes);
    const double norm = std::sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5]);
    if (!(norm > 0.0)) throw_invalid("wall shape", whole, "a plane normal that is not zero");
    for (int a = 0; a < 3; ++a) {
      w.point[static_cast<std::size_t>(a)] = v[static_cast<std::size_t>(a)];
      w.normal[static_cast<std::size_t>(a)] = v[static_cast<std::size_t>(a) + 3] / norm;
    }
    if (v.size() == 7) {
      if (!(v[6] > 0.0)) throw_invalid("wall shape", whole, "a half-width HALF > 0 [m]");
      w.half_width = v[6];
    }
    if (plane_axis(w) < 0 && w.half_width <= 0.0) {
      throw_invalid("wall shape", whole,
                    "a half-width HALF [m] for an oblique plane (plane:PX,PY,PZ,NX,NY,NZ,HALF: "
                    "the square of LIGGGHTS's mesh and YADE's facets)");
    }
    if (plane_axis(w) >= 0) w.half_width = 0.0;
    return w;
  }
  if (kind == "cylinder" && colon != std::string_view::npos) {
    const auto comma = text.find(',', colon);
    const std::string_view axis = trim(text.substr(colon + 1, comma - colon - 1));
    if (comma == std::string_view::npos || axis.size() != 1 || axis.find_first_of("xyz") != 0) {
      throw_invalid("wall shape", whole, kShapes);
    }
    w.shape = WallShape::cylinder;
    w.axis = axis[0] - 'x';
    const auto v = numbers(text, whole, comma + 1);
    if (v.size() != 5) throw_invalid("wall shape", whole, kShapes);
    w.centre = {v[0], v[1]};
    w.radius = v[2];
    w.lo = v[3];
    w.hi = v[4];
    if (!(w.radius > 0.0)) throw_invalid("wall shape", whole, "a cylinder radius R > 0 [m]");
    if (!(w.hi > w.lo)) throw_invalid("wall shape", whole, "a cylinder with HI > LO [m]");
    return w;
  }
  throw_invalid("wall shape", whole, kShapes);
}

int plane_axis(const Wall& wall) {
  for (int a = 0; a < 3; ++a) {
    if (std::abs(wall.normal[static_cast<std::size_t>(a)]) == 1.0) return a;
  }
  return -1;
}

std::array<std::array<double, 3>, 4> plane_square(const Wall& wall) {
  const auto& n = wall.normal;
  // u, v: an orthonormal basis of the plane with u x v = n
  const std::array<double, 3> helper =
      std::abs(n[0]) < 0.9 ? std::array<double, 3>{1, 0, 0} : std::array<double, 3>{0, 1, 0};
  std::array<double, 3> u{n[1] * helper[2] - n[2] * helper[1], n[2] * helper[0] - n[0] * helper[2],
                          n[0] * helper[1] - n[1] * helper[0]};
  const double norm = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  for (double& x : u) x /= norm;
  const std::array<double, 3> v{n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2],
                                n[0] * u[1] - n[1] * u[0]};
  constexpr std::array<std::array<double, 2>, 4> kSigns{{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};
  std::array<std::array<double, 3>, 4> corners{};
  for (std::size_t k = 0; k < 4; ++k) {
    for (std::size_t a = 0; a < 3; ++a) {
      corners[k][a] = wall.point[a] + wall.half_width * (kSigns[k][0] * u[a] + kSigns[k][1] * v[a]);
    }
  }
  return corners;
}

std::string wall_stl(const Wall& wall) {
  const auto c = plane_square(wall);
  std::string out = "solid corlab_wall\n";
  for (const auto& tri :
       {std::array<std::size_t, 3>{0, 1, 2}, std::array<std::size_t, 3>{0, 2, 3}}) {
    out += fmt::format("facet normal {:.17g} {:.17g} {:.17g}\nouter loop\n", wall.normal[0],
                       wall.normal[1], wall.normal[2]);
    for (const std::size_t k : tri) {
      out += fmt::format("vertex {:.17g} {:.17g} {:.17g}\n", c[k][0], c[k][1], c[k][2]);
    }
    out += "endloop\nendfacet\n";
  }
  return out + "endsolid corlab_wall\n";
}

std::vector<std::pair<std::string, std::string>> wall_meshes(const ExportSpec& spec) {
  std::vector<std::pair<std::string, std::string>> out;
  const auto walls = export_walls(spec);
  for (std::size_t k = 0; k < walls.size(); ++k) {
    if (walls[k].shape == WallShape::plane && plane_axis(walls[k]) < 0) {
      out.emplace_back(fmt::format("corlab_wall{}.stl", k + 1), wall_stl(walls[k]));
    }
  }
  return out;
}

void add_wall(ExportSpec& spec, std::string_view text) {
  const auto at = text.rfind('@');
  Wall w = at == std::string_view::npos ? Wall{} : parse_wall_shape(text.substr(at + 1));
  LabelledMaterial m =
      parse_labelled_material(at == std::string_view::npos ? text : text.substr(0, at), "wall");
  if (!spec.wall) {
    spec.wall = m.material;
    if (m.label_given) spec.wall_label = m.label;
    w.material = 0;
  } else {
    const int n = static_cast<int>(spec.extra_walls.size());
    w.material = -1;
    for (int k = 0; k <= n && !m.label.empty(); ++k) {
      if (wall_label(spec, k) != m.label) continue;
      const Material& seen =
          k == 0 ? *spec.wall : spec.extra_walls[static_cast<std::size_t>(k - 1)].material;
      if (!same_material(seen, m.material)) {
        throw_invalid("wall", std::string(text),
                      fmt::format("the material of wall {} as given before (one label, one "
                                  "material; LABEL=MATERIAL for another)",
                                  m.label));
      }
      w.material = k;
    }
    if (w.material < 0) {
      spec.extra_walls.push_back(std::move(m));
      w.material = n + 1;
    }
  }
  spec.walls.push_back(w);
}

std::vector<Wall> export_walls(const ExportSpec& spec) {
  if (!spec.walls.empty()) return spec.walls;
  if (spec.wall) return {Wall{}};
  return {};
}

std::vector<PairCalibration> calibrate_export(const ExportSpec& spec) {
  detail::validate_export_spec(spec);
  std::vector<PairCalibration> pairs = calibrate_pairs(one_wall(spec, 0));
  for (int k = 1; k <= static_cast<int>(spec.extra_walls.size()); ++k) {
    for (auto& p : calibrate_pairs(one_wall(spec, k))) {
      p.wall = k;
      pairs.push_back(std::move(p));
    }
  }
  for (auto& p : pairs) {
    p.friction = detail::pair_friction(spec, p.type_i, p.type_j == 0 ? -p.wall : p.type_j)
                     .value_or(spec.friction);
  }
  return pairs;
}

namespace detail {

void validate_walls(const ExportSpec& spec) {
  if (!spec.walls.empty() && !spec.wall) throw_invalid("walls", 1.0, "a wall material (--wall)");
  for (const auto& m : spec.extra_walls) validate(m.material, "wall");
  const auto n = static_cast<int>(spec.extra_walls.size());
  for (const Wall& w : spec.walls) {
    if (w.material < 0 || w.material > n) {
      throw_invalid("wall material", w.material, fmt::format("in [0, {}]", n));
    }
    const auto finite = [](const auto& xs) {
      return std::all_of(xs.begin(), xs.end(), [](double x) { return std::isfinite(x); });
    };
    if (!finite(w.point) || !finite(w.normal) || !finite(w.centre) || !std::isfinite(w.radius) ||
        !std::isfinite(w.lo) || !std::isfinite(w.hi) || !std::isfinite(w.half_width)) {
      throw_invalid("wall shape", 0.0, "finite numbers");
    }
  }
}

}  // namespace detail
}  // namespace corlab::dem
