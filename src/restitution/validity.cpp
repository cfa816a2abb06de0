// Validity warnings of the CoR models (validity.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/restitution/validity.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace corlab::restitution {

CalibrationCheck calibration_check(const ModelInfo& info,
                                   std::span<const double> velocities,
                                   const Material& sphere,
                                   const Material& substrate) {
  CalibrationCheck check;
  if (!info.calibrated || !substrate.yield_stress) return check;
  const DimensionlessBox& box = *info.calibrated;
  const double e_star = effective_modulus(sphere, substrate);
  check.known = true;
  check.k2 = k2(*substrate.yield_stress, e_star);
  check.k2_outside = check.k2 < box.k2_min || check.k2 > box.k2_max;
  check.k1_outside.reserve(velocities.size());
  for (const double v : velocities) {
    const double k1_value = k1(e_star, sphere.density, v);
    check.k1_outside.push_back(k1_value < box.k1_min || k1_value > box.k1_max);
  }
  return check;
}

std::vector<std::string> validity_warnings(const ModelInfo& info,
                                           std::span<const double> velocities,
                                           const Material& sphere,
                                           const Material& substrate) {
  std::vector<std::string> out;
  if (velocities.empty()) return out;
  const double v_max = *std::max_element(velocities.begin(), velocities.end());
  if (v_max > kMaxModelVelocity) {
    out.push_back(fmt::format(
        "model '{}': velocity {:g} m/s is beyond {:g} m/s, outside every model (hypervelocity "
        "impact: no equation of state, no quasi-static contact)",
        info.name, v_max, kMaxModelVelocity));
  }
  if (info.accurate_damage_number && substrate.yield_stress) {
    // Johnson's damage number rho v^2/sigma_y [-] grows with v: the largest is at v_max.
    const auto damage = [&](double v) { return sphere.density * v * v / *substrate.yield_stress; };
    const auto above = std::count_if(velocities.begin(), velocities.end(), [&](double v) {
      return damage(v) > *info.accurate_damage_number;
    });
    if (above > 0) {
      out.push_back(fmt::format(
          "model '{}' is less accurate: {} of {} velocities give a damage number rho v^2/sigma_y "
          "above {:g} (up to {:.3g}), where its held-out errors grow beyond 2 % RMS "
          "(docs/theory/corlab_model.md)",
          info.name, above, velocities.size(), *info.accurate_damage_number, damage(v_max)));
    }
  }
  const CalibrationCheck check = calibration_check(info, velocities, sphere, substrate);
  if (!check.known) return out;
  const DimensionlessBox& box = *info.calibrated;
  const auto outside =
      static_cast<std::size_t>(std::count(check.k1_outside.begin(), check.k1_outside.end(), true));
  if (outside == 0 && !check.k2_outside) return out;
  out.push_back(
      fmt::format("model '{}' extrapolates: {} of {} velocities give k1 = E*/(rho v^2) outside its "
                  "calibration [{:.3g}, {:.3g}], k2 = sigma_y/E* = {:.3g} {} [{:.3g}, {:.3g}] ({})",
                  info.name, outside, velocities.size(), box.k1_min, box.k1_max, check.k2,
                  check.k2_outside ? "outside" : "inside", box.k2_min, box.k2_max, info.validity));
  return out;
}

std::string radius_ratio_warning(const ModelInfo& info, double radius_ratio) {
  if (!info.fitted_radius_ratio || !(radius_ratio > *info.fitted_radius_ratio)) return {};
  return fmt::format(
      "model '{}' extrapolates: radius_ratio = R1/R2 = {:g} is beyond its fitted {:g} (the "
      "sphere is the larger body; to stay in the fitted range give the other body as the "
      "sphere and R2/R1 = {:.4g})",
      info.name, radius_ratio, *info.fitted_radius_ratio, 1.0 / radius_ratio);
}

}  // namespace corlab::restitution
