// The driver of one explicit impact run: model -> state -> steps until the stop rule, the run
// status and the result. Model, state and step: src/fem/solver/; stop rule: separation_rule.hpp;
// theory: docs/theory/solver.md.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/explicit_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "corlab/fem/output/field_snapshot.hpp"
#include "corlab/fem/solver/run_quality.hpp"
#include "corlab/fem/solver/separation_rule.hpp"
#include "corlab/fem/solver/simd_level.hpp"
#include "fem/solver/impact_model.hpp"
#include "fem/solver/impact_state.hpp"
#include "fem/solver/impact_step.hpp"
#include "fem/solver/run_bookkeeping.hpp"

namespace corlab::fem {
namespace {

using solver::ContactKind;
using solver::ForceReport;
using solver::ImpactModel;
using solver::ImpactState;
using solver::NodeSums;
using solver::RunBookkeeping;

/// The run stops as step_collapsed when dt falls below this fraction of the first step [-].
constexpr double kMinStepFraction = 1e-6;
/// Cancellation and progress are polled every kPollEvery steps (a power of two).
constexpr long long kPollEvery = 256;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

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
    const int k = m.elements.mesh_index[e];
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
  const double e0 = m.energy_relative_initial;
  const double ke_final = clean ? rule.mean_sphere_kinetic_energy() : sphere_kinetic_energy(m, s);
  res.status = status;
  res.separated = clean;
  res.e = clean ? solver::relative_velocity(s) / m.velocity : kNaN;
  res.sphere_velocity_final = s.sphere_velocity;
  res.target_velocity_final = s.target_velocity;
  res.e_energy = clean ? std::sqrt(std::max(ke_final, 0.0) / e0) : kNaN;
  res.t_contact = rule.contact_time();
  // The target's surface on the axis sunk relative to the target's c.o.m. (a flat's is at rest).
  res.crater_depth =
      m.contact == ContactKind::kSegments
          ? (z_axis_surface - s.z[m.masters[0]]) - (m.z_com_target_start - s.target_com_z)
          : 0.0;
  res.plastic_strain_max = s.eps_p_max;
  res.energy_sphere_loss = e0 - ke_final;
  res.energy_dissipated_plastic = s.energy.plastic;
  res.energy_hourglass = s.energy.hourglass;
  res.energy_viscous = s.energy.viscous;
  res.energy_balance_error = balance_max;
  res.hysteresis_area = s.hysteresis.area;
  res.F_max = s.force_max;
  res.delta_max = s.hysteresis.indentation_max;
  res.penetration_max = s.penetration_max;
  res.substrate_von_mises_max = substrate_von_mises_max(m, s);
  res.steps = s.step;
  res.element_updates = s.element_updates;
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
                          double v_com,
                          double t_limit) {
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
      return v_com <= 0.0 && s.t < t_limit
                 ? fmt::format(
                       "contact ended with the sphere moving into the substrate "
                       "(v = {:.4g} m/s)",
                       v_com)
                 : fmt::format("no clean rebound by t_max = {:.6g} s", t_limit);
    case RunStatus::kSeparated:
      break;
  }
  return {};
}

/// The time loop of one run: steps the state until a status ends it, with the run's
/// bookkeeping (energy balance, history, stop rule), field snapshots, progress and cancel
/// polling. One driver per stepping scheme; what they keep, they keep through RunBookkeeping.
class TimeLoop {
 public:
  TimeLoop(const ImpactConfig& config,
           const Mesh& mesh,
           const SimulationControl& control,
           const ImpactModel& m,
           ImpactState& s,
           ImpactHistory& history)
      : mesh_(mesh),
        control_(control),
        m_(m),
        s_(s),
        book_(m, control.stop_at_max_compression, history),
        field_times_(config.output.field_times),
        every_(config.output.history_every),
        t_boundary_(s.t),
        t_limit_(m.t_max) {
    std::sort(field_times_.begin(), field_times_.end());
  }

