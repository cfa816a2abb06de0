// The YADE fragment of a DEM export (Python: materials, en per material pair, the e(v) hook).
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "corlab/dem/dem_export.hpp"
#include "corlab/dem/tangential.hpp"
#include "dem/detail/export_spec.hpp"
#include "dem/detail/export_text.hpp"
#include "dem/detail/script_text.hpp"

namespace corlab::dem {
namespace {

// The Python name of a type's material (type >= 1) or of wall material -type (type <= 0):
// corlab_mat1, ..., corlab_wall_mat, corlab_wall_mat2, ...
std::string material_name(int type) {
  if (type > 0) return fmt::format("corlab_mat{}", type);
  return type == 0 ? std::string("corlab_wall_mat") : fmt::format("corlab_wall_mat{}", 1 - type);
}

// The YADE material code of a pair's second body: its type, or minus its wall material.
int second_code(const PairCalibration& p) { return p.type_j == 0 ? -p.wall : p.type_j; }

// The bodies of one wall (Python lines): utils.wall for an axis-aligned plane (the particles'
// side only), two facets for the square of an oblique plane, facetCylinder (48 sides, no ends)
// for a cylinder.
std::string wall_bodies(const Wall& w, const std::string& material) {
  if (w.shape == WallShape::cylinder) {
    std::array<double, 3> centre{};
    std::size_t c = 0;
    for (std::size_t a = 0; a < 3; ++a) {
      centre[a] = static_cast<int>(a) == w.axis ? 0.5 * (w.lo + w.hi) : w.centre[c++];
    }
    constexpr std::array<std::string_view, 3> kTurn{
        "Quaternion((0, 1, 0), pi / 2)", "Quaternion((1, 0, 0), -pi / 2)", "Quaternion.Identity"};
    return fmt::format(
        "corlab_walls += O.bodies.append(geom.facetCylinder(({:.17g}, {:.17g}, {:.17g}), "
        "{:.17g}, {:.17g}, orientation={}, segmentsNumber=48, wallMask=4, material={}))\n",
        centre[0], centre[1], centre[2], w.radius, w.hi - w.lo,
        kTurn[static_cast<std::size_t>(w.axis)], material);
  }
  const int axis = plane_axis(w);
  if (axis >= 0) {
    const auto a = static_cast<std::size_t>(axis);
    return fmt::format(
        "corlab_walls.append(O.bodies.append(utils.wall({:.17g}, axis={}, sense={}, "
        "material={})))\n",
        w.point[a], axis, w.normal[a] > 0.0 ? 1 : -1, material);
  }
  std::array<std::string, 4> corner;
  const auto square = plane_square(w);
  for (std::size_t k = 0; k < 4; ++k) {
    corner[k] =
        fmt::format("({:.17g}, {:.17g}, {:.17g})", square[k][0], square[k][1], square[k][2]);
  }
  return fmt::format(
      "corlab_walls.append(O.bodies.append(utils.facet([{0}, {1}, {2}], material={4})))\n"
      "corlab_walls.append(O.bodies.append(utils.facet([{0}, {2}, {3}], material={4})))\n",
      corner[0], corner[1], corner[2], corner[3], material);
}

// frictionAngle = atan(mu) [rad] of the export's mu (each pair's own: corlab_ip2.frictAngle).
std::string material_line(const std::string& var,
                          int type,
                          const Material& m,
                          const std::string& label,
                          double friction) {
  return fmt::format(
      "{0} = O.materials.append(FrictMat(young={1:.10g}, poisson={2:.6g}, density={3:.8g}, "
      "frictionAngle={6:.17g}, label={4}))\ncorlab_type_of_material[{0}] = {5}\n",
      var, m.youngs_modulus, m.poisson_ratio, m.density, detail::python_string(label), type,
      std::atan(friction));
}

// The header's paragraph on the tangential part.
std::string tangential_comment(const ExportSpec& spec) {
  std::string out;
  if (spec.rolling > 0.0) {
    out = fmt::format(
        "# Rolling resistance (--rolling {:.6g}): corlab_law2 with includeMoment, corlab_ip2's\n"
        "# eta = mu_r (the bending moment capped at mu_r R F_n) and krot = k_roll R*^2 [N m/rad],\n"
        "# one value for all pairs: the softest pair's (k_roll as LAMMPS's `rolling sds`).\n",
        spec.rolling);
  }
  if (!detail::has_friction(spec)) return out + std::string(kFrictionlessComment);
  return out + fmt::format(
                   "# Tangential (--friction {}): frictionAngle = atan(mu) per pair "
                   "(corlab_ip2.frictAngle); MindlinPhys's shear stiffness\n"
                   "# k_s = kso sqrt(u_N), kso = 8 G* sqrt(R) (Mindlin's; 1/G* = (2-nu_1)/G_1 + "
                   "(2-nu_2)/G_2),\n"
                   "# and es = en (the tangential dashpot at the normal damping ratio). YADE's Box "
                   "and Wall\n"
                   "# contacts take R = r/2, not r, in kn and ks alike (measured from kno): their "
                   "ratio is\n"
                   "# Mindlin's; by Hertz (t_c ~ R^(-1/5)) the contact lasts 2^(1/5) = 1.15 times "
                   "longer\n"
                   "# (docs/theory/dem_contact_laws.md).\n",
                   detail::friction_words(spec));
}

// The end of the e(v) tables, then the hook (Python): the normal and gap of a forming contact and
// the PyRunner callback that sets en per material pair.
constexpr std::string_view kHookFunctions = R"(}
def corlab_normal_gap(b1, b2):
    # Unit normal from b1 to b2 and the gap [m] (< 0: overlap), or None for other shapes.
    s1, s2 = b1.shape, b2.shape
    if not isinstance(s2, Sphere):
        if not isinstance(s1, Sphere):
            return None
        found = corlab_normal_gap(b2, b1)
        return None if found is None else (-found[0], found[1])
    c = b2.state.pos
    if isinstance(s1, Sphere):
        d = c - b1.state.pos
        return d / d.norm(), d.norm() - s1.radius - s2.radius
    if isinstance(s1, Box):
        lo, hi = b1.state.pos - s1.extents, b1.state.pos + s1.extents
        d = c - Vector3(*[min(max(c[k], lo[k]), hi[k]) for k in range(3)])
        return d / d.norm(), d.norm() - s2.radius
    if isinstance(s1, Wall):
        n = Vector3.Zero
        side = c[s1.axis] - b1.state.pos[s1.axis]
        n[s1.axis] = 1.0 if side > 0 else -1.0
        return n, abs(side) - s2.radius
    if isinstance(s1, Facet):
        n = b1.state.ori * s1.normal
        side = (c - b1.state.pos).dot(n)
        return (n if side > 0 else -n), abs(side) - s2.radius
    return None
def corlab_set_en():
    chosen = {}
    for i in O.interactions.all():
        if i.isReal:
            continue
        b1, b2 = O.bodies[i.id1], O.bodies[i.id2]
        t1 = corlab_type_of_material.get(b1.material.id)
        t2 = corlab_type_of_material.get(b2.material.id)
        found = None if t1 is None or t2 is None else corlab_normal_gap(b1, b2)
        if found is None:
            continue
        n, gap = found
        speed = (b1.state.vel - b2.state.vel).dot(n)
        key = (max(t1, t2), min(t1, t2)) if min(t1, t2) <= 0 else (min(t1, t2), max(t1, t2))
        if speed <= 0 or key not in corlab_ev:
            continue
        when = gap / speed
        if key not in chosen or when < chosen[key][0]:
            chosen[key] = (when, speed)
    if not chosen:
        return
    for k, entry in enumerate(corlab_en):
        t1 = corlab_type_of_material[entry[0]]
        t2 = corlab_type_of_material[entry[1]]
        key = (max(t1, t2), min(t1, t2)) if min(t1, t2) <= 0 else (min(t1, t2), max(t1, t2))
        if key in chosen:
            vs, es = corlab_ev[key]
            corlab_en[k] = (entry[0], entry[1], float(numpy.interp(chosen[key][1], vs, es)))
    corlab_ip2.en = MatchMaker(matches=corlab_en)
)";

}  // namespace

