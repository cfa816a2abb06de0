// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file contact_estimate.hpp
/// A-priori estimates of the contact of an elastic sphere on a substrate: the Hertz reference
/// (Johnson 1985, section 11.4) and a conservative contact radius used to size the refined mesh
/// zone.

#include "corlab/fem/config/impact_config.hpp"

namespace corlab::fem {

/// Quasi-static Hertz impact of a sphere of mass m = 4/3 pi R^3 rho on a fixed elastic
/// half-space (Johnson 1985, eqs. 11.22-11.24; Ma et al. 2023, eqs. 1-3); of two spheres with
/// R*, m*, E* in place of R, m, E* (Johnson 1985, section 11.4).
struct HertzReference {
  double effective_modulus = 0.0;  ///< E* [Pa], 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2
  double mass = 0.0;               ///< sphere mass m [kg] (m* = m1 m2 / (m1 + m2) of two spheres)
  double max_overlap = 0.0;        ///< delta_max = (15 m v^2 / (16 E* sqrt(R)))^(2/5) [m]
  double max_force = 0.0;          ///< F_max = 4/3 E* sqrt(R) delta_max^(3/2) [N]
  double contact_radius = 0.0;     ///< a_max = sqrt(R delta_max) [m]
  double contact_time = 0.0;       ///< t_c = hertz_contact_time_factor() delta_max / v [s]
};

/// Hertz force F = 4/3 E* sqrt(R) delta^(3/2) [N] at the overlap delta [m] (0 for delta <= 0) of a
/// sphere of radius R [m] on a half-space, E* [Pa] (Johnson 1985, eq. 4.23).
double hertz_force(double overlap, double sphere_radius, double effective_modulus);

/// Hertz contact radius a = sqrt(R delta) [m] at the overlap delta [m] (0 for delta <= 0).
double hertz_contact_radius(double overlap, double sphere_radius);

/// Hertz reference for the sphere (radius R [m], elastic constants, density) hitting the
/// substrate (elastic constants only; its yield stress is ignored) at `config.impact.velocity`.
HertzReference hertz_reference(const ImpactConfig& config);

/// Hertz peak contact pressure p0 = 3 F_max / (2 pi a_max^2) [Pa] (Johnson 1985, eq. 4.23).
double hertz_max_pressure(const HertzReference& hertz);

/// Mass 4/3 pi R^3 rho [kg] of a sphere of radius R [m] and density rho [kg/m^3].
double sphere_mass(double radius, double density);

/// The pair's effective radius of curvature [m]: R1 on a flat, R* = R1 R2 / (R1 + R2) on a second
/// sphere (Johnson 1985, eq. 4.19).
double contact_curvature_radius(const ImpactConfig& config);

/// The pair's effective mass [kg]: the sphere's on a fixed or rigid flat, m* = m1 m2 / (m1 + m2)
/// on a free second sphere.
double contact_mass(const ImpactConfig& config);

/// Hertz reference from R* [m], E* [Pa], m* [kg] and the approach speed v [m/s].
HertzReference hertz_reference_of_pair(double radius,
                                       double effective_modulus,
                                       double mass,
                                       double velocity);

/// Hertz reference from explicit values: R [m], E* [Pa], sphere density [kg/m^3], v [m/s].
HertzReference hertz_reference(double sphere_radius,
                               double effective_modulus,
                               double sphere_density,
                               double velocity);

/// Mean contact pressure assumed by the plastic contact-radius estimate, as a multiple of the
/// substrate yield stress [-]. Fully plastic indentation gives p_m ~ 2.8 sigma_y (Tabor 1951;
/// Johnson 1985, section 6.2); the lower value makes the estimate over-predict a (safe side).
inline constexpr double kPlasticMeanPressureFactor = 2.0;

/// Largest predicted contact radius as a fraction of R [-] (the estimate is capped there).
inline constexpr double kMaxContactRadiusFraction = 0.9;

/// Plastic contact-radius estimate [m] from the energy balance m v^2 / 2 = pi p_m R delta^2 with
/// a^2 = 2 R delta (fully plastic, truncated-sphere contact) and p_m = kPlasticMeanPressureFactor
/// sigma_y. Inputs: R [m], sphere density [kg/m^3], v [m/s], substrate yield stress [Pa].
double plastic_contact_radius(double sphere_radius,
                              double sphere_density,
                              double velocity,
                              double yield_stress);

/// The same from the pair's R* [m] and m* [kg].
double plastic_contact_radius_of_pair(double radius,
                                      double mass,
                                      double velocity,
                                      double yield_stress);

/// The larger of the Hertz and the plastic estimates [m] (the latter when the contact has a yield
/// stress: contact_yield_stress), not capped.
double uncapped_contact_radius(const ImpactConfig& config);

/// Conservative maximum contact radius [m] for sizing the mesh: uncapped_contact_radius, capped
/// at kMaxContactRadiusFraction x the smaller sphere's radius.
double predicted_contact_radius(const ImpactConfig& config);

}  // namespace corlab::fem
