// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file material.hpp
/// An isotropic material as the impact models and the solver see it (SI units).

#include <optional>
#include <string>
#include <string_view>

namespace corlab {

/// Isotropic elastic or elastic-plastic (J2, linear isotropic hardening) material.
struct Material {
  std::string name;                    ///< database key or "inline"
  double youngs_modulus = 0.0;         ///< E [Pa]
  double poisson_ratio = 0.0;          ///< nu [-], in (-1, 0.5)
  double density = 0.0;                ///< rho [kg/m^3]
  std::optional<double> yield_stress;  ///< sigma_y [Pa]; empty = purely elastic
  double hardening_modulus =
      0.0;             ///< H [Pa], plastic tangent d(sigma_y)/d(eps_p); 0 = perfectly plastic
  std::string source;  ///< where the values come from (citation)

  /// Shear modulus G = E / (2 (1 + nu)) [Pa].
  double shear_modulus() const { return youngs_modulus / (2.0 * (1.0 + poisson_ratio)); }
  /// Bulk modulus K = E / (3 (1 - 2 nu)) [Pa].
  double bulk_modulus() const { return youngs_modulus / (3.0 * (1.0 - 2.0 * poisson_ratio)); }
  /// P-wave (constrained) modulus lambda + 2 G [Pa].
  double p_wave_modulus() const {
    return youngs_modulus * (1.0 - poisson_ratio) /
           ((1.0 + poisson_ratio) * (1.0 - 2.0 * poisson_ratio));
  }
  /// Dilatational wave speed sqrt((lambda + 2G)/rho) [m/s].
  double dilatational_wave_speed() const;
};

/// Checks every field; throws InputError naming `<field_prefix>.<field>` on the first bad value.
/// Constraints: E > 0, nu in (-1, 0.5), rho > 0, sigma_y (if set) in (0, 0.1 E)
/// (a yield strain above 10 % is no metal), H >= 0. `require_yield` demands a yield stress
/// (substrates).
void validate(const Material& material, std::string_view field_prefix, bool require_yield = false);

/// Effective (contact) modulus of a pair: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 [Pa]
/// (Ma et al. 2023 eq. 3; Johnson 1985 eq. 4.22).
double effective_modulus(const Material& sphere, const Material& substrate);

/// Effective modulus from the four constants [Pa].
double effective_modulus(double e1, double nu1, double e2, double nu2);

/// Ma et al. 2023 eq. 5: k1 = E* / (rho v^2) [-], rho = sphere density [kg/m^3] (a pair of
/// spheres: rho*, pair_effective_density), v [m/s].
double k1(double effective_modulus, double sphere_density, double velocity);

/// rho* = 3 m* / (4 pi R*^3) [kg/m^3] of a sphere (radius R1, density rho1) hitting a free
/// sphere (R2, rho2): rho1 (1 + r)^3 / (1 + (rho1/rho2) r^3) with r = R1/R2; r = 0 is a flat
/// (rho* = rho1), two identical spheres give 4 rho1.
/// @param radius_ratio R1/R2 >= 0 [-]  @param sphere_density rho1 [kg/m^3]
/// @param density_ratio rho1/rho2 [-]
double pair_effective_density(double radius_ratio, double sphere_density, double density_ratio);

/// The sphere whose impact on a flat of `other` is the pair's Hertz impact: `sphere` with the
/// density rho* of pair_effective_density() for R1/R2 = radius_ratio [-] (itself for 0, a
/// flat). Throws InputError naming "radius_ratio" unless it is >= 0 and finite.
Material pair_reduced_sphere(const Material& sphere, const Material& other, double radius_ratio);

/// Dimensionless Hertz contact duration t_c v / delta_max =
/// 2 int_0^1 (1 - x^(5/2))^(-1/2) dx = (4/5) sqrt(pi) Gamma(2/5) / Gamma(9/10) = 2.943275...
/// (Johnson 1985, eq. 11.24) [-]: the one Hertz contact-time reference (the FE's time scales,
/// the MBF integration, the DEM time step).
double hertz_contact_time_factor();

/// Ma et al. 2023 eq. 6: k2 = sigma_y / E* [-], sigma_y = substrate yield stress [Pa].
double k2(double yield_stress, double effective_modulus);

}  // namespace corlab
