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
#include "fem/solver/transit_ledger.hpp"

namespace corlab::fem::solver {

/// Running energies [J] (work done up to the current time).
struct EnergySums {
  double internal = 0.0;   ///< internal (strain + plastic) work
  double plastic = 0.0;    ///< plastic dissipation
  double hourglass = 0.0;  ///< hourglass work
  double viscous = 0.0;    ///< bulk-viscosity dissipation
  double contact = 0.0;    ///< penalty energy stored now
};

/// The trapezoidal integral of F d(delta) over the sampled (force, indentation) pairs: the
/// force-indentation loop's area, the energy the sphere left in the substrate.
struct HysteresisLoop {
  double force = 0.0;            ///< contact force at the last sample [N]
  double indentation = 0.0;      ///< sphere c.o.m. displacement since the start then [m]
  double area = 0.0;             ///< integral of F d(indentation) so far [J]
  double indentation_max = 0.0;  ///< [m]

  void sample(double f, double delta) {
    area += 0.5 * (force + f) * (delta - indentation);
    force = f;
    indentation = delta;
    indentation_max = std::max(indentation_max, delta);
  }
};

struct ImpactState {
  std::vector<double> r, z;    ///< nodal positions [m]
  std::vector<double> vr, vz;  ///< nodal velocities at the last half step [m/s]
  std::vector<double> fr, fz;  ///< nodal forces being assembled [N]
  ElementState elements;
  std::vector<int> cursor;  ///< master segment of each slave at the last step
  double t = 0.0;           ///< time [s]
  double dt = 0.0;          ///< next step [s]
  double dt_prev = 0.0;     ///< last step [s] (0 before the first)
  long long step = 0;
  EnergySums energy;
  double eps_p_max = 0.0;         ///< largest equivalent plastic strain so far [-]
  double force = 0.0;             ///< contact force on the sphere now, + up [N]
  double force_max = 0.0;         ///< [N]
  HysteresisLoop hysteresis;      ///< sampled each step (subcycling: each major cycle)
  double penetration_max = 0.0;   ///< deepest slave penetration [m]
  double sphere_velocity = 0.0;   ///< sphere c.o.m. velocity at the last half step, + up [m/s]
  double sphere_com_z = 0.0;      ///< sphere c.o.m. height at the newest positions [m]
  double target_velocity = 0.0;   ///< a free target's c.o.m. velocity, + up [m/s] (else 0)
  double target_com_z = 0.0;      ///< a free target's c.o.m. height [m] (else 0)
  long long element_updates = 0;  ///< element updates done (with subcycling < elements x steps)
  // Subcycling only (model.levels.max_level > 0; docs/theory/solver.md section 11): fr/fz then
  // hold the 2^L-weighted forces of the elements due at each node's next update.
  /// Smallest stable step / 2^L over the elements of level L at their latest update [s].
  std::array<double, kMaxSubcyclingLevels + 1> level_dt_min{};
  bool cycle_penetrating = false;    ///< any slave in contact during this major cycle
  double t_first_penetrating = 0.0;  ///< start of the cycle's first step in contact [s]
  TransitLedger transit;             ///< energy in transit between levels
};

/// The sphere's velocity relative to the target, + up (apart) [m/s]: the sphere's own on a flat.
inline double relative_velocity(const ImpactState& s) {
  return s.sphere_velocity - s.target_velocity;
}

/// The approach since the start [m]: the sphere's c.o.m. displacement towards the target less the
/// target's (a free sphere's) displacement away from the sphere.
inline double indentation(const ImpactModel& m, const ImpactState& s) {
  return (m.z_com_start - s.sphere_com_z) - (m.z_com_target_start - s.target_com_z);
}

/// The state at the start: sphere touching, moving down at v0; everything else at rest.
ImpactState make_initial_state(const ImpactModel& model);

}  // namespace corlab::fem::solver
