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
///  - the estimated number of time steps <= solver.max_steps.

#include "corlab/fem/config/impact_config.hpp"

namespace corlab::fem {

/// Smallest accepted substrate radius and depth, in predicted contact radii [-].
inline constexpr double kMinSubstrateContactRadii = 2.0;
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
};

/// The estimate for `config` (whose keys are each within range).
RunEstimate estimate_run(const ImpactConfig& config);

/// Checks the limits above; throws InputError naming the field, its value and the limit.
void validate_limits(const ImpactConfig& config);

}  // namespace corlab::fem