double yade_delivered_e(double en) {
  // (en, e) measured with the constant-e drop test of dem_yade_check.py (steel sphere on a steel
  // wall at 0.1 m/s; the same e to 1e-5 for aluminium spheres at 0.3 m/s and at a 16 times
  // smaller step, so a property of YADE's en mapping, not of the step or the pair).
  static constexpr std::array<std::array<double, 2>, 10> kMeasured{{{0.85, 0.84990},
                                                                    {0.90, 0.89993},
                                                                    {0.92, 0.91973},
                                                                    {0.94, 0.93893},
                                                                    {0.96, 0.95680},
                                                                    {0.97, 0.96494},
                                                                    {0.98, 0.97237},
                                                                    {0.99, 0.97895},
                                                                    {0.995, 0.98189},
                                                                    {0.999, 0.98407}}};
  if (en >= 1.0 || en <= kMeasured.front()[0]) return en;
  if (en >= kMeasured.back()[0]) return kMeasured.back()[1];
  std::size_t k = 1;
  while (kMeasured[k][0] < en) ++k;
  const double w = (en - kMeasured[k - 1][0]) / (kMeasured[k][0] - kMeasured[k - 1][0]);
  return kMeasured[k - 1][1] + w * (kMeasured[k][1] - kMeasured[k - 1][1]);
}

