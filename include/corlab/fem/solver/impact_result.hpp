// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file impact_result.hpp
/// What one impact simulation returns: the summary numbers and the time histories.

#include <limits>
#include <string>
#include <vector>

#include "corlab/fem/solver/run_status.hpp"

namespace corlab::fem {

/// The time histories' columns, one value each (T = double: one row) or one entry per output
/// row (T = std::vector<double>: the histories). Their names, units and CSV columns:
/// history_columns.hpp.
template <class T>
struct HistoryColumns {
  T time;             ///< t [s], 0 = release at the gap
  T contact_force;    ///< F, force of the substrate on the sphere [N]
  T indentation;      ///< delta = sphere c.o.m. displacement - gap [m]
  T sphere_velocity;  ///< sphere c.o.m. velocity relative to the target, + towards it [m/s]
  /// [J] both bodies (product form; with subcycling less the energy in transit between levels,
  /// so that the energy columns add up to the initial energy)
  T kinetic_energy;
  T strain_energy;         ///< recoverable elastic strain energy [J]
  T plastic_dissipation;   ///< [J]
  T hourglass_energy;      ///< [J]
  T viscous_dissipation;   ///< bulk viscosity [J]
  T contact_energy;        ///< penalty energy [J]
  T energy_balance_error;  ///< (sum of the above - initial) / initial [-]
};

/// One row of the time histories.
using HistoryRow = HistoryColumns<double>;
/// Time histories, one entry per output row (structure of arrays).
using ImpactHistory = HistoryColumns<std::vector<double>>;

struct ImpactResult {
  RunStatus status = RunStatus::kNotSeparated;  ///< how the run ended (run_status.hpp)
  std::string status_detail;  ///< one line on a status other than separated (else empty)
  std::string suspect;        ///< why the run is suspect (run_quality.hpp), empty when it is not
  double e =
      0.0;  ///< CoR from momentum: rebound / impact c.o.m. velocity [-]; NaN unless separated
  double e_energy =
      0.0;  ///< CoR from the sphere's rebound kinetic energy [-]; NaN unless separated
  /// e of each impact that rebounded (impact.repeats; [e] for one; the list stops at the first
  /// impact that did not rebound, whose status is the run's) [-]
  std::vector<double> e_impacts;
  double e_last = 0.0;  ///< the last entry of e_impacts [-] (NaN unless the first impact rebounded)
  /// e on the mesh twice as coarse everywhere (discretisation_error.hpp) [-] (NaN unless estimated)
  double e_coarse = std::numeric_limits<double>::quiet_NaN();
  /// discretisation-error estimate of e: e +/- e_error [-] (discretisation_error.hpp; NaN unless
  /// estimated)
  double e_error = std::numeric_limits<double>::quiet_NaN();
  /// why an error estimate that was asked for has no e_error (no companion mesh, mesh.file,
  /// a companion or run without a clean rebound); empty when it has one or was not asked for
  std::string e_error_reason;
  /// Normal restitution -v_z' / v_z of the c.o.m. [-]: e itself on the axisymmetric model, the
  /// normal part of an oblique impact on the 3-D one; NaN unless separated
  double e_n = std::numeric_limits<double>::quiet_NaN();
  /// Tangential c.o.m. velocity ratio v_x' / v_x [-] (3-D model, impact.angle > 0; else NaN)
  double e_t = std::numeric_limits<double>::quiet_NaN();
  /// Rebound spin about the axis normal to the symmetry plane [rad/s] (> 0 rolls forward; 0 on
  /// the axisymmetric model)
  double omega = 0.0;
  double rebound_angle = 0.0;    ///< atan(v_x' / v_z') [deg from the normal] (normal impact: 0)
  double energy_friction = 0.0;  ///< frictional dissipation [J] (3-D model with friction)
  /// Energy the absorbing far boundary took out of the substrate [J] (substrate.boundary =
  /// absorbing; else 0): the elastic waves radiated into the half-space it stands for.
  double energy_absorbed = 0.0;
  /// discretisation-error estimate of e_t, from the same companions and estimator as e_error [-]
  /// (NaN unless estimated on an oblique impact)
  double e_t_error = std::numeric_limits<double>::quiet_NaN();
  /// discretisation-error estimate of omega, the same way [rad/s] (NaN unless estimated)
  double omega_error = std::numeric_limits<double>::quiet_NaN();
  double F_max = 0.0;               ///< largest contact force [N]
  double delta_max = 0.0;           ///< largest indentation (sphere c.o.m. displacement) [m]
  double t_contact = 0.0;           ///< duration of contact [s]
  double crater_depth = 0.0;        ///< residual depth of the substrate surface on the axis [m]
  double plastic_strain_max = 0.0;  ///< largest equivalent plastic strain left [-]
  double energy_initial = 0.0;      ///< sphere kinetic energy at impact [J]
  /// c.o.m. velocities at the end, + up (the sphere's rebound direction) [m/s]: the sphere's, and
  /// the target's (0 for a flat: it is the ground); m1 v1 + m2 v2 = m1 v0 down on a free sphere.
  double sphere_velocity_final = 0.0;
  double target_velocity_final = 0.0;
  /// Kinetic energy of the relative motion lost [J]: on a flat, initial - the sphere's after the
  /// rebound; on a free sphere, 1/2 m* v0^2 - both spheres' less their c.o.m. motion's.
  double energy_sphere_loss = 0.0;
  double energy_dissipated_plastic = 0.0;  ///< [J]
  double energy_hourglass = 0.0;           ///< at the end [J]
  double energy_viscous = 0.0;             ///< [J]
  double energy_balance_error = 0.0;       ///< max over the run of |balance| / initial [-]
  double hysteresis_area = 0.0;            ///< closed integral of F d(delta) [J]
  double penetration_max = 0.0;            ///< largest penalty penetration of a slave [m]
  double substrate_von_mises_max =
      0.0;                 ///< largest von Mises stress in the substrate at the end [Pa]
  bool separated = false;  ///< status == kSeparated (kept for the output schema)
  int elements = 0;
  int nodes = 0;
  long long steps = 0;
  long long element_updates = 0;  ///< element updates done (subcycling: < elements x steps) [-]
  double h_contact = 0.0;         ///< element size used at the contact [m]
  /// Who chose h_contact: "keys" (mesh.h_min, mesh.contact_elements) or "model" (the 3-D model's
  /// default when neither key is set: hex_resolution.hpp)
  std::string mesh_choice = "keys";
  std::string mesh_reason;  ///< one line: the rule, a/h and (the model's default) its basis
  double time_step = 0.0;   ///< initial stable time step [s]
  /// Mass scaling (docs/theory/solver.md section 12): base step / the physical one (1 = none) [-]
  double mass_scaling = 1.0;
  double added_mass_fraction = 0.0;  ///< mass added by the scaling / the sphere's mass [-]
  /// In-run mass scaling (solver.in_run_step_floor): mass it added / the sphere's mass [-]
  double in_run_added_mass_fraction = 0.0;
  int in_run_scaled_elements = 0;  ///< substrate elements it scaled [-]
  /// Steps it saved: those the run would have needed at the scaled elements' own steps, less
  /// those taken (an estimate along this run's path) [-]
  double in_run_steps_saved = 0.0;
  double energy_mass_scaling = 0.0;  ///< kinetic energy it took out, momentum kept [J]
  double end_time = 0.0;             ///< [s]
  double wall_s = 0.0;               ///< wall-clock time of the run [s]
  double element_steps_per_s = 0.0;  ///< throughput [1/s]
  std::string simd;                  ///< instruction set of the hot loops (simd_level.hpp)
  ImpactHistory history;
};

}  // namespace corlab::fem
