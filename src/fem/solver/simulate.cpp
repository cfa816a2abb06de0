// simulate(): config -> mesh -> explicit solver (axisymmetric or 3-D).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/simulate.hpp"

#include <cmath>
#include <limits>

#include "corlab/fem/mesh/mesh_generator.hpp"
#include "corlab/fem/solver/explicit_solver.hpp"
#include "corlab/fem/solver/hex_impact.hpp"
#include "corlab/fem/solver/run_quality.hpp"

namespace corlab::fem {
namespace {

// The 3-D run's result in the common result (fields the 3-D model has no value for stay NaN).
ImpactResult result_of(const HexImpactResult& h) {
  constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  ImpactResult r;
  r.status = h.status;
  r.separated = h.status == RunStatus::kSeparated;
  r.e = r.separated ? h.e_n : kNan;
  r.e_n = r.e;
  r.e_t = r.separated ? h.e_t : kNan;
  r.e_energy = kNan;
  r.e_impacts = r.separated ? std::vector<double>{r.e} : std::vector<double>{};
  r.e_last = r.e;
  r.omega = h.omega;
  r.rebound_angle = h.rebound_angle;
  r.energy_friction = h.energy_friction;
  r.F_max = h.F_max;
  r.delta_max = kNan;
  r.t_contact = h.t_contact;
  r.crater_depth = kNan;
  r.plastic_strain_max = h.plastic_strain_max;
  r.energy_initial = h.energy_initial;
  r.energy_dissipated_plastic = h.energy_dissipated_plastic;
  r.energy_hourglass = h.energy_hourglass;
  r.energy_viscous = h.energy_viscous;
  r.end_time = h.end_time;
  r.energy_balance_error = h.energy_balance_error;
  r.penetration_max = h.penetration_max;
  r.elements = h.elements;
  r.nodes = h.nodes;
  r.steps = h.steps;
  r.element_updates = static_cast<long long>(h.elements) * h.steps;
  r.h_contact = h.h_contact;
  r.time_step = h.time_step;
  r.sphere_velocity_final = h.vz_final;
  r.simd = h.simd;
  r.wall_s = h.wall_s;
  r.element_steps_per_s = h.wall_s > 0.0 ? static_cast<double>(r.element_updates) / h.wall_s : 0.0;
  // The quality guards of the axisymmetric runs; the penetration guard needs delta_max, which the
  // 3-D model does not have yet.
  if (r.separated) r.suspect = suspect_reason(r);
  return r;
}

}  // namespace

ImpactResult simulate(const ImpactConfig& config, const SimulationControl& control) {
  if (!control.config_validated) validate(config);
  if (uses_3d_model(config)) return result_of(simulate_hex_impact(config, control));
  const Mesh mesh = build_impact_mesh(config);
  ImpactResult r = run_impact(config, mesh, control);
  r.e_n = r.e;
  return r;
}

}  // namespace corlab::fem
