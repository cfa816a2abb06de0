// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file hex_impact.hpp
/// The 3-D explicit impact solver (issue 27; docs/theory/solver3d.md): a sphere hits a flat
/// (the rigid plane z = 0 or a deformable block below it) at angle theta from the normal with
/// Coulomb friction mu, modelled as the half (y >= 0) cut by the plane of the velocity and the
/// normal. One-point hexahedra with
/// Flanagan-Belytschko hourglass control (hex8.hpp, hourglass.hpp), the J2 material point, the
/// Hughes-Winget rotation and the bulk viscosity of the axisymmetric solver (the same kernels),
/// node-on-plane or node-on-facet penalty contact (facet_contact.hpp) with the Coulomb return
/// map (coulomb_friction.hpp), central differences at the elements' stable step, and the
/// axisymmetric solver's stop rule (separation_rule.hpp) on the normal velocity. The second
/// sphere (substrate.shape = sphere) is not modelled in 3-D yet.

#include <string>

#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/solver/run_status.hpp"
#include "corlab/fem/solver/simulate.hpp"

namespace corlab::fem {

/// What a 3-D run gives. Velocities of the sphere's centre of mass; x is the tangential
/// direction of the impact (the sphere moves towards +x), z the normal (up).
struct HexImpactResult {
  RunStatus status = RunStatus::kNotSeparated;
  double e_n = 0.0;              ///< normal restitution -v_z' / v_z [-]
  double e_t = 0.0;              ///< tangential c.o.m. velocity ratio v_x' / v_x [-] (NaN: normal)
  double omega = 0.0;            ///< rebound spin about +y [rad/s] (> 0: rolling towards +x)
  double rebound_angle = 0.0;    ///< atan(v_x' / v_z') [deg from the normal]
  double vx_final = 0.0;         ///< c.o.m. tangential velocity after the impact [m/s]
  double vz_final = 0.0;         ///< c.o.m. normal velocity after the impact (+ up) [m/s]
  double F_max = 0.0;            ///< largest normal contact force, half model x 2 [N]
  double t_contact = 0.0;        ///< contact duration [s]
  double energy_initial = 0.0;   ///< kinetic energy at impact, whole sphere [J]
  double energy_friction = 0.0;  ///< frictional dissipation, whole sphere [J]
  double energy_dissipated_plastic = 0.0;  ///< [J]
  double energy_hourglass = 0.0;           ///< at the end [J]
  double energy_viscous = 0.0;             ///< bulk-viscosity dissipation [J]
  double energy_balance_error = 0.0;       ///< max over the run of |balance| / initial [-]
  double plastic_strain_max = 0.0;         ///< [-]
  double penetration_max = 0.0;            ///< deepest slave penetration [m]
  double h_contact = 0.0;                  ///< element size at the lowest point [m]
  double time_step = 0.0;                  ///< initial step [s]
  double end_time = 0.0;                   ///< simulated time at the end, from the release [s]
  std::string simd;                        ///< the element pass's SIMD level
  int elements = 0;                        ///< of the half model
  int nodes = 0;
  long long steps = 0;
  double wall_s = 0.0;  ///< [s]
};

/// Runs the 3-D impact of config's sphere on the flat (substrate.shape = flat: the substrate's
/// material, radius and depth; rigid: the plane z = 0): impact.velocity at impact.angle with
/// contact.friction; the mesh and solver keys apply. The config must have passed validate()
/// (which refuses what the 3-D model lacks: a second sphere, repeats, mesh files). From `control`:
/// cancel (status cancelled), progress (the fraction of the expected simulated time) and
/// on_hex_fields (at each output.times, counted from the release at impact.gap).
HexImpactResult simulate_hex_impact(const ImpactConfig& config,
                                    const SimulationControl& control = {});

}  // namespace corlab::fem
