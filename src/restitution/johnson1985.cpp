// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/restitution/johnson1985.hpp"

#include <algorithm>
#include <cmath>

#include "corlab/core/units.hpp"

namespace corlab::restitution {

using units::kPi;

double johnson_energy_prefactor() { return 3.0 * std::pow(kPi, 1.25) * std::pow(4.0, 0.75) / 10.0; }

double johnson_yield_velocity(double yield_stress,
                              double effective_modulus,
                              double sphere_density) {
  // sqrt(26 Y^5 / (rho E*^4)) in logs
  return std::exp(0.5 * (std::log(26.0) + 5.0 * std::log(yield_stress) - std::log(sphere_density) -
                         4.0 * std::log(effective_modulus)));
}

double Johnson1985::flow_pressure() const { return 3.0 * pair.yield_stress; }

double Johnson1985::yield_velocity() const {
  return johnson_yield_velocity(pair.yield_stress, pair.effective_modulus, pair.sphere_density);
}

double Johnson1985::fully_plastic(double velocity) const {
  // e^2 = 3.548 (p_d/E*) (1/2 m v^2/(p_d R^3))^(-1/4), 1/2 m v^2/(p_d R^3) = (2 pi/3) rho v^2/p_d
  const double pd = flow_pressure();
  const double ln_group = std::log(2.0 * kPi / 3.0) + std::log(pair.sphere_density) +
                          2.0 * std::log(velocity) - std::log(pd);
  return std::sqrt(johnson_energy_prefactor() * pd / pair.effective_modulus) *
         std::exp(-0.125 * ln_group);
}

double Johnson1985::cor(double velocity) const {
  if (velocity <= yield_velocity()) return 1.0;
  const double e = fully_plastic(velocity);
  return clamp ? std::clamp(e, 0.0, 1.0) : e;
}

}  // namespace corlab::restitution
