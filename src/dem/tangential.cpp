// The tangential (Mindlin, Coulomb) part of a DEM export: G*, k_t/a and each code's form.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dem/tangential.hpp"

#include <cmath>

#include "corlab/core/error.hpp"

namespace corlab::dem {

double mindlin_shear_modulus(const Material& a, const Material& b) {
  return 1.0 / ((2.0 - a.poisson_ratio) / a.shear_modulus() +
                (2.0 - b.poisson_ratio) / b.shear_modulus());
}

double mindlin_coefficient(double shear_modulus) { return 8.0 * shear_modulus; }

double tangential_damping_ratio(double shear_modulus, double effective_modulus) {
  return std::sqrt(4.0 * shear_modulus / effective_modulus);
}

void validate_friction(double friction) {
  if (!std::isfinite(friction) || friction < 0.0) {
    throw_invalid("friction", friction, ">= 0 (Coulomb mu; 0: frictionless)");
  }
}

}  // namespace corlab::dem
