// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file time_loop.hpp
/// The one time loop of an impact run, for every geometry (docs/dev/architecture.md, "One
/// driver"): the axisymmetric model (ImpactModel, ImpactState: explicit_solver.cpp) and the 3-D
/// one (HexModel, HexState: hex_impact.cpp). A model and its state derive from RunConstants and
/// RunState (run_state.hpp) and come with, found by argument-dependent lookup in their namespace:
///   NodeSums move_nodes(const Model&, State&)        the kinematic half of a step
///   ForceReport compute_forces(const Model&, State&)  the force half (advances t, sets dt)
///   double rebound_kinetic_energy(const Model&, const State&, const NodeSums&)
///   double sphere_kinetic_energy(const Model&, const State&)
/// The axisymmetric model's element subcycling and repeated impacts are compiled in only for a
/// model with `levels` (SubcyclingLevels). Private to src/fem/solver.

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/solver/impact_result.hpp"
#include "corlab/fem/solver/run_quality.hpp"
#include "corlab/fem/solver/separation_rule.hpp"
#include "corlab/fem/solver/simulate.hpp"
#include "fem/solver/impact_step.hpp"
#include "fem/solver/run_bookkeeping.hpp"
#include "fem/solver/run_state.hpp"

namespace corlab::fem::solver {

/// The run stops as step_collapsed when dt falls below this fraction of the first step [-].
inline constexpr double kMinStepFraction = 1e-6;
/// Cancellation and progress are polled every kPollEvery steps (a power of two).
inline constexpr long long kPollEvery = 256;

/// Whether the model has the axisymmetric model's subcycling levels (and its repeated impacts).
template <class Model>
inline constexpr bool kSubcycles = requires(const Model& m) {
  m.levels.max_level;
};

/// The time loop of one run: steps the state until a status ends it, with the run's
/// bookkeeping (energy balance, history, stop rule), field snapshots, progress and cancel
/// polling. One driver per stepping scheme; what they keep, they keep through RunBookkeeping.
template <class Model, class State>
class TimeLoop {
 public:
  /// `fields(t)` writes the fields at time t [s] (called at each output.times passed).
  TimeLoop(const ImpactConfig& config,
           const SimulationControl& control,
           const Model& m,
           State& s,
           ImpactHistory& history,
           std::function<void(double)> fields)
      : control_(control),
        m_(m),
        s_(s),
        book_(m, control.stop_at_max_compression, control.e_only, history),
        field_times_(config.output.field_times),
        fields_(std::move(fields)),
        every_(config.output.history_every),
        t_boundary_(s.t),
        t_limit_(m.t_max) {
    std::sort(field_times_.begin(), field_times_.end());
  }

  /// Runs to the end; returns the status.
  RunStatus run() {
    // A run cancelled before it starts does no work (the loop polls only every kPollEvery steps).
    if (cancelled()) return RunStatus::kCancelled;
    if constexpr (kSubcycles<Model>) {
      if (m_.levels.max_level > 0) return run_subcycled();
    }
    return run_plain();
  }

  /// Another impact after a rebound (impact.repeats): the bodies sent back at the approach speed,
  /// a fresh stop rule, the time limit one impact's length on; the next run() continues the step
  /// the rebound was found in.
  void relaunch() requires kSubcycles<Model> {
    book_.relaunch(relaunch_bodies(m_, s_), s_);
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
      const NodeSums ns = move_nodes(m_, s_);
      if (auto end = book_.sample(s_, kinetic(ns), s_.step % every_ == 0)) return *end;
      rep_ = compute_forces(m_, s_);
      if (auto end = step_failed()) return *end;
      if (auto end = book_.stop(s_, rebound_kinetic_energy(m_, s_, ns), dt_avg, s_.dt_prev,
                                rep_.penetrating)) {
        return *end;
      }
      if (auto end = after_step()) return *end;
    }
  }

  /// The model's kinetic energy at t^n (less the energy in transit between subcycling levels).
  double kinetic(const NodeSums& ns) const {
    if constexpr (kSubcycles<Model>) {
      return ns.ke - s_.transit.energy;
    } else {
      return ns.ke;
    }
  }