  /// Runs to the end; returns the status.
  RunStatus run() {
    // A run cancelled before it starts does no work (the loop polls only every kPollEvery steps).
    if (cancelled()) return RunStatus::kCancelled;
    return m_.levels.max_level > 0 ? run_subcycled() : run_plain();
  }

  /// Another impact after a rebound (impact.repeats): the bodies sent back at the approach speed,
  /// a fresh stop rule, the time limit one impact's length on; the next run() continues the step
  /// the rebound was found in.
  void relaunch() {
    book_.relaunch(solver::relaunch_bodies(m_, s_), s_);
    t_limit_ = s_.t + (m_.t_max - m_.t_start);
    s_.cycle_penetrating = false;
    resume_forces_ = m_.levels.max_level > 0;
  }

  const RunBookkeeping& bookkeeping() const { return book_; }
  const ForceReport& last_forces() const { return rep_; }
  double time_limit() const { return t_limit_; }

 private:
  bool cancelled() const {
    return control_.cancel != nullptr && control_.cancel->load(std::memory_order_relaxed);
  }

  /// The plain loop: the energy balance and history at t^n between the kinematic and the force
  /// half, the stop rule after the force half.
  RunStatus run_plain() {
    while (true) {
      const double dt_avg = 0.5 * (s_.dt_prev + s_.dt);
      const NodeSums ns = solver::move_nodes(m_, s_);
      if (auto end = book_.sample(s_, ns.ke - s_.transit.energy, s_.step % every_ == 0)) {
        return *end;
      }
      rep_ = solver::compute_forces(m_, s_);
      if (auto end = step_failed()) return *end;
      if (auto end = book_.stop(s_, solver::rebound_kinetic_energy(m_, s_, ns), dt_avg, s_.dt_prev,
                                rep_.penetrating)) {
        return *end;
      }
      if (auto end = after_step()) return *end;
    }
  }

  /// The subcycled loop (docs/theory/solver.md section 11): the energy balance, history and stop
  /// rule at major-cycle boundaries, where every node and element is in sync.
  RunStatus run_subcycled() {
    const long long cycle = 1LL << m_.levels.max_level;
    const long long rows_every = std::max<long long>(1, every_ / cycle);
    while (true) {
      // A relaunch comes back for the force half of the step whose boundary found the rebound.
      if (!resume_forces_) {
        const bool boundary = s_.step % cycle == 0;
        const NodeSums ns = solver::move_nodes_subcycled(m_, s_);
        if (boundary) {
          if (auto end = cycle_boundary(ns, (s_.step / cycle) % rows_every == 0)) return *end;
        }
      }
      resume_forces_ = false;
      rep_ = solver::compute_forces_subcycled(m_, s_);
      if (auto end = step_failed()) return *end;
      if (s_.step % cycle == 0) {
        if (auto end = after_step()) return *end;
      } else if (s_.t >= t_limit_ || s_.step >= m_.max_steps) {
        return s_.t >= t_limit_ ? RunStatus::kNotSeparated : RunStatus::kStepBudgetExceeded;
      }
    }
  }

  /// At a major-cycle boundary t^k: energy balance and history row, then the stop rule over the
  /// cycle that ended (none at the start).
  std::optional<RunStatus> cycle_boundary(const NodeSums& ns, bool row) {
    const double cycle_dt = s_.t - t_boundary_;
    t_boundary_ = s_.t;
    if (auto end = book_.sample(s_, ns.ke - s_.transit.energy, row)) return end;
    if (s_.step == 0) return std::nullopt;
    const bool penetrating = s_.cycle_penetrating;
    const double since = penetrating ? s_.t - s_.t_first_penetrating : cycle_dt;
    s_.cycle_penetrating = false;
    return book_.stop(s_, solver::rebound_kinetic_energy(m_, s_, ns), cycle_dt, since, penetrating);
  }

  /// An inverted element or a collapsed step after a force half.
  std::optional<RunStatus> step_failed() const {
    if (rep_.inverted_element >= 0) return RunStatus::kElementInverted;
    if (!(s_.dt > kMinStepFraction * m_.dt_initial)) return RunStatus::kStepCollapsed;
    return std::nullopt;
  }

