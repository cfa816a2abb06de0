// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dem/contact_laws.hpp"

#include <cmath>

#include "corlab/core/error.hpp"
#include "corlab/core/units.hpp"

namespace corlab::dem {

double hertz_stiffness(double effective_modulus, double effective_radius) {
  return 4.0 / 3.0 * effective_modulus * std::sqrt(effective_radius);
}

double linear_restitution(double damping, double effective_mass, double stiffness) {
  const double zeta = damping / (2.0 * std::sqrt(effective_mass * stiffness));
  if (zeta >= 1.0) return 0.0;  // overdamped: no rebound
  return std::exp(-units::kPi * zeta / std::sqrt(1.0 - zeta * zeta));
}

double linear_damping_for_restitution(double restitution, double effective_mass, double stiffness) {
  require_closed_range("restitution", restitution, kMinRestitution, 1.0);
  const double log_e = std::log(restitution);
  return 2.0 * std::sqrt(effective_mass * stiffness) * std::abs(log_e) /
         std::sqrt(log_e * log_e + units::kPi * units::kPi);
}

}  // namespace corlab::dem
