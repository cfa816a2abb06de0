// History CSV and summary JSON of one impact.
#include "corlab/fem/impact_output.hpp"

#include <fmt/format.h>

#include <fstream>
#include <stdexcept>

namespace corlab::fem {

namespace {

nlohmann::json material_json(const Material& m) {
  nlohmann::json j;
  j["name"] = m.name;
  j["E"] = m.youngs_modulus;
  j["nu"] = m.poisson_ratio;
  j["rho"] = m.density;
  j["sigma_y"] = m.yield_stress ? nlohmann::json(*m.yield_stress) : nlohmann::json(nullptr);
  j["hardening"] = m.hardening_modulus;
  j["source"] = m.source;
  return j;
}

std::ofstream open_for_writing(const std::filesystem::path& file) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error(fmt::format("cannot write '{}'", file.string()));
  return out;
}

}  // namespace

nlohmann::json config_to_json(const ImpactConfig& c) {
  nlohmann::json j;
  j["sphere"] = {{"radius", c.sphere.radius}, {"material", material_json(c.sphere.material)}};
  j["substrate"] = {{"radius", c.substrate.radius},
                    {"depth", c.substrate.depth},
                    {"material", material_json(c.substrate.material)}};
  j["impact"] = {{"velocity", c.impact.velocity}, {"gap", c.impact.gap}};
  j["mesh"] = {{"h_min", c.mesh.h_min},
               {"growth", c.mesh.growth},
               {"h_max", c.mesh.h_max},
               {"refine_factor", c.mesh.refine_factor},
               {"contact_elements", c.mesh.contact_elements},
               {"file", c.mesh.file.string()}};
  j["solver"] = {{"safety_factor", c.solver.safety_factor},
                 {"hourglass", c.solver.hourglass},
                 {"bulk_viscosity_linear", c.solver.bulk_viscosity_linear},
                 {"bulk_viscosity_quadratic", c.solver.bulk_viscosity_quadratic},
                 {"penalty_scale", c.solver.penalty_scale},
                 {"t_max", c.solver.t_max}};
  j["output"] = {{"times", c.output.field_times}, {"history_every", c.output.history_every}};
  return j;
}

nlohmann::json summary_to_json(const ImpactResult& r, const ImpactConfig& config) {
  nlohmann::json j;
  j["e"] = r.e;
  j["e_energy"] = r.e_energy;
  j["F_max"] = r.force_max;
  j["delta_max"] = r.indentation_max;
  j["t_contact"] = r.contact_time;
  j["crater_depth"] = r.crater_depth;
  j["plastic_strain_max"] = r.plastic_strain_max;
  j["energy_initial"] = r.energy_initial;
  j["energy_sphere_loss"] = r.energy_sphere_loss;
  j["energy_dissipated_plastic"] = r.energy_dissipated_plastic;
  j["energy_hourglass"] = r.energy_hourglass;
  j["energy_viscous"] = r.energy_viscous;
  j["energy_balance_error"] = r.energy_balance_error;
  j["hysteresis_area"] = r.hysteresis_area;
  j["penetration_max"] = r.penetration_max;
  j["separated"] = r.separated;
  j["status"] = std::string(to_string(r.status));
  j["status_detail"] = r.status_detail;
  j["suspect"] = r.suspect;
  j["elements"] = r.elements;
  j["nodes"] = r.nodes;
  j["steps"] = r.steps;
  j["h_contact"] = r.h_contact;
  j["time_step"] = r.time_step;
  j["end_time"] = r.end_time;
  j["wall_s"] = r.wall_s;
  j["element_steps_per_s"] = r.element_steps_per_s;
  j["units"] = {{"F_max", "N"},           {"delta_max", "m"},       {"t_contact", "s"},
                {"crater_depth", "m"},    {"energy_*", "J"},        {"h_contact", "m"},
                {"time_step", "s"},       {"end_time", "s"},        {"wall_s", "s"},
                {"hysteresis_area", "J"}, {"penetration_max", "m"}, {"element_steps_per_s", "1/s"}};
  j["config"] = config_to_json(config);
  return j;
}

void write_summary_json(const ImpactResult& result,
                        const ImpactConfig& config,
                        const std::filesystem::path& file) {
  auto out = open_for_writing(file);
  out << summary_to_json(result, config).dump(2) << '\n';
  if (!out) throw std::runtime_error(fmt::format("cannot write '{}'", file.string()));
}

void write_history_csv(const ImpactHistory& h, const std::filesystem::path& file) {
  auto out = open_for_writing(file);
  out << "time_s,contact_force_N,indentation_m,sphere_velocity_m_per_s,kinetic_energy_J,"
         "strain_energy_J,plastic_dissipation_J,hourglass_energy_J,viscous_dissipation_J,"
         "contact_energy_J,energy_balance_error\n";
  for (std::size_t i = 0; i < h.time.size(); ++i) {
    out << fmt::format(
        "{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.6g}\n", h.time[i],
        h.contact_force[i], h.indentation[i], h.sphere_velocity[i], h.kinetic_energy[i],
        h.strain_energy[i], h.plastic_dissipation[i], h.hourglass_energy[i],
        h.viscous_dissipation[i], h.contact_energy[i], h.energy_balance_error[i]);
  }
  if (!out) throw std::runtime_error(fmt::format("cannot write '{}'", file.string()));
}

}  // namespace corlab::fem