  /// Field snapshots, the time and step limits, cancel and progress.
  std::optional<RunStatus> after_step() {
    while (next_field_ < field_times_.size() && s_.t >= field_times_[next_field_]) {
      if (control_.on_fields) control_.on_fields(s_.t, snapshot(m_, mesh_, s_, s_.t));
      ++next_field_;
    }
    if (s_.t >= t_limit_) return RunStatus::kNotSeparated;
    if (s_.step >= m_.max_steps) return RunStatus::kStepBudgetExceeded;
    if ((s_.step & (kPollEvery - 1)) == 0) {
      if (cancelled()) return RunStatus::kCancelled;
      if (control_.progress) {
        control_.progress(
            std::clamp((s_.t - m_.t_start) / (m_.t_expected - m_.t_start), 0.0, 0.99));
      }
    }
    return std::nullopt;
  }

  const Mesh& mesh_;
  const SimulationControl& control_;
  const ImpactModel& m_;
  ImpactState& s_;
  RunBookkeeping book_;
  std::vector<double> field_times_;
  std::size_t next_field_ = 0;
  int every_;
  double t_boundary_ = 0.0;     ///< time of the last major-cycle boundary (subcycling) [s]
  double t_limit_;              ///< hard stop of the present impact [s]
  bool resume_forces_ = false;  ///< the next subcycled step starts at its force half
  ForceReport rep_;
};

}  // namespace

ImpactResult run_impact(const ImpactConfig& config,
                        const Mesh& mesh,
                        const SimulationControl& control) {
  const auto wall_start = std::chrono::steady_clock::now();
  const ImpactModel m = solver::make_impact_model(config, mesh);
  ImpactState s = solver::make_initial_state(m);
  // The substrate surface on the axis (the rigid flat: z = 0), for the crater depth.
  const double z_axis_surface = m.contact == ContactKind::kSegments ? s.z[m.masters[0]] : 0.0;
  ImpactResult res;
  res.elements = m.n_elements;
  res.nodes = m.n_nodes;
  res.time_step = m.dt_initial;
  res.mass_scaling = m.scaling.factor * m.scaling.step_floor_scale;
  res.added_mass_fraction = m.scaling.added_mass / m.scaling.sphere_mass_physical;
  res.simd = std::string(to_string(m.simd));
  res.h_contact = solver::contact_element_size(m);
  res.energy_initial = m.energy_initial;

  TimeLoop loop(config, mesh, control, m, s, res.history);
  RunStatus status = loop.run();
  const RunBookkeeping& book = loop.bookkeeping();
  res = finish(m, s, book.rule(), status, book.balance_max(), z_axis_surface, std::move(res));
  if (res.status != RunStatus::kSeparated && res.status_detail.empty()) {
    res.status_detail = status_detail(res.status, m, s, loop.last_forces(),
                                      solver::relative_velocity(s), loop.time_limit());
  }
  if (res.separated) res.e_impacts = {res.e};
  for (int k = 2; k <= config.impact.repeats && status == RunStatus::kSeparated; ++k) {
    loop.relaunch();
    status = loop.run();
    if (status == RunStatus::kSeparated) {
      res.e_impacts.push_back(solver::relative_velocity(s) / m.velocity);
    } else {
      // The run's status is its last impact's; the first impact's fields stay as they were.
      res.status = status;
      res.separated = false;
      res.status_detail =
          fmt::format("impact {}: {}", k,
                      status_detail(status, m, s, loop.last_forces(), solver::relative_velocity(s),
                                    loop.time_limit()));
    }
  }
  if (config.impact.repeats > 1) {  // the run's totals over every impact
    res.energy_balance_error = book.balance_max();
    res.steps = s.step;
    res.element_updates = s.element_updates;
    res.end_time = s.t;
  }
  res.e_last = res.e_impacts.empty() ? kNaN : res.e_impacts.back();
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  res.element_steps_per_s = static_cast<double>(s.element_updates) / res.wall_s;
  if (control.progress) control.progress(1.0);
  return res;
}

}  // namespace corlab::fem
