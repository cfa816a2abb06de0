// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file johnson1985.hpp
/// Johnson K.L. (1985), Contact Mechanics, Cambridge University Press, ch. 11: yield onset of a
/// Hertz impact and the fully plastic rebound estimate (rigid-plastic loading at the dynamic
/// flow pressure p_d = 3Y, elastic Hertz unloading).

#include "corlab/restitution/impact_pair.hpp"

namespace corlab::restitution {

/// Prefactor of e^2 in the fully plastic estimate: 3 pi^(5/4) 4^(3/4) / 10 = 3.548...
double johnson_energy_prefactor();

/// Johnson's yield-onset velocity V_Y = sqrt(26 Y^5/(rho E*^4)) [m/s] (printed constant 26 is
/// unconfirmed; the exact onset with p_0 = 1.6Y gives 25.5).
double johnson_yield_velocity(double yield_stress, double effective_modulus, double sphere_density);

/// Fully plastic rebound, p_d = 3Y:
/// e = sqrt(3.548) (2 pi/3)^(-1/8) (p_d/E*)^(1/2) (rho v^2/p_d)^(-1/8) for v > V_Y; 1 below.
/// Valid only for v >> V_Y; exceeds 1 where the impact is not fully plastic, hence the default
/// clamp at 1.
struct Johnson1985 {
  ImpactPair pair;    ///< materials
  bool clamp = true;  ///< clamp e to [0, 1]

  /// p_d = 3 Y [Pa].
  double flow_pressure() const;
  /// V_Y [m/s].
  double yield_velocity() const;
  /// The fully plastic formula at v [m/s] without switch or clamp [-].
  double fully_plastic(double velocity) const;
  /// CoR at v > 0 [m/s].
  double cor(double velocity) const;
};

}  // namespace corlab::restitution
