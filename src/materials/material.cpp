// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/materials/material.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "corlab/core/error.hpp"
#include "corlab/core/units.hpp"

namespace corlab {

namespace {
// Largest accepted yield strain sigma_y/E [-]: metals yield below ~1 %; 10 % leaves room for
// polymers and soft alloys while catching unit slips (MPa typed as Pa, or Pa as GPa).
constexpr double kMaxYieldStrain = 0.1;
}  // namespace

double Material::dilatational_wave_speed() const { return std::sqrt(p_wave_modulus() / density); }

void validate(const Material& material, std::string_view field_prefix, bool require_yield) {
  const std::string p(field_prefix);
  require_positive(p + ".E", material.youngs_modulus, "[Pa]");
  require_open_range(p + ".nu", material.poisson_ratio, -1.0, 0.5);
  require_positive(p + ".rho", material.density, "[kg/m^3]");
  if (material.yield_stress) {
    const double sy = *material.yield_stress;
    if (!(std::isfinite(sy) && sy > 0.0 && sy < kMaxYieldStrain * material.youngs_modulus)) {
      throw_invalid(p + ".sigma_y", sy,
                    "in (0, 0.1 E) [Pa] (a yield strain above 10 % is no metal)");
    }
  } else if (require_yield) {
    throw_invalid(p + ".sigma_y", "missing", "given for an elastic-plastic substrate [Pa]");
  }
  require_non_negative(p + ".H", material.hardening_modulus, "[Pa]");
  if (!(material.hardening_modulus < material.youngs_modulus)) {
    throw_invalid(p + ".H", material.hardening_modulus,
                  fmt::format("< {}.E = {:g} [Pa]", p, material.youngs_modulus));
  }
}

double effective_modulus(double e1, double nu1, double e2, double nu2) {
  return 1.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2);
}

double effective_modulus(const Material& sphere, const Material& substrate) {
  return effective_modulus(sphere.youngs_modulus, sphere.poisson_ratio, substrate.youngs_modulus,
                           substrate.poisson_ratio);
}

double k1(double effective_modulus, double sphere_density, double velocity) {
  return effective_modulus / (sphere_density * velocity * velocity);
}

double hertz_contact_time_factor() {
  // 2 int_0^1 (1 - x^(5/2))^(-1/2) dx = 2 (2/5) B(2/5, 1/2) = (4/5) sqrt(pi) G(2/5) / G(9/10).
  return 0.8 * std::sqrt(units::kPi) * std::tgamma(0.4) / std::tgamma(0.9);
}

double pair_effective_density(double radius_ratio, double sphere_density, double density_ratio) {
  const double r = radius_ratio;
  if (r <= 1.0) {
    const double r3 = r * r * r;
    return sphere_density * std::pow(1.0 + r, 3) / (1.0 + density_ratio * r3);
  }
  // divided by r^3, so that a large ratio (1e200: inf / inf) stays finite, towards rho2
  const double s = 1.0 / r;
  return sphere_density * std::pow(1.0 + s, 3) / (s * s * s + density_ratio);
}

Material pair_reduced_sphere(const Material& sphere, const Material& other, double radius_ratio) {
  if (!(std::isfinite(radius_ratio) && radius_ratio >= 0.0)) {
    throw_invalid("radius_ratio", radius_ratio, ">= 0 and finite (R1/R2, 0 for a flat) [-]");
  }
  Material reduced = sphere;
  if (radius_ratio > 0.0) {
    reduced.density =
        pair_effective_density(radius_ratio, sphere.density, sphere.density / other.density);
  }
  return reduced;
}

double k2(double yield_stress, double effective_modulus) {
  return yield_stress / effective_modulus;
}

}  // namespace corlab
