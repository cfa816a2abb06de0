// The driver of one explicit impact run: model -> state -> steps until the stop rule, the run
// status and the result. Model, state and step: src/fem/solver/; stop rule: separation_rule.hpp;
// theory: docs/theory/solver.md.
#include "corlab/fem/explicit_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "corlab/fem/field_snapshot.hpp"
#include "corlab/fem/run_quality.hpp"
#include "corlab/fem/separation_rule.hpp"
#include "fem/solver/impact_model.hpp"
#include "fem/solver/impact_state.hpp"
#include "fem/solver/impact_step.hpp"

namespace corlab::fem {
namespace {

using solver::ForceReport;
using solver::ImpactModel;
using solver::ImpactState;
using solver::NodeSums;

/// The run stops as step_collapsed when dt falls below this fraction of the first step [-].
constexpr double kMinStepFraction = 1e-6;
/// Cancellation and progress are polled every kPollEvery steps (a power of two).
constexpr long long kPollEvery = 256;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Appends one history row (state at t^n; ke from the kinematic half of the step).
void record_history(
    const ImpactState& s, double ke, double v_half_mean, double balance, ImpactHistory& h) {
  h.time.push_back(s.t);
  h.contact_force.push_back(s.force);
  h.indentation.push_back(s.indentation);
  h.sphere_velocity.push_back(-v_half_mean);
  h.kinetic_energy.push_back(ke);
  h.strain_energy.push_back(s.energy.internal - s.energy.plastic);
  h.plastic_dissipation.push_back(s.energy.plastic);
  h.hourglass_energy.push_back(s.energy.hourglass);
  h.viscous_dissipation.push_back(s.energy.viscous);
  h.contact_energy.push_back(s.energy.contact);
  h.energy_balance_error.push_back(balance);
}

FieldSnapshot snapshot(const ImpactModel& m, const Mesh& mesh, const ImpactState& s, double t) {
  FieldSnapshot f;
  f.time = t;
  f.mesh = mesh;
  f.mesh.r = s.r;
  f.mesh.z = s.z;
  f.displacement_r.resize(m.n_nodes);
  f.displacement_z.resize(m.n_nodes);
  for (int i = 0; i < m.n_nodes; ++i) {
    f.displacement_r[i] = s.r[i] - mesh.r[i];
    f.displacement_z[i] = s.z[i] - mesh.z[i];
  }
  f.velocity_r = s.vr;
  f.velocity_z = s.vz;
  f.von_mises.assign(m.n_elements, 0.0);
  f.pressure.assign(m.n_elements, 0.0);
  f.plastic_strain.assign(m.n_elements, 0.0);
  const auto& es = s.elements;
  for (int e = 0; e < m.n_elements; ++e) {
    const AxisymTensor st{es.srr[e], es.szz[e], es.stt[e], es.srz[e]};
    const int k = m.original_element[e];
    f.von_mises[k] = von_mises(st);
    f.pressure[k] = -trace(st) / 3.0;
    f.plastic_strain[k] = es.eps_p[e];
  }
  return f;
}

/// Sphere kinetic energy now [J].
double sphere_kinetic_energy(const ImpactModel& m, const ImpactState& s) {
  double ke = 0.0;
  for (int i = 0; i < m.n_nodes; ++i)
    ke += 0.5 * m.mass[i] * (s.vr[i] * s.vr[i] + s.vz[i] * s.vz[i]) * m.is_sphere[i];
  return ke;
}

/// Largest von Mises stress over the substrate's elements now [Pa].
double substrate_von_mises_max(const ImpactModel& m, const ImpactState& s) {
  const auto& es = s.elements;
  double vm = 0.0;
  for (int e = m.n_sphere_elements; e < m.n_elements; ++e) {
    vm = std::max(vm, von_mises(AxisymTensor{es.srr[e], es.szz[e], es.stt[e], es.srz[e]}));
  }
  return vm;
}

/// The result of a run that ended with `status`.
ImpactResult finish(const ImpactModel& m,
                    const ImpactState& s,
                    const SeparationRule& rule,
                    RunStatus status,
                    double balance_max,
                    double z_axis_surface,
                    ImpactResult res) {
  const bool clean = status == RunStatus::kSeparated;
  const double e0 = m.energy_initial;
  const double ke_final = clean ? rule.mean_sphere_kinetic_energy() : sphere_kinetic_energy(m, s);
  res.status = status;
  res.separated = clean;
  res.e = clean ? s.sphere_velocity / m.velocity : kNaN;
  res.e_energy = clean ? std::sqrt(std::max(ke_final, 0.0) / e0) : kNaN;
  res.contact_time = rule.contact_time();
  res.crater_depth = z_axis_surface - s.z[m.masters[0]];
  res.plastic_strain_max = s.eps_p_max;
  res.energy_sphere_loss = e0 - ke_final;
  res.energy_dissipated_plastic = s.energy.plastic;
  res.energy_hourglass = s.energy.hourglass;
  res.energy_viscous = s.energy.viscous;
  res.energy_balance_error = balance_max;
  res.hysteresis_area = s.hysteresis;
  res.force_max = s.force_max;
  res.indentation_max = s.indentation_max;
  res.penetration_max = s.penetration_max;
  res.substrate_von_mises_max = substrate_von_mises_max(m, s);
  res.steps = s.step;
  res.end_time = s.t;
  if (status != RunStatus::kNonFinite && !std::isfinite(res.energy_sphere_loss)) {
    res.status = RunStatus::kNonFinite;
    res.status_detail = "non-finite energies at the end of the run";
  }
  if (res.status == RunStatus::kSeparated) res.suspect = suspect_reason(res);
  return res;
}

/// A one-line detail for a status other than separated.
std::string status_detail(RunStatus status,
                          const ImpactModel& m,
                          const ImpactState& s,
                          const ForceReport& rep,
                          double v_com) {
  switch (status) {
    case RunStatus::kElementInverted:
      return fmt::format("element {} inverted at t = {:.6g} s (step {})", rep.inverted_element, s.t,
                         s.step);
    case RunStatus::kStepCollapsed:
      return fmt::format("stable time step collapsed to {:.3g} s at t = {:.6g} s", s.dt, s.t);
    case RunStatus::kNonFinite:
      return fmt::format("non-finite energy at t = {:.6g} s (step {})", s.t, s.step);
    case RunStatus::kStepBudgetExceeded:
      return fmt::format("{} steps (solver.max_steps) reached at t = {:.6g} s", m.max_steps, s.t);
    case RunStatus::kCancelled:
      return "interrupted";
    case RunStatus::kMaxCompression:
      return fmt::format("stopped at maximum compression, t = {:.6g} s", s.t);
    case RunStatus::kNotSeparated:
      return v_com <= 0.0 && s.t < m.t_max
                 ? fmt::format(
                       "contact ended with the sphere moving into the substrate "
                       "(v = {:.4g} m/s)",
                       v_com)
                 : fmt::format("no clean rebound by t_max = {:.6g} s", m.t_max);
    case RunStatus::kSeparated:
      break;
  }
  return {};
}

}  // namespace

ImpactResult run_impact(const ImpactConfig& config,
                        const Mesh& mesh,
                        const SimulationControl& control) {
  const auto wall_start = std::chrono::steady_clock::now();
  const ImpactModel m = solver::make_impact_model(config, mesh);
  ImpactState s = solver::make_initial_state(m);
  SeparationRule rule(m.t_wave, m.velocity);
  const double z_axis_surface = s.z[m.masters[0]];
  std::vector<double> field_times = config.output.field_times;
  std::sort(field_times.begin(), field_times.end());
  std::size_t next_field = 0;
  const int every = config.output.history_every;
  const auto* cancel = control.cancel;

  ImpactResult res;
  res.elements = m.n_elements;
  res.nodes = m.n_nodes;
  res.time_step = m.dt_initial;
  res.h_contact =
      std::hypot(s.r[m.masters[1]] - s.r[m.masters[0]], s.z[m.masters[1]] - s.z[m.masters[0]]);
  res.energy_initial = m.energy_initial;

  RunStatus status = RunStatus::kNotSeparated;
  double balance_max = 0.0;
  double v_com_prev = s.sphere_velocity;
  ForceReport rep;
  // A run cancelled before it starts does no work (the loop polls only every kPollEvery steps).
  const bool cancelled_at_start = cancel != nullptr && cancel->load(std::memory_order_relaxed);
  if (cancelled_at_start) status = RunStatus::kCancelled;
  while (!cancelled_at_start) {
    // Kinematic half, then the energy balance at t^n (kinetic energy in product form, exact for
    // the scheme) and the history row.
    const double dt_avg = 0.5 * (s.dt_prev + s.dt);
    const NodeSums ns = solver::move_nodes(m, s);
    const double v_half_mean = 0.5 * (s.sphere_velocity + v_com_prev);
    v_com_prev = s.sphere_velocity;
    const double total =
        ns.ke + s.energy.internal + s.energy.hourglass + s.energy.viscous + s.energy.contact;
    const double balance = (total - m.energy_initial) / m.energy_initial;
    if (!std::isfinite(balance)) {
      status = RunStatus::kNonFinite;
      balance_max = kNaN;
      break;
    }
    balance_max = std::max(balance_max, std::abs(balance));
    if (s.step % every == 0) record_history(s, ns.ke, v_half_mean, balance, res.history);
    rule.accumulate(ns.ke_sphere, dt_avg);

    // Force half, then the stop rule.
    rep = solver::compute_forces(m, s);
    if (rep.inverted_element >= 0) {
      status = RunStatus::kElementInverted;
      break;
    }
    if (!(s.dt > kMinStepFraction * m.dt_initial)) {
      status = RunStatus::kStepCollapsed;
      break;
    }
    const auto decision = rule.update(s.t, s.dt_prev, rep.penetrating, s.sphere_velocity);
    if (decision == SeparationRule::Decision::kRebound) {
      status = RunStatus::kSeparated;
      break;
    }
    if (decision == SeparationRule::Decision::kNoRebound) break;
    if (control.stop_at_max_compression && rule.touched() && s.sphere_velocity >= 0.0) {
      status = RunStatus::kMaxCompression;
      break;
    }
    while (next_field < field_times.size() && s.t >= field_times[next_field]) {
      if (control.on_fields) control.on_fields(s.t, snapshot(m, mesh, s, s.t));
      ++next_field;
    }
    if (s.t >= m.t_max) break;
    if (s.step >= m.max_steps) {
      status = RunStatus::kStepBudgetExceeded;
      break;
    }
    if ((s.step & (kPollEvery - 1)) == 0) {
      if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) {
        status = RunStatus::kCancelled;
        break;
      }
      if (control.progress) {
        control.progress(std::clamp((s.t - m.t_start) / (m.t_expected - m.t_start), 0.0, 0.99));
      }
    }
  }
  res = finish(m, s, rule, status, balance_max, z_axis_surface, std::move(res));
  if (res.status != RunStatus::kSeparated && res.status_detail.empty()) {
    res.status_detail = status_detail(res.status, m, s, rep, s.sphere_velocity);
  }
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  res.element_steps_per_s =
      static_cast<double>(m.n_elements) * static_cast<double>(s.step) / res.wall_s;
  if (control.progress) control.progress(1.0);
  return res;
}

}  // namespace corlab::fem
