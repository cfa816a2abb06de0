// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file thornton1997.hpp
/// Thornton C. (1997), "Coefficient of restitution for collinear collisions of
/// elastic-perfectly plastic spheres", J. Appl. Mech. 64:383-386: the contact law (Hertz up to
/// a limiting contact pressure p_y, then truncated pressure), its yield velocity and its
/// closed-form CoR.

#include "corlab/restitution/impact_pair.hpp"

namespace corlab::restitution {

/// Which limiting contact pressure p_y Thornton's model uses. Which choice the seed paper used
/// for its "Thornton" curve is unconfirmed.
enum class ThorntonPressure {
  kHertzOnset,     ///< p_y = 1.6 sigma_y (von Mises onset under Hertz pressure, nu ~ 0.3)
  kJacksonGreenC,  ///< p_y = C(nu) sigma_y, C = 1.295 exp(0.736 nu) (Jackson & Green 2005)
  kYieldStress,    ///< p_y = sigma_y
};

/// sqrt(pi^4/40) = 1.5605214756...: v_y = kThorntonYieldConstant sqrt(p_y^5 / (E*^4 rho)).
inline constexpr double kThorntonYieldConstant = 1.5605214756132195;

/// Thornton (1997) yield velocity of a sphere on a flat:
/// v_y = sqrt(pi^4/40) sqrt(p_y^5/(E*^4 rho)) [m/s].
/// @param limiting_pressure p_y [Pa]   @param effective_modulus E* [Pa]
/// @param sphere_density rho [kg/m^3]
double thornton_yield_velocity(double limiting_pressure,
                               double effective_modulus,
                               double sphere_density);

/// Thornton (1997) closed form for r = v_y/v in (0, 1]:
/// e = sqrt(6 sqrt(3)/5) sqrt(1 - r^2/6) [r / (r + 2 sqrt(6/5 - r^2/5))]^(1/4); e(1) = 1.
double thornton_closed_form(double velocity_ratio);

/// Elastic-perfectly-plastic contact law of Thornton (1997) for a sphere of radius R on a flat.
/// Loading: Hertz F = 4/3 E* sqrt(R) d^1.5 up to d_y = R (pi p_y/(2E*))^2, then
/// F = F_y + pi p_y R (d - d_y). Unloading from d_max > d_y: Hertz with the radius R_p and
/// offset d_p that keep force and contact radius continuous at reversal.
struct ThorntonContact {
  double effective_modulus = 0.0;  ///< E* [Pa]
  double radius = 0.0;             ///< R [m]
  double limiting_pressure = 0.0;  ///< p_y [Pa]

  /// d_y = R (pi p_y / (2 E*))^2 [m].
  double yield_overlap() const;
  /// F_y = 4/3 E* sqrt(R) d_y^1.5 [N].
  double yield_force() const;
  /// Loading force at overlap d >= 0 [m] -> [N].
  double loading_force(double overlap) const;
  /// Unloading curve from the reversal point d_max [m].
  struct Unloading {
    double radius = 0.0;       ///< R_p = 4E*/(3F_max) ((2F_max + F_y)/(2 pi p_y))^1.5 [m]
    double offset = 0.0;       ///< d_p = d_max - (3F_max/(4E* sqrt(R_p)))^(2/3) [m]
    double max_overlap = 0.0;  ///< d_max [m]
  };
  /// The unloading curve after loading to d_max [m] (d_max > d_y; else R_p = R, d_p = 0).
  Unloading unloading(double max_overlap) const;
  /// Unloading force F = 4/3 E* sqrt(R_p) (d - d_p)^1.5 for d in [d_p, d_max], 0 below [N].
  double unloading_force(const Unloading& curve, double overlap) const;
};

/// Thornton (1997) CoR model (closed form, sphere on flat).
struct Thornton1997 {
  ImpactPair pair;                                            ///< materials
  ThorntonPressure pressure = ThorntonPressure::kHertzOnset;  ///< choice of p_y

  /// p_y [Pa] for the chosen ThorntonPressure.
  double limiting_pressure() const;
  /// v_y [m/s].
  double yield_velocity() const;
  /// CoR at v > 0 [m/s]: 1 for v <= v_y, else the closed form (always in (0, 1]).
  double cor(double velocity) const;
};

}  // namespace corlab::restitution
