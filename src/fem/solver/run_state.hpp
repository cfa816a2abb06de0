// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file run_state.hpp
/// What the time loop (time_loop.hpp) and its bookkeeping (run_bookkeeping.hpp) read of a run,
/// whatever its geometry: the constants every model has (RunConstants, a base of the
/// axisymmetric ImpactModel and of the 3-D HexModel) and the running sums every state keeps
/// (RunState, a base of ImpactState and HexState). Private to src/fem/solver.

#include <algorithm>
#include <cstdint>

#include "corlab/fem/solver/simd_level.hpp"

namespace corlab::fem::solver {

/// What the contact slaves (the sphere's surface) meet, in either model: the one
/// representation of the target's surface.
enum class ContactKind : std::uint8_t {
  kSegments,      ///< the substrate surface's master segments (axisymmetric node-to-segment)
  kBlockSurface,  ///< the 3-D block's smooth top (node on surface, hex_master_surface.hpp)
  kRigidPlane,    ///< the rigid flat z = 0 (substrate.shape = rigid; no master nodes)
};

/// Running energies [J] (work done up to the current time), of the model.
struct EnergySums {
  double internal = 0.0;   ///< internal (strain + plastic) work
  double plastic = 0.0;    ///< plastic dissipation
  double hourglass = 0.0;  ///< hourglass work
  double viscous = 0.0;    ///< bulk-viscosity dissipation
  double contact = 0.0;    ///< penalty energy stored now (normal and tangential springs)
  double friction = 0.0;   ///< frictional dissipation (0 without friction)
  double absorbed = 0.0;   ///< work taken out by the absorbing far boundary (dashpots.hpp)
  double boundary = 0.0;   ///< energy stored now in the viscous-spring boundary's springs
  /// Kinetic energy taken out where in-run mass scaling added mass with the momentum kept
  /// (impact_step_mass.hpp; 0 without it)
  double mass_scaling = 0.0;
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

/// The constants of a run that the time loop, the bookkeeping and the result read.
struct RunConstants {
  /// Approach speed along the contact normal [m/s]: the impact speed v0 (3-D: v0 cos(angle)).
  double velocity = 0.0;
  double energy_initial = 0.0;  ///< kinetic energy at the start, of the model [J]
  /// Kinetic energy of the relative motion at the start [J]: energy_initial on a flat, 1/2 m* v0^2
  /// on a free sphere (the rest is the pair's c.o.m. motion, which the impact cannot change).
  double energy_relative_initial = 0.0;
  double dt_initial = 0.0;     ///< safety_factor x the smallest element stable step [s]
  double safety_factor = 0.0;  ///< [-]
  double t_start = 0.0;        ///< gap / normal speed: the gap is crossed in free flight [s]
  double t_max = 0.0;          ///< hard stop [s]
  double t_wave = 0.0;         ///< shortest window of the stop rule, 4 R / c_d of the sphere [s]
  double t_expected = 0.0;     ///< expected end, for the progress estimate [s]
  double z_com_start = 0.0;    ///< sphere c.o.m. height at the start [m]
  long long max_steps = 0;     ///< step budget (solver.max_steps)
  SimdLevel simd = SimdLevel::kBaseline;  ///< the hot loops' instruction set (simd_level.hpp)
  /// The whole pair over the model, for its forces, energies and masses [-]: 1 (axisymmetric: the
  /// whole body), 2 (the 3-D half model).
  double extensive = 1.0;
};

/// The running part of a state that the time loop, the bookkeeping and the result read.
struct RunState {
  double t = 0.0;        ///< time since the release [s]
  double dt = 0.0;       ///< next step [s]
  double dt_prev = 0.0;  ///< last step [s] (0 before the first)
  long long step = 0;
  EnergySums energy;
  double eps_p_max = 0.0;         ///< largest equivalent plastic strain so far [-]
  double force = 0.0;             ///< contact force on the sphere now, + up [N]
  double force_max = 0.0;         ///< [N]
  HysteresisLoop hysteresis;      ///< sampled each step (subcycling: each major cycle)
  double penetration_max = 0.0;   ///< deepest slave penetration [m]
  double sphere_velocity = 0.0;   ///< sphere c.o.m. normal velocity at the last half step, + up
                                  ///< [m/s]
  double sphere_com_z = 0.0;      ///< sphere c.o.m. height at the newest positions [m]
  double target_velocity = 0.0;   ///< a free target's c.o.m. velocity, + up [m/s] (else 0)
  double target_com_z = 0.0;      ///< a free target's c.o.m. height [m] (else 0)
  long long element_updates = 0;  ///< element updates done (with subcycling < elements x steps)
};

/// The sphere's velocity relative to the target along the normal, + up (apart) [m/s]: the
/// sphere's own on a flat.
inline double relative_velocity(const RunState& s) { return s.sphere_velocity - s.target_velocity; }

/// Time advanced by the step just taken.
inline void advance_time(RunState& s) {
  s.t += s.dt;
  ++s.step;
  s.dt_prev = s.dt;
}

}  // namespace corlab::fem::solver
