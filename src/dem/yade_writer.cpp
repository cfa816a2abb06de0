// The YADE fragment of a DEM export (Python: materials, en per material pair, the e(v) hook).
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "corlab/dem/dem_export.hpp"
#include "corlab/dem/tangential.hpp"
#include "dem/detail/export_text.hpp"
#include "dem/detail/script_text.hpp"

namespace corlab::dem {
namespace {

std::string material_name(int type) {
  return type == 0 ? std::string("corlab_wall_mat") : fmt::format("corlab_mat{}", type);
}

// frictionAngle = atan(mu) [rad] (YADE takes the smaller of the two materials').
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
  if (spec.friction <= 0.0) return std::string(kFrictionlessComment);
  return fmt::format(
      "# Tangential (--friction {:.6g}): frictionAngle = atan(mu); MindlinPhys's shear stiffness\n"
      "# k_s = kso sqrt(u_N), kso = 8 G* sqrt(R) (Mindlin's; 1/G* = (2-nu_1)/G_1 + (2-nu_2)/G_2),\n"
      "# and es = en (the tangential dashpot at the normal damping ratio). YADE's Box and Wall\n"
      "# contacts take R = r/2, not r, in kn and ks alike (measured from kno): their ratio is\n"
      "# Mindlin's; by Hertz (t_c ~ R^(-1/5)) the contact lasts 2^(1/5) = 1.15 times longer\n"
      "# (docs/theory/dem_contact_laws.md).\n",
      spec.friction);
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
        key = (max(t1, t2), 0) if min(t1, t2) == 0 else (min(t1, t2), max(t1, t2))
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
        key = (max(t1, t2), 0) if min(t1, t2) == 0 else (min(t1, t2), max(t1, t2))
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

std::string write_yade(const ExportSpec& spec, const std::vector<PairCalibration>& pairs) {
  std::string out =
      detail::export_header(spec, "YADE (2023.02a), Python: exec() it in a YADE script");
  out +=
      "# Hertz-Mindlin: Ip2_FrictMat_FrictMat_MindlinPhys maps en to its damping exactly for\n"
      "# Hertz up to en = 0.9 (measured: 0.3 -> 0.3001, 0.9 -> 0.89993) but falls short above\n"
      "# (0.96 -> 0.9568, 0.99 -> 0.9790, 0.999 -> 0.9841; en = 1: elastic): the stated max |de|\n"
      "# includes that. Use corlab_ip2 in the InteractionLoop\n"
      "# with Law2_ScGeom_MindlinPhys_Mindlin(); en is per material pair (MatchMaker).\n";
  out += tangential_comment(spec);
  const bool hook =
      std::any_of(pairs.begin(), pairs.end(), [](const auto& p) { return !p.constant; });
  out += "# Type pairs and the target:\n";
  for (const auto& p : pairs) {
    out += fmt::format("# {}: {}; {}, max |de| {:.1e}\n", p.name(), p.target,
                       p.constant ? "en" : "the hook (table interpolation)",
                       yade_delivery(spec, p).max_abs_error);
  }
  out += "from yade import *\nimport numpy\ncorlab_type_of_material = {}\n";
  for (std::size_t i = 0; i < spec.types.size(); ++i) {
    const int id = static_cast<int>(i) + 1;
    out += material_line(material_name(id), id, spec.types[i].material, type_label(spec, id),
                         spec.friction);
  }
  if (spec.wall) {
    out += material_line(material_name(0), 0, *spec.wall, wall_label(spec), spec.friction);
  }
  std::vector<std::string> matches;
  for (int i = 1; spec.wall_only && i <= static_cast<int>(spec.types.size()); ++i) {
    for (int j = i; j <= static_cast<int>(spec.types.size()); ++j) {  // not calibrated: elastic
      matches.push_back(fmt::format("({}, {}, 1.0)", material_name(i), material_name(j)));
    }
  }
  for (const auto& p : pairs) {
    matches.push_back(fmt::format("({}, {}, {:.8g})", material_name(p.type_i),
                                  material_name(p.type_j),
                                  p.constant ? *p.constant : p.curve(spec.v_min)));
  }
  out += fmt::format(
      "corlab_en = [{}]\ncorlab_ip2 = Ip2_FrictMat_FrictMat_MindlinPhys(en=MatchMaker(matches="
      "corlab_en))\n",
      fmt::join(matches, ", "));
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
    out += fmt::format("    ({}, {}): ([{}], [{}]),\n", p.type_i, p.type_j, fmt::join(vs, ", "),
                       fmt::join(es, ", "));
  }
  out += kHookFunctions;
  return out;
}

}  // namespace corlab::dem
