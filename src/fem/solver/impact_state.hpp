// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file impact_state.hpp
/// The mutable part of one impact run (MuJoCo's data): nodal kinematics and forces, element
/// stresses, contact cursors, time, and the running energy and response sums. One step
/// (impact_step.hpp) maps a state to the next.

#include <algorithm>
#include <array>
#include <vector>

#include "fem/solver/element_loop.hpp"
#include "fem/solver/impact_model.hpp"
#include "fem/solver/impact_step_mass.hpp"
#include "fem/solver/run_state.hpp"
#include "fem/solver/transit_ledger.hpp"

namespace corlab::fem::solver {

/// The axisymmetric state; the time loop's running sums in its base (run_state.hpp).
struct ImpactState : RunState {
  std::vector<double> r, z;    ///< nodal positions [m]
  std::vector<double> vr, vz;  ///< nodal velocities at the last half step [m/s]
  std::vector<double> fr, fz;  ///< nodal forces being assembled [N]
  ElementState elements;
  std::vector<int> cursor;  ///< master segment of each slave at the last step
  // Subcycling only (model.levels.max_level > 0; docs/theory/solver.md section 11): fr/fz then
  // hold the 2^L-weighted forces of the elements due at each node's next update.
  /// Smallest stable step / 2^L over the elements of level L at their latest update [s].
  std::array<double, kMaxSubcyclingLevels + 1> level_dt_min{};
  bool cycle_penetrating = false;    ///< any slave in contact during this major cycle
  double t_first_penetrating = 0.0;  ///< start of the cycle's first step in contact [s]
  TransitLedger transit;             ///< energy in transit between levels
  /// In-run mass scaling (impact_step_mass.hpp; off unless solver.in_run_step_floor > 0): its
  /// nodal masses and step scales replace the model's.
  InRunScaling scaling;
};

/// The approach since the start [m]: the sphere's c.o.m. displacement towards the target less the
/// target's (a free sphere's) displacement away from the sphere.
inline double indentation(const ImpactModel& m, const ImpactState& s) {
  return (m.z_com_start - s.sphere_com_z) - (m.z_com_target_start - s.target_com_z);
}

/// The state at the start: sphere touching, moving down at v0; everything else at rest.
ImpactState make_initial_state(const ImpactModel& model);

}  // namespace corlab::fem::solver
