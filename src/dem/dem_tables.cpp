// The e(v) tables of a DEM export (CSV, and everything as JSON).
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/format.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "corlab/dem/contact_ode.hpp"
#include "corlab/dem/dem_export.hpp"
#include "corlab/dem/hysteresis_chi.hpp"
#include "corlab/dem/tangential.hpp"
#include "corlab/version.hpp"
#include "dem/detail/export_text.hpp"

namespace corlab::dem {
namespace {

// "1-2", "1-wall" (the first wall material), "1-wall2" (the second, ...).
std::string short_name(const PairCalibration& p) {
  if (p.type_j != 0) return fmt::format("{}-{}", p.type_i, p.type_j);
  return p.wall == 0 ? fmt::format("{}-wall", p.type_i)
                     : fmt::format("{}-wall{}", p.type_i, p.wall + 1);
}

// e of the fitted viscoelastic law at v (ODE), for the tables.
double viscoelastic_e(const PairCalibration& p, double v) {
  const ViscoelasticHertzLaw law{p.hertz_stiffness, p.viscoelastic->parameter};
  const ForceLaw f = [&law](double d, double r, const ContactHistory&) { return law.force(d, r); };
  return simulate_impact(f, p.effective_mass, v).restitution;
}

double liggghts_e(const PairCalibration& p, double v) {
  const LiggghtsThorntonNingLaw law{
      {p.effective_modulus, p.effective_radius, p.liggghts->parameter}};
  const ForceLaw f = [&law](double d, double, const ContactHistory& h) { return law.force(d, h); };
  return simulate_impact(f, p.effective_mass, v).restitution;
}

// Each particle type as the exports use it (id = LAMMPS/LIGGGHTS atom type).
nlohmann::json types_json(const ExportSpec& spec) {
  nlohmann::json types = nlohmann::json::array();
  for (int id = 1; id <= static_cast<int>(spec.types.size()); ++id) {
    const ParticleType& t = spec.types[static_cast<std::size_t>(id - 1)];
    types.push_back({{"id", id},
                     {"label", type_label(spec, id)},
                     {"radius_m", t.radius},
                     {"density_kg_per_m3", t.material.density},
                     {"youngs_modulus_Pa", t.material.youngs_modulus},
                     {"poisson_ratio", t.material.poisson_ratio}});
  }
  return types;
}

}  // namespace

std::string write_table_csv(const ExportSpec& spec,
                            const std::vector<PairCalibration>& pairs,
                            int points) {
  std::string out = "# corlab dem e(v) table: linear interpolation in v, end values outside\n";
  out +=
      "pair,label,velocity_m_s,e_target,chi_exact,e_lammps_viscoelastic,e_liggghts_thornton_"
      "ning\n";
  for (const auto& p : pairs) {
    for (const double v : detail::table_speeds(spec, points)) {
      const double e = p.curve(v);
      out += fmt::format("{},{},{:.8g},{:.8g},{:.8g},{},{}\n", short_name(p), p.label, v, e,
                         exact_chi(std::min(e, 1.0)),
                         p.viscoelastic ? fmt::format("{:.8g}", viscoelastic_e(p, v)) : "",
                         p.liggghts ? fmt::format("{:.8g}", liggghts_e(p, v)) : "");
    }
  }
  return out;
}

std::string write_json(const ExportSpec& spec,
                       const std::vector<PairCalibration>& pairs,
                       int points) {
  nlohmann::json root;
  root["corlab_version"] = std::string(kVersion);
  root["units"] = "SI (m, kg, s, N, Pa)";
  root["interpolation"] =
      "linear in velocity between table rows; end values outside [v_min, v_max]";
  root["v_min"] = spec.v_min;
  root["v_max"] = spec.v_max;
  root["time_step_error"] = kTimeStepError;
  root["time_step_s"] = {{"lammps", lammps_time_step(pairs, true)},
                         {"lammps_nopython", lammps_time_step(pairs, false)},
                         {"liggghts", liggghts_time_step(pairs)},
                         {"yade", yade_time_step(pairs)}};
  root["liggghts_model"] = liggghts_uses_thornton_ning(pairs) ? "thornton_ning" : "hertz";
  root["types"] = types_json(spec);
  const auto fit_json = [](const CurveFit& f) {
    return nlohmann::json{{"parameter", f.parameter},
                          {"rms_error", f.rms_error},
                          {"max_abs_error", f.max_abs_error},
                          {"velocities", f.velocities},
                          {"target", f.target},
                          {"fitted", f.fitted}};
  };
  const auto delivery_json = [](const Delivery& d) {
    return nlohmann::json{{"route", d.route},
                          {"law_e", d.law_e},
                          {"law", step_rule(d.law).name},
                          {"steps_per_contact", step_rule(d.law).steps_per_contact},
                          {"max_abs_error", d.max_abs_error}};
  };
  for (const auto& p : pairs) {
    nlohmann::json j{{"pair", short_name(p)},
                     {"type_i", p.type_i},
                     {"type_j", p.type_j},
                     {"wall_material", p.wall},
                     {"label", p.label},
                     {"target", p.target},
                     {"effective_modulus_Pa", p.effective_modulus},
                     {"effective_radius_m", p.effective_radius},
                     {"effective_mass_kg", p.effective_mass},
                     {"effective_density_kg_per_m3", p.effective_density},
                     {"hertz_stiffness_N_per_m1.5", p.hertz_stiffness},
                     {"friction", p.friction},
                     {"mindlin_shear_modulus_Pa", p.shear_modulus},
                     {"mindlin_kt_per_contact_radius_Pa", mindlin_coefficient(p.shear_modulus)},
                     {"tangential_damping_ratio_x_gamma",
                      tangential_damping_ratio(p.shear_modulus, p.effective_modulus)},
                     {"contact_time_at_v_max_s", p.contact_time_fast},
                     {"contact_time_at_v_min_s", p.contact_time_slow}};
    j["delivered"] = {{"lammps", delivery_json(lammps_delivery(spec, p, true))},
                      {"lammps_nopython", delivery_json(lammps_delivery(spec, p, false))},
                      {"liggghts", delivery_json(liggghts_delivery(pairs, p))},
                      {"yade", delivery_json(yade_delivery(spec, p))}};
    if (p.constant) {
      j["constant_e"] = *p.constant;
      j["chi_exact"] = p.chi;
      j["tsuji_alpha_exact"] = p.tsuji_alpha;
      j["lammps_tsuji_input"] = p.lammps_tsuji_input;
    } else {
      j["viscoelastic_damping_N_s_per_m1.5"] = fit_json(*p.viscoelastic);
      j["lammps_viscoelastic_eta"] = p.lammps_viscoelastic_eta();
      j["thornton_limiting_pressure_Pa"] = fit_json(*p.thornton);
      j["liggghts_thornton_ning_pressure_Pa"] = fit_json(*p.liggghts);
      j["liggghts_yield_ratio"] = p.liggghts_yield_ratio();
    }
    j["best_constant_e"] = fit_json(*p.best_constant);
    if (p.liggghts_written) j["liggghts_as_written"] = fit_json(*p.liggghts_written);
    nlohmann::json table = nlohmann::json::array();
    for (const double v : detail::table_speeds(spec, points)) {
      const double e = p.curve(v);
      table.push_back({{"v", v}, {"e", e}, {"chi", exact_chi(std::min(e, 1.0))}});
    }
    j["table"] = table;
    root["pairs"].push_back(j);
  }
  return root.dump(2) + "\n";
}

}  // namespace corlab::dem
