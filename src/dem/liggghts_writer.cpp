// The LIGGGHTS 3.8 fragment of a DEM export (pair_style gran, fix wall/gran).
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <functional>
#include <limits>

#include "corlab/dem/dem_export.hpp"
#include "corlab/dem/tangential.hpp"
#include "dem/detail/export_spec.hpp"
#include "dem/detail/export_text.hpp"

namespace corlab::dem {
namespace {

// The wall materials' count (LIGGGHTS atom types after the particle types).
int wall_materials(const ExportSpec& spec) {
  return spec.wall ? 1 + static_cast<int>(spec.extra_walls.size()) : 0;
}

// The pair of LIGGGHTS atom types a, b (particle types 1..n, then one per wall material), or
// nullptr (two walls, or a --wall-only particle pair: elastic, frictionless as the export's mu).
const PairCalibration* atom_type_pair(const ExportSpec& spec,
                                      const std::vector<PairCalibration>& pairs,
                                      int a,
                                      int b) {
  const int n = static_cast<int>(spec.types.size());
  if (a > n && b > n) return nullptr;
  const int t = std::min(a, b);
  const int other = std::max(a, b);
  for (const auto& p : pairs) {
    if (p.type_i != t) continue;
    if (other > n ? (p.type_j == 0 && p.wall == other - n - 1) : p.type_j == other) return &p;
  }
  return nullptr;
}

// youngsModulus and poissonsRatio per atom type (the wall materials last).
std::string elastic_constants(const ExportSpec& spec) {
  std::string young = "fix m1 all property/global youngsModulus peratomtype";
  std::string poisson = "fix m2 all property/global poissonsRatio peratomtype";
  const auto add = [&](const Material& m) {
    young += fmt::format(" {:.10g}", m.youngs_modulus);
    poisson += fmt::format(" {:.6g}", m.poisson_ratio);
  };
  for (const auto& t : spec.types) add(t.material);
  if (spec.wall) add(*spec.wall);
  for (const auto& w : spec.extra_walls) add(w.material);
  return young + "\n" + poisson + "\n";
}

// LIGGGHTS refuses a youngsModulus outside [5e6, 1e9] Pa in SI units unless told: the switch
// for the moduli the export holds.
std::string moduli_switches(const ExportSpec& spec) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = 0.0;
  const auto see = [&](const Material& m) {
    lo = std::min(lo, m.youngs_modulus);
    hi = std::max(hi, m.youngs_modulus);
  };
  for (const auto& t : spec.types) see(t.material);
  if (spec.wall) see(*spec.wall);
  for (const auto& w : spec.extra_walls) see(w.material);
  std::string out;
  if (lo < 5e6) out += "soft_particles yes  # a youngsModulus below 5e6 Pa\n";
  if (hi > 1e9) out += "hard_particles yes  # a youngsModulus above 1e9 Pa\n";
  return out;
}

// A per-type-pair property/global matrix of n atom types: value(pair or nullptr, a, b).
std::string type_pair_matrix(const ExportSpec& spec,
                             const std::vector<PairCalibration>& pairs,
                             std::string_view head,
                             const std::function<double(const PairCalibration*, int, int)>& value) {
  const int n = static_cast<int>(spec.types.size()) + wall_materials(spec);
  std::string out = fmt::format("{} peratomtypepair {}", head, n);
  for (int a = 1; a <= n; ++a) {
    for (int b = 1; b <= n; ++b) {
      out += fmt::format(" {:.8g}", value(atom_type_pair(spec, pairs, a, b), a, b));
    }
  }
  return out + "\n";
}

// The walls: a primitive for an axis-aligned plane or a cylinder, a mesh (the export's
// corlab_wallW.stl) for an oblique plane; `model` the pair style's model words.
std::string wall_fixes(const ExportSpec& spec, const std::string& model) {
  std::string out;
  const auto walls = export_walls(spec);
  const int n = static_cast<int>(spec.types.size());
  for (std::size_t k = 0; k < walls.size(); ++k) {
    const Wall& w = walls[k];
    const int id = static_cast<int>(k) + 1;
    const int type = n + 1 + w.material;
    const char axis =
        static_cast<char>('x' + (w.shape == WallShape::plane ? plane_axis(w) : w.axis));
    out += fmt::format("# wall {}: {} (atom type {})\n", id, wall_label(spec, w.material), type);
    if (w.shape == WallShape::cylinder) {
      out += fmt::format(
          "fix corlab_wall{} all wall/gran {} primitive type {} {}cylinder {:.10g} {:.10g} "
          "{:.10g}\n",
          id, model, type, axis, w.radius, w.centre[0], w.centre[1]);
    } else if (plane_axis(w) >= 0) {
      out += fmt::format("fix corlab_wall{} all wall/gran {} primitive type {} {}plane {:.10g}\n",
                         id, model, type, axis, w.point[static_cast<std::size_t>(plane_axis(w))]);
    } else {
      out += fmt::format(
          "# an oblique plane: the square of half-width {:.6g} m the export wrote as\n"
          "# corlab_wall{}.stl (a path from where LIGGGHTS runs: copy it there or edit it)\n"
          "fix corlab_mesh{} all mesh/surface file corlab_wall{}.stl type {}\n"
          "fix corlab_wall{} all wall/gran {} mesh n_meshes 1 meshes corlab_mesh{}\n",
          w.half_width, id, id, id, type, id, model, id);
    }
  }
  return out;
}

// Why this normal model, and how it maps e.
std::string model_comment(const std::vector<PairCalibration>& pairs, bool tn) {
  std::string out;
  if (tn) {
    out +=
        "# e(v): model thornton_ning without adhesion (surfaceEnergy 0): Hertz until the contact\n"
        "# radius reaches a_y = coefficientYieldRatio r_i, unloading with the loading radius (not\n"
        "# Thornton's R_p); corlab fits the ratio on ODE solutions of exactly that law. The ratio\n"
        "# is per atom type (its wall fit, else its same-type fit), so a type's pairs share it;\n"
        "# model hertz with one constant e per pair would miss the targets by more (below).\n";
  } else {
    out +=
        "# model hertz maps e to the damping 2 sqrt(5/6) |beta| sqrt(S_n m*), beta = ln e/\n"
        "# sqrt(ln^2 e + pi^2): exact for Hertz while the force is not clamped (keep limitForce\n"
        "# off). One constant e per type pair";
    out += std::any_of(pairs.begin(), pairs.end(), [](const auto& p) { return !p.constant; })
               ? ": for an e(v) target the constant closest to it\n# (thornton_ning misses it "
                 "by more, below).\n"
               : ".\n";
  }
  return out;
}

// The header's paragraph on the tangential part.
std::string tangential_comment(const ExportSpec& spec) {
  if (!detail::has_friction(spec)) return std::string(kFrictionlessComment);
  return fmt::format(
      "# Tangential (--friction {}): `tangential history`, LIGGGHTS's own Mindlin stiffness\n"
      "# k_t = 8 G* sqrt(R* delta) from youngsModulus and poissonsRatio (1/G* = 2(2-nu_1)\n"
      "# (1+nu_1)/E_1 + ...), Coulomb coefficientFriction, and its tangential dashpot (the\n"
      "# normal damping ratio with k_t; tangential_damping on).\n",
      detail::friction_words(spec));
}

}  // namespace

