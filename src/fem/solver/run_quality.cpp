// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/run_quality.hpp"

#include <fmt/format.h>

#include <cmath>

namespace corlab::fem {

std::string suspect_reason(const ImpactResult& r, const QualityLimits& limits) {
  if (!std::isfinite(r.energy_balance_error) || r.energy_balance_error > limits.energy_balance) {
    return fmt::format("energy balance error {:.3g} % (limit {:.3g} %)",
                       100.0 * r.energy_balance_error, 100.0 * limits.energy_balance);
  }
  const double hourglass = r.energy_hourglass / r.energy_initial;
  if (!(std::abs(hourglass) <= limits.hourglass_energy)) {
    return fmt::format("hourglass energy {:.3g} % of the initial energy (limit {:.3g} %)",
                       100.0 * hourglass, 100.0 * limits.hourglass_energy);
  }
  if (r.delta_max > 0.0 && r.penetration_max > limits.penetration * r.delta_max) {
    return fmt::format("contact penetration {:.3g} % of the indentation (limit {:.3g} %)",
                       100.0 * r.penetration_max / r.delta_max, 100.0 * limits.penetration);
  }
  return {};
}

}  // namespace corlab::fem
