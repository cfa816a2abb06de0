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

// The hook's margin: sphere-sphere and sphere-Box interactions are made at a gap of
// kHookMargin (r_1 + r_2), sphere-Wall ones by the hook below kHookMargin r_min [-].
constexpr double kHookMargin = 0.1;

// The hook's helpers (Python, before corlab_ip2): the damping ratio beta_n that YADE's
// Ip2_FrictMat_FrictMat_MindlinPhys gives en = e (Thornton et al. 2013, Eqs. B6-B7, Table 2, as
// YADE 2023.02a computes it; es = en gives beta_s = beta_n), and each material pair's type key.
// Its Law2 damps by c_n = 2 beta_n sqrt(m* k_n) (c_s alike): the dashpot of en, which a PyRunner
// can set per contact (betan, betas of its MindlinPhys).
constexpr std::string_view kHookHelpers = R"(def corlab_beta(e):
    # beta_n [-] of en = e (1: none)
    if e >= 1.0:
        return 0.0
    a = 0.0
    for h in (-1489.915, 6276.757, -11342.18, 11494.29, -7206.864, 2928.711, -796.4559,
              146.8049, -16.41105, -6.918798):
        a = a * e + h
    return math.sqrt(1.0 / (1.0 - (1.0 + e) ** 2 * math.exp(a * e)) - 1.0)
def corlab_key(a, b):
    t1, t2 = corlab_type_of_material[a], corlab_type_of_material[b]
    return (max(t1, t2), min(t1, t2)) if min(t1, t2) <= 0 else (min(t1, t2), max(t1, t2))
corlab_betan = [(a, b, corlab_beta(e)) for a, b, e in corlab_en]
)";

// The end of the e(v) tables, then the hook (Python): the PyRunner corlab_hook visits every
// corlab_every steps and sets each contact's damping once, before it touches.
constexpr std::string_view kHookFunctions = R"(}
corlab_keys = {}
for a, b, _ in corlab_en:
    if corlab_key(a, b) in corlab_ev:
        corlab_keys[(a, b)] = corlab_keys[(b, a)] = corlab_key(a, b)
corlab_missed = 0
corlab_last_visit = -1
def corlab_e(key, speed):
    # e(v) of the pair's table, linear in v, the end values outside
    vs, es = corlab_ev[key]
    j = bisect.bisect_right(vs, speed)
    if j == 0 or j == len(vs):
        return es[min(j, len(vs) - 1)]
    return es[j - 1] + (speed - vs[j - 1]) * (es[j] - es[j - 1]) / (vs[j] - vs[j - 1])
def corlab_set(i, key, b1, b2):
    # the damping of a contact not yet touching, from its normal approach speed now
    p = i.phys
    p.betan = p.betas = corlab_beta(corlab_e(key, (b1.state.vel - b2.state.vel).dot(i.geom.normal)))
    p.shearElastic = p.usElastic = p.usTotal = p.momentBend = p.momentTwist = Vector3.Zero
def corlab_wall_gap(w, s):
    # unit normal from wall w to sphere s and the gap [m] (Wall, or a facet's plane)
    c = s.state.pos
    if isinstance(w.shape, Wall):
        n = Vector3.Zero
        side = c[w.shape.axis] - w.state.pos[w.shape.axis]
        n[w.shape.axis] = 1.0 if side > 0 else -1.0
        return n, abs(side) - s.shape.radius
    n = w.state.ori * w.shape.normal
    side = (c - w.state.pos).dot(n)
    return (n if side > 0 else -n), abs(side) - s.shape.radius