Delivery liggghts_delivery(const std::vector<PairCalibration>& pairs, const PairCalibration& pair) {
  if (liggghts_uses_thornton_ning(pairs)) {
    return {CodeLaw::liggghts_thornton_ning,
            "model thornton_ning (yield ratio per type)",
            pair.liggghts_written->max_abs_error,
            {}};
  }
  return {CodeLaw::liggghts_hertz,
          pair.constant ? "model hertz" : "model hertz, the closest constant e",
          pair.best_constant->max_abs_error,
          {}};
}

double liggghts_time_step(const std::vector<PairCalibration>& pairs) {
  const CodeLaw law = liggghts_uses_thornton_ning(pairs) ? CodeLaw::liggghts_thornton_ning
                                                         : CodeLaw::liggghts_hertz;
  return detail::recommended_step(pairs, [law](const PairCalibration&) { return law; });
}

namespace {

// The header: what the fragment needs, the model, the tangential part, each pair's delivery.
std::string header(const ExportSpec& spec, const std::vector<PairCalibration>& pairs, bool tn) {
  std::string out = detail::export_header(spec, "LIGGGHTS 3.8 (pair_style gran)");
  const int types = static_cast<int>(spec.types.size());
  const int n = types + wall_materials(spec);
  out +=
      "# Needs: atom_style granular, communicate single vel yes (it sets soft_particles or\n"
      "# hard_particles where a modulus is outside [5e6, 1e9] Pa); include it after create_box N";
  out += spec.wall
             ? fmt::format(" with N = {} (the wall materials are types {}..{}).\n", n, types + 1, n)
             : fmt::format(" with N = {}.\n", n);
  out +=
      "# Atom types start at 1 (LIGGGHTS refuses others): particle type N of the export is\n"
      "# atom type N.\n";
  out += model_comment(pairs, tn);
  out += tangential_comment(spec);
  out +=
      "# Type pairs, the target and what this fragment delivers (max |de| over the fit speeds):\n";
  for (const auto& p : pairs) {
    const CurveFit& delivered = tn ? *p.liggghts_written : *p.best_constant;
    out += fmt::format("# {}: {}; {} (thornton_ning: {:.2e}, constant: {:.2e})\n", p.name(),
                       p.target, detail::fit_comment(delivered),
                       p.liggghts_written ? p.liggghts_written->max_abs_error : 1.0,
                       p.best_constant->max_abs_error);
  }
  return out;
}

// The yield ratios (coefficientYieldRatio per atom type) and surface energies of thornton_ning.
std::string thornton_ning_properties(const ExportSpec& spec,
                                     const std::vector<PairCalibration>& pairs) {
  std::string out;
  const int n = static_cast<int>(spec.types.size()) + wall_materials(spec);
  std::string ratio = "fix m5 all property/global coefficientYieldRatio peratomtype";
  for (const double r : liggghts_type_ratios(spec, pairs)) ratio += fmt::format(" {:.10g}", r);
  if (spec.wall) {
    out +=
        "# The wall types' own yield ratios are never read (a_y = ratio r_i of the particle),\n"
        "# 1.0 fills their places.\n";
    for (int k = 0; k < wall_materials(spec); ++k) ratio += " 1.0";
  }
  out += ratio + "\n";
  out +=
      fmt::format("fix m6 all property/global surfaceEnergy peratomtypepair {} {}\n", n,
                  fmt::join(std::vector<std::string>(static_cast<std::size_t>(n * n), "0.0"), " "));
  return out;
}

}  // namespace

