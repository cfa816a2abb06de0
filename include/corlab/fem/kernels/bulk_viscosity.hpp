// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file bulk_viscosity.hpp
/// Bulk viscosity as in ABAQUS/Explicit (Analysis User's Guide, "Bulk viscosity"; von Neumann &
/// Richtmyer 1950 for the quadratic term). Viscous pressure
///   p_bv = b1 rho c_d L_e (-eps_vol_rate) + rho (b2 L_e)^2 eps_vol_rate^2   (quadratic only when
///   eps_vol_rate < 0, i.e. in compression),
/// returned here as the mean stress added to sigma_rr, sigma_zz, sigma_tt:
///   s_bv = -p_bv = rho L_e eps_vol_rate (b1 c_d + b2^2 L_e |min(eps_vol_rate, 0)|).
/// It damps the highest (ringing) frequency; it also lowers the stable step:
///   dt = (L_e / c_d) (sqrt(1 + xi^2) - xi),  xi = b1 + b2^2 L_e |min(eps_vol_rate, 0)| / c_d.

#include <algorithm>
#include <cmath>

namespace corlab::fem {

/// Viscous mean stress s_bv [Pa] (negative in compression) for the volumetric strain rate
/// eps_vol_rate [1/s], density rho [kg/m^3], wave speed c_d [m/s], length L_e [m].
inline double bulk_viscous_stress(
    double eps_vol_rate, double rho, double wave_speed, double length, double b1, double b2) {
  const double compression = std::max(-eps_vol_rate, 0.0);
  return rho * length * eps_vol_rate * (b1 * wave_speed + b2 * b2 * length * compression);
}

/// Fraction of critical damping of the highest mode, xi [-].
inline double bulk_viscous_damping_ratio(
    double eps_vol_rate, double wave_speed, double length, double b1, double b2) {
  const double compression = std::max(-eps_vol_rate, 0.0);
  const double inv_c = 1.0 / wave_speed;  // loop-invariant in the solver: hoisted
  return b1 + b2 * b2 * length * compression * inv_c;
}

}  // namespace corlab::fem
