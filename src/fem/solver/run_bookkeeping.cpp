// The energy balance, history rows and stop rule of a run (run_bookkeeping.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "fem/solver/run_bookkeeping.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "corlab/fem/solver/history_columns.hpp"

namespace corlab::fem::solver {

namespace {

SeparationRule rule_for(const RunConstants& m, bool e_only) {
  return e_only ? SeparationRule::e_only(m.t_wave, m.velocity)
                : SeparationRule(m.t_wave, m.velocity);
}

}  // namespace

RunBookkeeping::RunBookkeeping(const RunConstants& model,
                               bool stop_at_max_compression,
                               bool e_only,
                               ImpactHistory& history)
    : m_(model),
      stop_at_max_compression_(stop_at_max_compression),
      e_only_(e_only),
      history_(history),
      rule_(rule_for(model, e_only)),
      v_com_prev_(-model.velocity),
      energy_reference_(model.energy_initial) {}

void RunBookkeeping::relaunch(double added_energy, const RunState& s) {
  rule_ = rule_for(m_, e_only_);
  energy_reference_ += added_energy;
  v_com_prev_ = relative_velocity(s);
}

std::optional<RunStatus> RunBookkeeping::sample(const RunState& s, double kinetic, bool row) {
  // The sphere's velocity at the sampled time: the mean of the half steps around it.
  const double v_mean = 0.5 * (relative_velocity(s) + v_com_prev_);
  v_com_prev_ = relative_velocity(s);
  const EnergySums& w = s.energy;
  const double total = kinetic + w.internal + w.hourglass + w.viscous + w.contact + w.friction +
                       w.absorbed + w.boundary + w.mass_scaling;
  const double balance = (total - energy_reference_) / m_.energy_initial;
  if (!std::isfinite(balance)) {
    balance_max_ = std::numeric_limits<double>::quiet_NaN();
    return RunStatus::kNonFinite;
  }
  balance_max_ = std::max(balance_max_, std::abs(balance));
  if (row) {
    const double x = m_.extensive;
    append_row(history_, HistoryRow{.time = s.t,
                                    .contact_force = x * s.force,
                                    .indentation = s.hysteresis.indentation,
                                    .sphere_velocity = -v_mean,
                                    .kinetic_energy = x * kinetic,
                                    .strain_energy = x * (w.internal - w.plastic),
                                    .plastic_dissipation = x * w.plastic,
                                    .hourglass_energy = x * w.hourglass,
                                    .viscous_dissipation = x * w.viscous,
                                    .contact_energy = x * w.contact,
                                    .energy_balance_error = balance});
  }
  return std::nullopt;
}

std::optional<RunStatus> RunBookkeeping::stop(
    const RunState& s, double ke_sphere, double window, double since, bool penetrating) {
  rule_.accumulate(ke_sphere, window);
  const auto decision = rule_.update(s.t, since, penetrating, relative_velocity(s));
  if (decision == SeparationRule::Decision::kRebound) return RunStatus::kSeparated;
  if (decision == SeparationRule::Decision::kNoRebound) return RunStatus::kNotSeparated;
  if (stop_at_max_compression_ && rule_.touched() && relative_velocity(s) >= 0.0) {
    return RunStatus::kMaxCompression;
  }
  return std::nullopt;
}

}  // namespace corlab::fem::solver