  /// The subcycled loop (docs/theory/solver.md section 11): the energy balance, history and stop
  /// rule at major-cycle boundaries, where every node and element is in sync.
  RunStatus run_subcycled() requires kSubcycles<Model> {
    const long long cycle = 1LL << m_.levels.max_level;
    const long long rows_every = std::max<long long>(1, every_ / cycle);
    while (true) {
      // A relaunch comes back for the force half of the step whose boundary found the rebound.
      if (!resume_forces_) {
        const bool boundary = s_.step % cycle == 0;
        const NodeSums ns = move_nodes_subcycled(m_, s_);
        if (boundary) {
          if (auto end = cycle_boundary(ns, (s_.step / cycle) % rows_every == 0)) return *end;
        }
      }
      resume_forces_ = false;
      rep_ = compute_forces_subcycled(m_, s_);
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
  std::optional<RunStatus> cycle_boundary(const NodeSums& ns, bool row) requires kSubcycles<Model> {
    const double cycle_dt = s_.t - t_boundary_;
    t_boundary_ = s_.t;
    if (auto end = book_.sample(s_, kinetic(ns), row)) return end;
    if (s_.step == 0) return std::nullopt;
    const bool penetrating = s_.cycle_penetrating;
    const double since = penetrating ? s_.t - s_.t_first_penetrating : cycle_dt;
    s_.cycle_penetrating = false;
    return book_.stop(s_, rebound_kinetic_energy(m_, s_, ns), cycle_dt, since, penetrating);
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
      if (fields_) fields_(s_.t);
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

  const SimulationControl& control_;
  const Model& m_;
  State& s_;
  RunBookkeeping book_;
  std::vector<double> field_times_;
  std::function<void(double)> fields_;
  std::size_t next_field_ = 0;
  int every_;
  double t_boundary_ = 0.0;     ///< time of the last major-cycle boundary (subcycling) [s]
  double t_limit_;              ///< hard stop of the present impact [s]
  bool resume_forces_ = false;  ///< the next subcycled step starts at its force half
  ForceReport rep_;
};

/// A one-line detail for a status other than separated; v_rel [m/s] the relative normal
/// velocity at the end, t_limit [s] the impact's time limit.
inline std::string status_detail(RunStatus status,
                                 const RunConstants& m,
                                 const RunState& s,
                                 const ForceReport& rep,
                                 double t_limit) {
  const double v_com = relative_velocity(s);
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

/// What every geometry's result takes from the run that ended with `status` (into `res`): e,
/// e_energy, the contact, the energies (for the whole pair: x m.extensive), the step counts and
/// the status with its detail; the quality guard (`suspect`) is left to the caller, which adds
/// its geometry's own fields first.
template <class Model, class State>
void finish_run(const Model& m,
                const State& s,
                const TimeLoop<Model, State>& loop,
                RunStatus status,
                ImpactResult& res) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const SeparationRule& rule = loop.bookkeeping().rule();
  const bool clean = status == RunStatus::kSeparated;
  const double e0 = m.energy_relative_initial;
  const double ke_final = clean ? rule.mean_sphere_kinetic_energy() : sphere_kinetic_energy(m, s);
  const double x = m.extensive;
  res.status = status;
  res.separated = clean;
  res.e = clean ? relative_velocity(s) / m.velocity : kNaN;
  res.e_n = res.e;
  res.sphere_velocity_final = s.sphere_velocity;
  res.target_velocity_final = s.target_velocity;
  res.e_energy = clean ? std::sqrt(std::max(ke_final, 0.0) / e0) : kNaN;
  res.t_contact = rule.contact_time();
  res.plastic_strain_max = s.eps_p_max;
  res.energy_sphere_loss = x * (e0 - ke_final);
  res.energy_dissipated_plastic = x * s.energy.plastic;
  res.energy_hourglass = x * s.energy.hourglass;
  res.energy_viscous = x * s.energy.viscous;
  res.energy_friction = x * s.energy.friction;
  res.energy_absorbed = x * s.energy.absorbed;
  res.energy_balance_error = loop.bookkeeping().balance_max();
  res.hysteresis_area = x * s.hysteresis.area;
  res.F_max = x * s.force_max;
  res.delta_max = s.hysteresis.indentation_max;
  res.penetration_max = s.penetration_max;
  res.steps = s.step;
  res.element_updates = s.element_updates;
  res.end_time = s.t;
  if (status != RunStatus::kNonFinite && !std::isfinite(res.energy_sphere_loss)) {
    res.status = RunStatus::kNonFinite;
    res.status_detail = "non-finite energies at the end of the run";
  }
  if (res.status != RunStatus::kSeparated && res.status_detail.empty()) {
    res.status_detail = status_detail(res.status, m, s, loop.last_forces(), loop.time_limit());
  }
}

/// The end of every run: e_last, the wall time since `wall_start` and the throughput, progress 1.
inline void close_run(const RunState& s,
                      std::chrono::steady_clock::time_point wall_start,
                      const SimulationControl& control,
                      ImpactResult& res) {
  res.e_last =
      res.e_impacts.empty() ? std::numeric_limits<double>::quiet_NaN() : res.e_impacts.back();
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  res.element_steps_per_s = static_cast<double>(s.element_updates) / res.wall_s;
  if (control.progress) control.progress(1.0);
}

}  // namespace corlab::fem::solver
