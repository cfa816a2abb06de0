// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/restitution/thornton1997.hpp"

#include <algorithm>
#include <cmath>

#include "corlab/core/units.hpp"
#include "corlab/restitution/jackson_green2005.hpp"

namespace corlab::restitution {

using units::kPi;

double thornton_yield_velocity(double limiting_pressure,
                               double effective_modulus,
                               double sphere_density) {
  // 1.5605 sqrt(p^5/(E*^4 rho)) in logs.
  return kThorntonYieldConstant *
         std::exp(0.5 * (5.0 * std::log(limiting_pressure) - 4.0 * std::log(effective_modulus) -
                         std::log(sphere_density)));
}

double thornton_closed_form(double velocity_ratio) {
  const double r = std::clamp(velocity_ratio, 0.0, 1.0);
  const double r2 = r * r;
  const double root = std::sqrt(6.0 / 5.0 - r2 / 5.0);
  return std::sqrt(6.0 * std::sqrt(3.0) / 5.0) * std::sqrt(1.0 - r2 / 6.0) *
         std::pow(r / (r + 2.0 * root), 0.25);
}

double ThorntonContact::yield_overlap() const {
  const double x = kPi * limiting_pressure / (2.0 * effective_modulus);
  return radius * x * x;
}

double ThorntonContact::yield_force() const {
  const double dy = yield_overlap();
  return 4.0 / 3.0 * effective_modulus * std::sqrt(radius) * dy * std::sqrt(dy);
}

double ThorntonContact::loading_force(double overlap) const {
  if (overlap <= 0.0) return 0.0;
  const double dy = yield_overlap();
  if (overlap <= dy) {
    return 4.0 / 3.0 * effective_modulus * std::sqrt(radius) * overlap * std::sqrt(overlap);
  }
  return yield_force() + kPi * limiting_pressure * radius * (overlap - dy);
}

ThorntonContact::Unloading ThorntonContact::unloading(double max_overlap) const {
  Unloading curve{.radius = radius, .offset = 0.0, .max_overlap = max_overlap};
  if (max_overlap <= yield_overlap()) return curve;
  const double f_max = loading_force(max_overlap);
  const double a2 = (2.0 * f_max + yield_force()) / (2.0 * kPi * limiting_pressure);
  curve.radius = 4.0 * effective_modulus / (3.0 * f_max) * a2 * std::sqrt(a2);
  curve.offset =
      max_overlap -
      std::cbrt(std::pow(3.0 * f_max / (4.0 * effective_modulus * std::sqrt(curve.radius)), 2.0));
  return curve;
}

double ThorntonContact::unloading_force(const Unloading& curve, double overlap) const {
  const double d = std::min(overlap, curve.max_overlap) - curve.offset;
  if (d <= 0.0) return 0.0;
  return 4.0 / 3.0 * effective_modulus * std::sqrt(curve.radius) * d * std::sqrt(d);
}

double Thornton1997::limiting_pressure() const {
  switch (pressure) {
    case ThorntonPressure::kHertzOnset:
      return 1.6 * pair.yield_stress;
    case ThorntonPressure::kJacksonGreenC:
      return jackson_green_c(pair.substrate_poisson) * pair.yield_stress;
    case ThorntonPressure::kYieldStress:
      return pair.yield_stress;
  }
  return 1.6 * pair.yield_stress;
}

double Thornton1997::yield_velocity() const {
  return thornton_yield_velocity(limiting_pressure(), pair.effective_modulus, pair.sphere_density);
}

double Thornton1997::cor(double velocity) const {
  const double vy = yield_velocity();
  if (velocity <= vy) return 1.0;
  return thornton_closed_form(vy / velocity);
}

}  // namespace corlab::restitution
