// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file jackson_green2005.hpp
/// Jackson R.L., Green I. (2005), "A finite element study of elasto-plastic hemispherical
/// contact against a rigid flat", J. Tribol. 127(2):343-354: critical (yield-onset) quantities
/// and the elastic-plastic loading law of a sphere of radius R on a flat.

namespace corlab::restitution {

/// C(nu) = 1.295 exp(0.736 nu), nu of the yielding body (here the substrate) [-].
double jackson_green_c(double poisson_ratio);

/// Critical quantities and the loading law. Inputs: E' (= E*) [Pa], S_y (substrate yield
/// stress) [Pa], nu of the substrate [-], sphere radius R [m].
struct JacksonGreen2005 {
  double effective_modulus = 0.0;  ///< E' = E* [Pa]
  double yield_stress = 0.0;       ///< S_y [Pa]
  double poisson_ratio = 0.0;      ///< nu of the yielding body [-]
  double radius = 1.0;             ///< R [m]

  /// Switch from Hertz to the elastic-plastic fit at omega* = 1.9.
  static constexpr double kHertzLimit = 1.9;

  /// C(nu) [-].
  double c() const;
  /// omega_c = (pi C S_y / (2E'))^2 R [m].
  double critical_interference() const;
  /// P_c = 4/3 (R/E')^2 (C pi S_y / 2)^3 [N].
  double critical_force() const;
  /// B = 0.14 exp(23 S_y / E') [-].
  double b_exponent() const;
  /// a/R at interference omega [m]: sqrt(omega/R) (omega*/1.9)^(B/2) above 1.9 omega_c,
  /// Hertz sqrt(omega/R) below [-].
  double contact_radius_ratio(double interference) const;
  /// H_G/S_y = 2.84 [1 - exp(-0.82 (a/R)^-0.7)] [-] at interference omega [m].
  double hardness_ratio(double interference) const;
  /// Dimensionless load P/P_c at omega* = omega/omega_c >= 0:
  /// omega* <= 1.9: omega*^1.5; else exp(-0.25 omega*^(5/12)) omega*^1.5
  ///   + 4 H_G/(C S_y) [1 - exp(-omega*^(5/9)/25)] omega*.
  double load_ratio(double normalized_interference) const;
  /// Load P at interference omega [m] -> [N].
  double load(double interference) const;
};

/// Jackson & Green's (2005) hardness of a sphere flattened by a rigid flat at contact radius
/// ratio a/R >= 0: H_G/S_y = 2.84 [1 - exp(-0.82 (a/R)^-0.7)] [-] (2.84 for a/R -> 0; it falls
/// as the flat grows, unlike the indentation hardness of a half-space).
double jackson_green_hardness_ratio(double a_over_r);

/// Jackson-Green critical (yield-onset) velocity of a sphere on a flat:
/// V_c = sqrt(pi^4/40) (C S_y)^2.5 / (E'^2 sqrt(rho)) [m/s] (from 1/2 m V_c^2 = 2/5 P_c omega_c;
/// equals Thornton's v_y with p_y = C S_y; independent of R).
double jackson_green_critical_velocity(double effective_modulus,
                                       double yield_stress,
                                       double poisson_ratio,
                                       double sphere_density);

}  // namespace corlab::restitution