def corlab_visit():
    global corlab_missed, corlab_last_visit
    soonest = {}
    for w in corlab_walls:  # wall contacts within corlab_margin: made now (erased walls: None)
        for i in O.interactions.withBodyAll(w) if O.bodies[w] is not None else ():
            if i.isReal:
                continue
            b1, b2 = O.bodies[i.id1], O.bodies[i.id2]
            key = corlab_keys.get((b1.material.id, b2.material.id))
            if key is None or not isinstance((b2 if i.id1 == w else b1).shape, Sphere):
                continue
            wall, ball = (b1, b2) if i.id1 == w else (b2, b1)
            n, gap = corlab_wall_gap(wall, ball)
            if gap >= corlab_margin:
                continue
            if isinstance(wall.shape, Facet):  # YADE makes facet contacts only when touching
                speed = -ball.state.vel.dot(n)
                if speed > 0 and (key not in soonest or gap / speed < soonest[key][0]):
                    soonest[key] = (gap / speed, speed)
                continue
            j = utils.createInteraction(i.id1, i.id2)
            corlab_set(j, key, O.bodies[j.id1], O.bodies[j.id2])
    for i in O.interactions.all(True):
        depth = i.geom.penetrationDepth
        if depth >= 0:
            if i.iterMadeReal > corlab_last_visit:  # touched before a visit prepared it
                b1, b2 = O.bodies[i.id1], O.bodies[i.id2]
                if ((b1.material.id, b2.material.id) in corlab_keys
                        and not isinstance(b1.shape, Facet) and not isinstance(b2.shape, Facet)):
                    corlab_missed += 1
            continue
        b1, b2 = O.bodies[i.id1], O.bodies[i.id2]
        key = corlab_keys.get((b1.material.id, b2.material.id))
        if key is None:
            continue
        if -depth > corlab_erase_gap:
            O.interactions.erase(i.id1, i.id2)
        else:
            corlab_set(i, key, b1, b2)
    corlab_last_visit = O.iter
    if soonest:
        for k, (a, b, _) in enumerate(corlab_betan):
            key = corlab_key(a, b)
            if key in soonest:
                corlab_betan[k] = (a, b, corlab_beta(corlab_e(key, soonest[key][1])))
        corlab_ip2.betan = MatchMaker(matches=corlab_betan)
corlab_hook = PyRunner(command='corlab_visit()', iterPeriod=corlab_every, initRun=True)
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
std::string materials(const ExportSpec& spec, bool hook) {
  std::string out;
  out +=
      "from yade import *\nfrom yade import geom, utils\nfrom math import pi\nimport numpy\n"
      "corlab_type_of_material = {}\n";
  if (hook) out += "import bisect\nimport math\n";
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

// corlab_ip2 (en and frictAngle per material pair, rolling), corlab_law2 and the functors. With
// the hook: betan and betas per material pair instead of en (the same dashpot, kHookHelpers; an
// e(v) pair's is e(v_max), for a contact the hook did not prepare), interactions kept apart
// (neverErase: the hook makes and erases them) and spheres' interactions made at a gap of
// kHookMargin (r_1 + r_2) (the Sphere and Box functors' interactionDetectionFactor).
std::string interaction_physics(const ExportSpec& spec,
                                const std::vector<PairCalibration>& pairs,
                                bool hook) {
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
        fmt::format("({}, {}, {:.8g})", a, b,
                    p.constant ? *p.constant : p.curve(hook ? spec.v_max : spec.v_min)));
    angles.push_back(fmt::format("({}, {}, {:.17g})", a, b, std::atan(p.friction)));
  }
  out += fmt::format("corlab_en = [{}]\n", fmt::join(matches, ", "));
  if (hook) out += kHookHelpers;
  out += fmt::format(
      "corlab_ip2 = Ip2_FrictMat_FrictMat_MindlinPhys({}, frictAngle=MatchMaker(matches=[{}]))\n",
      hook ? "betan=MatchMaker(matches=corlab_betan)" : "en=MatchMaker(matches=corlab_en)",
      fmt::join(angles, ", "));
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
  const auto factor = [hook](std::string_view name) {
    return hook ? fmt::format("{}={:g}", name, 1.0 + kHookMargin) : std::string();
  };
  out += fmt::format(
      "corlab_law2 = Law2_ScGeom_MindlinPhys_Mindlin(includeMoment={}{})\n"
      "# The functors the walls below need, for O.engines (see docs/user/dem.md):\n"
      "corlab_bound = [Bo1_Sphere_Aabb({}), Bo1_Box_Aabb(), Bo1_Wall_Aabb(), Bo1_Facet_Aabb()]\n"
      "corlab_ig2 = [Ig2_Sphere_Sphere_ScGeom({}), Ig2_Box_Sphere_ScGeom({}), "
      "Ig2_Wall_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()]\n",
      spec.rolling > 0.0 ? "True" : "False", hook ? ", neverErase=True" : "",
      factor("aabbEnlargeFactor"), factor("interactionDetectionFactor"),
      factor("interactionDetectionFactor"));
  return out;
}

