// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/restitution/jackson_green2005.hpp"

#include <algorithm>
#include <cmath>

#include "corlab/core/units.hpp"
#include "corlab/restitution/thornton1997.hpp"

namespace corlab::restitution {

using units::kPi;

double jackson_green_c(double poisson_ratio) { return 1.295 * std::exp(0.736 * poisson_ratio); }

double JacksonGreen2005::c() const { return jackson_green_c(poisson_ratio); }

double JacksonGreen2005::critical_interference() const {
  const double x = kPi * c() * yield_stress / (2.0 * effective_modulus);
  return x * x * radius;
}

double JacksonGreen2005::critical_force() const {
  const double ratio = radius / effective_modulus;
  const double p = c() * kPi * yield_stress / 2.0;
  return 4.0 / 3.0 * ratio * ratio * p * p * p;
}

double JacksonGreen2005::b_exponent() const {
  return 0.14 * std::exp(23.0 * yield_stress / effective_modulus);
}

double JacksonGreen2005::contact_radius_ratio(double interference) const {
  const double w = std::max(interference, 0.0);
  const double hertz = std::sqrt(w / radius);
  const double s = w / critical_interference();
  if (s <= kHertzLimit) return hertz;
  return hertz * std::pow(s / kHertzLimit, 0.5 * b_exponent());
}

double jackson_green_hardness_ratio(double a_over_r) {
  if (a_over_r <= 0.0) return 2.84;
  return 2.84 * (1.0 - std::exp(-0.82 * std::pow(a_over_r, -0.7)));
}

double JacksonGreen2005::hardness_ratio(double interference) const {
  return jackson_green_hardness_ratio(contact_radius_ratio(interference));
}

double JacksonGreen2005::load_ratio(double normalized_interference) const {
  const double s = std::max(normalized_interference, 0.0);
  const double hertz = s * std::sqrt(s);
  if (s <= kHertzLimit) return hertz;
  const double hg = hardness_ratio(s * critical_interference());
  return std::exp(-0.25 * std::pow(s, 5.0 / 12.0)) * hertz +
         4.0 * hg / c() * (1.0 - std::exp(-std::pow(s, 5.0 / 9.0) / 25.0)) * s;
}

double JacksonGreen2005::load(double interference) const {
  return critical_force() * load_ratio(interference / critical_interference());
}

double jackson_green_critical_velocity(double effective_modulus,
                                       double yield_stress,
                                       double poisson_ratio,
                                       double sphere_density) {
  return thornton_yield_velocity(jackson_green_c(poisson_ratio) * yield_stress, effective_modulus,
                                 sphere_density);
}

}  // namespace corlab::restitution
