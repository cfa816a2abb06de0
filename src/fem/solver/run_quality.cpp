// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/run_quality.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

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
  // e above 1 beyond its error bar, or round-off without one: the first such impact.
  const bool has_bar = std::isfinite(r.e_error);
  const double excess =
      has_bar ? std::max(limits.restitution_excess, r.e_error) : limits.restitution_excess;
  const auto above = [&](double e, const std::string& name) -> std::string {
    if (!(e > 1.0 + excess)) return {};
    return fmt::format("{} = {:.6g} above 1 by more than {} ({:.3g}): the rebound gained energy",
                       name, e, has_bar ? "its error bar e_error" : "round-off", excess);
  };
  if (auto reason = above(r.e, "e"); !reason.empty()) return reason;
  for (std::size_t k = 0; k < r.e_impacts.size(); ++k) {
    if (auto reason = above(r.e_impacts[k], fmt::format("e_impacts[{}]", k)); !reason.empty())
      return reason;
  }
  return {};
}

}  // namespace corlab::fem
