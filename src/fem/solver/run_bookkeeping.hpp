// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file run_bookkeeping.hpp
/// What every time loop of an impact run keeps the same way, whatever its geometry (axisymmetric
/// or 3-D) and stepping scheme (plain or subcycled; docs/dev/architecture.md, "One driver"): the
/// energy balance and the history rows at the times it samples, and the stop rule over the
/// windows between them. It reads the run only through RunConstants and RunState
/// (run_state.hpp). Private to the solver.

#include <optional>

#include "corlab/fem/solver/impact_result.hpp"
#include "corlab/fem/solver/run_status.hpp"
#include "corlab/fem/solver/separation_rule.hpp"
#include "fem/solver/run_state.hpp"

namespace corlab::fem::solver {

class RunBookkeeping {
 public:
  /// History rows go to `history`; `stop_at_max_compression` ends a run at the sphere's turning
  /// point, `e_only` watches the rebound over the short window of SeparationRule::e_only
  /// (SimulationControl).
  RunBookkeeping(const RunConstants& model,
                 bool stop_at_max_compression,
                 bool e_only,
                 ImpactHistory& history);

  /// At a sampled time (the state's; every node in sync), `kinetic` the model's kinetic energy
  /// then [J] (product form, less the subcycling's energy in transit): the energy balance, and a
  /// history row when `row` (extensive columns for the whole pair: x model.extensive).
  /// kNonFinite when the balance is not finite.
  std::optional<RunStatus> sample(const RunState& state, double kinetic, bool row);

  /// The stop rule on the relative velocity at the end of a window of `window` [s] over which the
  /// rebound kinetic energy (rebound_kinetic_energy) was `ke_sphere` [J]; `penetrating`: a slave
  /// was in contact in it, for the last `since` [s]. kSeparated, kNotSeparated or
  /// kMaxCompression when the run ends.
  std::optional<RunStatus> stop(
      const RunState& state, double ke_sphere, double window, double since, bool penetrating);

  /// A new impact (impact.repeats): the bodies were just sent back at the approach speed, adding
  /// `added_energy` [J] of kinetic energy; a fresh stop rule, the balance against the energy now.
  void relaunch(double added_energy, const RunState& state);

  const SeparationRule& rule() const { return rule_; }
  /// Largest |energy balance| / initial energy so far (NaN once non-finite) [-].
  double balance_max() const { return balance_max_; }

 private:
  const RunConstants& m_;
  bool stop_at_max_compression_;
  bool e_only_;
  ImpactHistory& history_;
  SeparationRule rule_;
  double v_com_prev_;  ///< relative velocity at the last sample [m/s]
  /// The total energy the balance compares with [J]: the initial kinetic energy, plus what each
  /// relaunch added.
  double energy_reference_;
  double balance_max_ = 0.0;
};

}  // namespace corlab::fem::solver