Delivery yade_delivery(const ExportSpec& spec, const PairCalibration& pair) {
  Delivery d{CodeLaw::yade_mindlin,
             pair.constant ? "Hertz-Mindlin en" : "Hertz-Mindlin en set by corlab's hook",
             pair.constant ? 0.0 : detail::hook_table_error(spec, pair, false),
             {}};
  double mapping = 0.0;
  for (const double e : pair.best_constant->target) {
    d.law_e.push_back(yade_delivered_e(e));
    mapping = std::max(mapping, std::abs(d.law_e.back() - e));
  }
  d.max_abs_error += mapping;
  return d;
}

double yade_time_step(const std::vector<PairCalibration>& pairs) {
  return detail::recommended_step(pairs,
                                  [](const PairCalibration&) { return CodeLaw::yade_mindlin; });
}

namespace {

// The imports and one FrictMat per type and wall material (frictionAngle: the export's mu).
std::string materials(const ExportSpec& spec) {
  std::string out;
  out +=
      "from yade import *\nfrom yade import geom, utils\nfrom math import pi\nimport numpy\n"
      "corlab_type_of_material = {}\n";
  for (std::size_t i = 0; i < spec.types.size(); ++i) {
    const int id = static_cast<int>(i) + 1;
    out += material_line(material_name(id), id, spec.types[i].material, type_label(spec, id),
                         spec.friction);
  }
  if (spec.wall) {
    out += material_line(material_name(0), 0, *spec.wall, wall_label(spec), spec.friction);
  }
  for (std::size_t k = 0; k < spec.extra_walls.size(); ++k) {
    const int code = -static_cast<int>(k) - 1;
    out += material_line(material_name(code), code, spec.extra_walls[k].material,
                         wall_label(spec, static_cast<int>(k) + 1), spec.friction);
  }
  return out;
}

// corlab_ip2 (en and frictAngle per material pair, rolling), corlab_law2 and the functors.
std::string interaction_physics(const ExportSpec& spec, const std::vector<PairCalibration>& pairs) {
  std::string out;
  std::vector<std::string> matches;
  std::vector<std::string> angles;
  for (int i = 1; spec.wall_only && i <= static_cast<int>(spec.types.size()); ++i) {
    for (int j = i; j <= static_cast<int>(spec.types.size()); ++j) {  // not calibrated: elastic
      matches.push_back(fmt::format("({}, {}, 1.0)", material_name(i), material_name(j)));
      angles.push_back(
          fmt::format("({}, {}, {:.17g})", material_name(i), material_name(j),
                      std::atan(detail::pair_friction(spec, i, j).value_or(spec.friction))));
    }
  }
  for (const auto& p : pairs) {
    const std::string a = material_name(p.type_i);
    const std::string b = material_name(second_code(p));
    matches.push_back(
        fmt::format("({}, {}, {:.8g})", a, b, p.constant ? *p.constant : p.curve(spec.v_min)));
    angles.push_back(fmt::format("({}, {}, {:.17g})", a, b, std::atan(p.friction)));
  }
  out += fmt::format(
      "corlab_en = [{}]\ncorlab_ip2 = Ip2_FrictMat_FrictMat_MindlinPhys(en=MatchMaker(matches="
      "corlab_en), frictAngle=MatchMaker(matches=[{}]))\n",
      fmt::join(matches, ", "), fmt::join(angles, ", "));
  if (spec.rolling > 0.0) {
    double krot = std::numeric_limits<double>::infinity();
    for (const auto& p : pairs) {
      krot =
          std::min(krot, detail::rolling_stiffness(p.effective_modulus, p.effective_radius,
                                                   p.effective_mass, p.shear_modulus, spec.v_max) *
                             p.effective_radius * p.effective_radius);
    }
    out += fmt::format("corlab_ip2.eta = {:.17g}\ncorlab_ip2.krot = {:.17g}\n", spec.rolling, krot);
  }
  out += fmt::format(
      "corlab_law2 = Law2_ScGeom_MindlinPhys_Mindlin(includeMoment={})\n"
      "# The functors the walls below need, for O.engines (see docs/user/dem.md):\n"
      "corlab_bound = [Bo1_Sphere_Aabb(), Bo1_Box_Aabb(), Bo1_Wall_Aabb(), Bo1_Facet_Aabb()]\n"
      "corlab_ig2 = [Ig2_Sphere_Sphere_ScGeom(), Ig2_Box_Sphere_ScGeom(), "
      "Ig2_Wall_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()]\n",
      spec.rolling > 0.0 ? "True" : "False");
  return out;
}

}  // namespace

