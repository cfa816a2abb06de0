// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/restitution/ma2023.hpp"

#include <algorithm>
#include <cmath>

namespace corlab::restitution {

namespace {
// Ma et al. 2023 eqs. 9, 11: e = a + 0.056 ln k1, a = 1.16 + 0.253 ln k2.
constexpr double kIntercept = 1.16;
constexpr double kSlopeK2 = 0.253;
constexpr double kSlopeK1 = 0.056;
}  // namespace

double Ma2023::published_yield_velocity() const {
  const double sy = pair.yield_stress;
  const double es = pair.effective_modulus;
  // sqrt(15.81 sy^4.5 / (rho E*^3.5)) in logs (no overflow for any valid input).
  return std::exp(0.5 * (std::log(kMaYieldConstant) + 4.5 * std::log(sy) -
                         std::log(pair.sphere_density) - 3.5 * std::log(es)));
}

double Ma2023::exact_yield_velocity() const {
  // log branch = 1  <=>  ln(E*/(rho v^2)) = -(0.16 + 0.253 ln k2)/0.056
  const double ln_k2 = std::log(pair.yield_stress / pair.effective_modulus);
  const double ln_v2 = ((kIntercept - 1.0) + kSlopeK2 * ln_k2) / kSlopeK1 +
                       std::log(pair.effective_modulus / pair.sphere_density);
  return std::exp(0.5 * ln_v2);
}

double Ma2023::yield_velocity() const {
  return exact_crossing ? exact_yield_velocity() : published_yield_velocity();
}

double Ma2023::log_branch(double velocity) const {
  const double ln_k2 = std::log(pair.yield_stress / pair.effective_modulus);
  const double ln_k1 =
      std::log(pair.effective_modulus) - std::log(pair.sphere_density) - 2.0 * std::log(velocity);
  return kIntercept + kSlopeK2 * ln_k2 + kSlopeK1 * ln_k1;
}

double Ma2023::cor(double velocity) const {
  if (velocity < yield_velocity()) return 1.0;
  const double e = log_branch(velocity);
  return clamp ? std::clamp(e, 0.0, 1.0) : e;
}

}  // namespace corlab::restitution