std::string write_liggghts(const ExportSpec& spec, const std::vector<PairCalibration>& pairs) {
  const bool tn = liggghts_uses_thornton_ning(pairs);
  std::string out = header(spec, pairs, tn);
  out += moduli_switches(spec);
  out += elastic_constants(spec);
  if (tn) {
    out +=
        "# coefficientRestitution: thornton_ning reads it only for tangential damping (zero\n"
        "# here, frictionless); 1.0 keeps it out of the normal force.\n";
  }
  out += type_pair_matrix(spec, pairs, "fix m3 all property/global coefficientRestitution",
                          [tn](const PairCalibration* p, int, int) {
                            if (tn || p == nullptr) return 1.0;
                            return p->constant ? *p->constant : p->best_constant->parameter;
                          });
  const auto mu = [&spec](const PairCalibration* p, int a, int b) {
    if (p != nullptr) return p->friction;
    const int n_types = static_cast<int>(spec.types.size());
    return a <= n_types && b <= n_types
               ? detail::pair_friction(spec, std::min(a, b), std::max(a, b)).value_or(spec.friction)
               : 0.0;
  };
  out += type_pair_matrix(spec, pairs, "fix m4 all property/global coefficientFriction", mu);
  if (tn) out += thornton_ning_properties(spec, pairs);
  std::string words = fmt::format("model {} tangential {}", tn ? "thornton_ning" : "hertz",
                                  detail::has_friction(spec) ? "history" : "no_history");
  if (spec.rolling > 0.0) {
    out +=
        "# Rolling resistance (--rolling): rolling_friction cdt, a constant torque mu_r R* F_n\n"
        "# against the relative rolling (LIGGGHTS's coefficientRollingFriction).\n";
    out += type_pair_matrix(spec, pairs, "fix m7 all property/global coefficientRollingFriction",
                            [&spec](const PairCalibration*, int, int) { return spec.rolling; });
    words += " rolling_friction cdt";
  }
  const double r_min =
      std::min_element(spec.types.begin(), spec.types.end(), [](const auto& a, const auto& b) {
        return a.radius < b.radius;
      })->radius;
  out += fmt::format(
      "# The pair cutoff follows the radii; skin 0.2 r_min.\nneighbor {:.6g} bin\nneigh_modify "
      "delay 0\npair_style gran {}\npair_coeff * *\n",
      0.2 * r_min, words);
  out += wall_fixes(spec, words);
  const auto law = [tn](const PairCalibration&) {
    return tn ? CodeLaw::liggghts_thornton_ning : CodeLaw::liggghts_hertz;
  };
  out += detail::time_step_comment(spec, pairs, law);
  out += fmt::format("timestep {:.4g}\n", detail::recommended_step(pairs, law));
  return out;
}

}  // namespace corlab::dem