std::string write_yade(const ExportSpec& spec, const std::vector<PairCalibration>& pairs) {
  std::string out =
      detail::export_header(spec, "YADE (2023.02a), Python: exec() it in a YADE script");
  out +=
      "# Hertz-Mindlin: Ip2_FrictMat_FrictMat_MindlinPhys maps en to its damping exactly for\n"
      "# Hertz up to en = 0.9 (measured: 0.3 -> 0.3001, 0.9 -> 0.89993) but falls short above\n"
      "# (0.96 -> 0.9568, 0.99 -> 0.9790, 0.999 -> 0.9841; en = 1: elastic): the stated max |de|\n"
      "# includes that. Use corlab_ip2 and corlab_law2 in the InteractionLoop; en is per\n"
      "# material pair (MatchMaker).\n";
  out += tangential_comment(spec);
  const bool hook =
      std::any_of(pairs.begin(), pairs.end(), [](const auto& p) { return !p.constant; });
  out += "# Type pairs and the target:\n";
  for (const auto& p : pairs) {
    out += fmt::format("# {}: {}; {}, max |de| {:.1e}\n", p.name(), p.target,
                       p.constant ? "en" : "the hook (table interpolation)",
                       yade_delivery(spec, p).max_abs_error);
  }
  out += materials(spec);
  out += interaction_physics(spec, pairs);
  out +=
      "# The walls (fixed bodies of the wall materials); their ids in corlab_walls.\ncorlab_walls "
      "= []\n";
  for (const Wall& w : export_walls(spec)) {
    out += fmt::format("# {}\n", wall_label(spec, w.material));
    out += wall_bodies(w, material_name(-w.material));
  }
  const auto law = [](const PairCalibration&) { return CodeLaw::yade_mindlin; };
  out += detail::time_step_comment(spec, pairs, law);
  out += fmt::format("O.dt = {:.4g}\n", detail::recommended_step(pairs, law));
  if (!hook) return out;
  out +=
      "# e(v): add PyRunner(command='corlab_set_en()', iterPeriod=1) to O.engines just before\n"
      "# the InteractionLoop. For each material pair it sets en from the NORMAL approach speed of\n"
      "# the contact of that pair closest to touching (e(v) tables below, linear in v, end values\n"
      "# outside): exact unless two contacts of the same material pair form in one step at\n"
      "# different speeds (then the first to touch sets both). Shapes: Sphere, Box (not rotated),\n"
      "# Wall; other shapes keep the last en of their pair.\ncorlab_ev = {\n";
  for (const auto& p : pairs) {
    std::vector<std::string> vs;
    std::vector<std::string> es;
    for (const double v : detail::table_speeds(spec, detail::kHookTableRows)) {
      vs.push_back(fmt::format("{:.8g}", v));
      es.push_back(fmt::format("{:.8g}", p.curve(v)));
    }
    out += fmt::format("    ({}, {}): ([{}], [{}]),\n", p.type_i, second_code(p),
                       fmt::join(vs, ", "), fmt::join(es, ", "));
  }
  out += kHookFunctions;
  return out;
}

}  // namespace corlab::dem
