// The LIGGGHTS 3.8 fragment of a DEM export (pair_style gran, fix wall/gran).
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "corlab/dem/dem_export.hpp"
#include "corlab/dem/tangential.hpp"
#include "dem/detail/export_text.hpp"

namespace corlab::dem {
namespace {

// e of pair (a, b) (type ids, 0 = wall) in a hertz export: its constant, or the closest constant.
double pair_constant(const std::vector<PairCalibration>& pairs, int a, int b) {
  for (const auto& p : pairs) {
    if ((p.type_i == a && p.type_j == b) || (p.type_i == b && p.type_j == a)) {
      return p.constant ? *p.constant : p.best_constant->parameter;
    }
  }
  return 1.0;  // a pair the export leaves out (--wall-only particle pairs): elastic
}

// youngsModulus and poissonsRatio per atom type (the wall's material last).
std::string elastic_constants(const ExportSpec& spec) {
  std::string young = "fix m1 all property/global youngsModulus peratomtype";
  std::string poisson = "fix m2 all property/global poissonsRatio peratomtype";
  for (const auto& t : spec.types) {
    young += fmt::format(" {:.10g}", t.material.youngs_modulus);
    poisson += fmt::format(" {:.6g}", t.material.poisson_ratio);
  }
  if (spec.wall) {
    young += fmt::format(" {:.10g}", spec.wall->youngs_modulus);
    poisson += fmt::format(" {:.6g}", spec.wall->poisson_ratio);
  }
  return young + "\n" + poisson + "\n";
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
  if (spec.friction <= 0.0) return std::string(kFrictionlessComment);
  return fmt::format(
      "# Tangential (--friction {:.6g}): `tangential history`, LIGGGHTS's own Mindlin stiffness\n"
      "# k_t = 8 G* sqrt(R* delta) from youngsModulus and poissonsRatio (1/G* = 2(2-nu_1)\n"
      "# (1+nu_1)/E_1 + ...), Coulomb coefficientFriction, and its tangential dashpot (the\n"
      "# normal damping ratio with k_t; tangential_damping on).\n",
      spec.friction);
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

std::string write_liggghts(const ExportSpec& spec, const std::vector<PairCalibration>& pairs) {
  std::string out = detail::export_header(spec, "LIGGGHTS 3.8 (pair_style gran)");
  const bool tn = liggghts_uses_thornton_ning(pairs);
  const std::size_t n = spec.types.size() + (spec.wall ? 1 : 0);
  const int wall_type = static_cast<int>(spec.types.size()) + 1;
  out +=
      "# Needs: atom_style granular, communicate single vel yes, hard_particles yes (moduli\n"
      "# above 1e9 Pa); include it after create_box N";
  out += spec.wall ? fmt::format(" with N = {} (the wall's material is type {}).\n", n, wall_type)
                   : fmt::format(" with N = {}.\n", n);
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
  out += elastic_constants(spec);
  std::string matrix =
      fmt::format("fix m3 all property/global coefficientRestitution peratomtypepair {}", n);
  for (std::size_t a = 1; a <= n; ++a) {
    for (std::size_t b = 1; b <= n; ++b) {
      const int ia = a == n && spec.wall ? 0 : static_cast<int>(a);
      const int ib = b == n && spec.wall ? 0 : static_cast<int>(b);
      matrix += fmt::format(" {:.8g}", tn ? 1.0 : pair_constant(pairs, ia, ib));
    }
  }
  if (tn) {
    out +=
        "# coefficientRestitution: thornton_ning reads it only for tangential damping (zero\n"
        "# here, frictionless); 1.0 keeps it out of the normal force.\n";
  }
  out += matrix + "\n";
  out += fmt::format("fix m4 all property/global coefficientFriction peratomtypepair {} {}\n", n,
                     fmt::join(std::vector<double>(n * n, spec.friction), " "));
  std::string model = "hertz";
  if (tn) {
    model = "thornton_ning";
    std::string ratio = "fix m5 all property/global coefficientYieldRatio peratomtype";
    for (const double r : liggghts_type_ratios(spec, pairs)) ratio += fmt::format(" {:.10g}", r);
    if (spec.wall) {
      out +=
          "# The wall type's own yield ratio is never read (a_y = ratio r_i of the particle),\n"
          "# 1.0 fills its place.\n";
      ratio += " 1.0";
    }
    out += ratio + "\n";
    out += fmt::format("fix m6 all property/global surfaceEnergy peratomtypepair {} {}\n", n,
                       fmt::join(std::vector<std::string>(n * n, "0.0"), " "));
  }
  const double r_min =
      std::min_element(spec.types.begin(), spec.types.end(), [](const auto& a, const auto& b) {
        return a.radius < b.radius;
      })->radius;
  const std::string_view tangential = spec.friction > 0.0 ? "history" : "no_history";
  out += fmt::format(
      "# The pair cutoff follows the radii; skin 0.2 r_min.\nneighbor {:.6g} bin\nneigh_modify "
      "delay 0\npair_style gran model {} tangential {}\npair_coeff * *\n",
      0.2 * r_min, model, tangential);
  if (spec.wall) {
    out += fmt::format(
        "fix corlab_wall all wall/gran model {} tangential {} primitive type {} zplane 0.0\n",
        model, tangential, wall_type);
  }
  const auto law = [tn](const PairCalibration&) {
    return tn ? CodeLaw::liggghts_thornton_ning : CodeLaw::liggghts_hertz;
  };
  out += detail::time_step_comment(spec, pairs, law);
  out += fmt::format("timestep {:.4g}\n", detail::recommended_step(pairs, law));
  return out;
}

}  // namespace corlab::dem
