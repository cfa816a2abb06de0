// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file config_limits.hpp
/// Limits that join several config keys, checked before a run starts so that a meaningless or
/// unaffordable run is refused with one line naming the input instead of crashing, hanging or
/// ending in NaN:
///  - impact.gap <= sphere.radius (the gap is crossed in exact free flight, a wider one only
///    loses precision; a gap of 1e15 m broke the mesher);
///  - the predicted contact radius (contact_estimate.hpp, uncapped) <= 0.9 sphere.radius;
///  - substrate.radius and substrate.depth >= 2 predicted contact radii (Hertz: the axial stress
///    below the contact is p0 / (1 + z^2/a^2), 20 % of p0 at z = 2a, Johnson 1985 eq. 3.45; the
///    prediction over-estimates a, and the paper's own L = 2R substrate at 70 m/s is 2.6 a wide);
///  - yield strain sigma_y/E in [1e-5, 0.1) and hardening H < E for a plastic body;
///  - solver.safety_factor <= 1/sqrt(1 + solver.penalty_scale): the contact spring adds
///    penalty_scale (2/dt_crit)^2 to the highest squared frequency, so the step must shrink;
///  - solver.t_max (when given) > gap/velocity, the moment of contact;
///  - the estimated number of time steps <= solver.max_steps;
///  - impact.angle 0 with solver.model = axisymmetric, and 0 or >= 1 deg with 3d: below 1 deg
///    the tangential speed (1.7 % of the impact speed at 1 deg) is swamped by the tangential
///    velocity a normal impact itself leaves, and e_t = v_x'/v_x means nothing (1e-10 deg gave
///    e_t = -678697).
///  - the a-priori element count <= solver.max_elements and element count x expected steps <=
///    solver.max_element_steps (work caps, checked before anything is meshed: a 10 m second
///    sphere meshed 2.8 million elements and ran past 20 min);
///  - mesh.h_max >= mesh.h_min, with either model.

#include "corlab/fem/config/impact_config.hpp"

namespace corlab::fem {

/// Smallest accepted substrate radius and depth, in predicted contact radii [-].
inline constexpr double kMinSubstrateContactRadii = 2.0;
/// Smallest oblique angle the 3-D model accepts [deg] (0 is a normal impact).
inline constexpr double kMinObliqueAngle = 1.0;
/// Accepted yield strain sigma_y / E [-] of a plastic body.
inline constexpr double kMinYieldStrain = 1e-5;
inline constexpr double kMaxYieldStrain = 0.1;

/// A-priori cost of a run (built-in mesh only; for a Gmsh file the element size is unknown).
struct RunEstimate {
  double contact_radius = 0.0;  ///< predicted, uncapped [m]
  double element_size = 0.0;    ///< h at the contact [m]
  double wave_speed = 0.0;      ///< largest dilatational wave speed of the two bodies [m/s]
  double time_step = 0.0;       ///< safety_factor x (h / sqrt 2) / c x damping reduction [s]
  double simulated_time = 0.0;  ///< (t_max - gap/velocity) x impact.repeats [s]
  double steps = 0.0;           ///< simulated_time / time_step [-]
  /// Elements of the built-in mesh, from its sizes alone (estimate_elements) [-].
  double elements = 0.0;
  /// Steps to the expected end of the run (run_cost.hpp's rule, x impact.repeats) [-].
  double expected_steps = 0.0;
  /// elements x expected_steps: the run's work [-].
  double element_steps() const { return elements * expected_steps; }
};

/// The built-in mesh's element count of `config` without building it [-]: each body's section
/// (2-D) or half volume (3-D) integrated over the distance d from the contact point, dA / h(d)^2
/// or dV / h(d)^3, with h = the contact size within the refined zone, then growing by
/// (mesh.growth - 1) per unit length up to mesh.h_max; a tensor grid without transitions (the
/// axisymmetric flat with mesh.transitions = 0, the 3-D flat) counted exactly from its 1-D
/// grading. Within 0.5x-2x of the mesh's count for every case of the shipped studies (a test).
double estimate_elements(const ImpactConfig& config);

/// The estimate for `config` (whose keys are each within range).
RunEstimate estimate_run(const ImpactConfig& config);

/// Checks the limits above; throws InputError naming the field, its value and the limit.
void validate_limits(const ImpactConfig& config);

}  // namespace corlab::fem