// The hook's comment and numbers: corlab_margin [m], corlab_erase_gap [m], corlab_every [steps]
// (the margin closed at 2 v_max, at most half the shortest contact), then the e(v) tables' start.
std::string hook_comment(const ExportSpec& spec,
                         const std::vector<PairCalibration>& pairs,
                         double dt) {
  double r_min = std::numeric_limits<double>::infinity();
  double r_max = 0.0;
  for (const auto& t : spec.types) {
    r_min = std::min(r_min, t.radius);
    r_max = std::max(r_max, t.radius);
  }
  double shortest = std::numeric_limits<double>::infinity();
  for (const auto& p : pairs) shortest = std::min(shortest, p.contact_time_fast);
  const double margin = kHookMargin * r_min;
  const double every = std::clamp(std::floor(margin / (2.0 * spec.v_max * dt)), 1.0,
                                  std::floor(0.5 * shortest / dt));
  return fmt::format(
      "# e(v): put corlab_hook (a PyRunner) in O.engines just after the InteractionLoop. Every\n"
      "# corlab_every steps it gives each contact of a pair below that is not touching yet the\n"
      "# damping of e(v_n), v_n its normal approach speed then (tables below, linear in v, end\n"
      "# values outside): per contact, set once before it touches. Sphere-sphere and sphere-Box\n"
      "# interactions are made at a gap of {0:g} (r_1 + r_2) (interactionDetectionFactor),\n"
      "# sphere-Wall ones by the hook below corlab_margin = {0:g} r_min; corlab_every is the "
      "steps\n"
      "# in which 2 v_max closes corlab_margin, at most half the shortest contact: a contact\n"
      "# approaching at up to 2 v_max is set before it touches and none starts and ends unseen.\n"
      "# One that touches unset (faster, or inserted within the margin) keeps e(v_max) and adds 1\n"
      "# to corlab_missed. Facets (oblique planes, the cylinder) make contacts only on touching:\n"
      "# there the hook sets the wall material pair's betan from its facet contact closest to\n"
      "# touching (one e per pair and visit). Interactions stay after separation (neverErase)\n"
      "# until corlab_erase_gap apart; one touching again before the next visit keeps its e.\n"
      "corlab_margin = {1:.17g}\ncorlab_erase_gap = {2:.17g}\ncorlab_every = {3:.0f}\n"
      "corlab_ev = {{\n",
      kHookMargin, margin, 2.0 * kHookMargin * r_max, every);
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
  const bool hook =
      std::any_of(pairs.begin(), pairs.end(), [](const auto& p) { return !p.constant; });
  if (hook) {
    out +=
        "# e(v): corlab_ip2 takes YADE's damping ratio betan of each en (the same dashpot),\n"
        "# and corlab_hook (below) sets each contact's own before it touches.\n";
  }
  out += tangential_comment(spec);
  out += "# Type pairs and the target:\n";
  for (const auto& p : pairs) {
    out += fmt::format("# {}: {}; {}, max |de| {:.1e}\n", p.name(), p.target,
                       p.constant ? "en" : "the hook (table interpolation)",
                       yade_delivery(spec, p).max_abs_error);
  }
  out += materials(spec, hook);
  out += interaction_physics(spec, pairs, hook);
  out +=
      "# The walls (fixed bodies of the wall materials); their ids in corlab_walls.\ncorlab_walls "
      "= []\n";
  for (const Wall& w : export_walls(spec)) {
    out += fmt::format("# {}\n", wall_label(spec, w.material));
    out += wall_bodies(w, material_name(-w.material));
  }
  const auto law = [](const PairCalibration&) { return CodeLaw::yade_mindlin; };
  out += detail::time_step_comment(spec, pairs, law);
  const double dt = detail::recommended_step(pairs, law);
  out += fmt::format("O.dt = {:.4g}\n", dt);
  if (!hook) return out;
  out += hook_comment(spec, pairs, dt);
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
