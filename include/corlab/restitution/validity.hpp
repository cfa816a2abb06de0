// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file validity.hpp
/// Whether a CoR model is asked about the conditions it was made for: its calibration box in the
/// dimensionless groups k1 = E*/(rho v^2) and k2 = sigma_y/E* (ModelInfo::calibrated), and speeds
/// no quasi-static contact model covers. The answer is a list of one-line warnings: the numbers
/// are still computed (extrapolation is the user's call), but never silently.

#include <span>
#include <string>
#include <vector>

#include "corlab/materials/material.hpp"
#include "corlab/restitution/model_info.hpp"

namespace corlab::restitution {

/// Largest impact speed any of the analytic models can speak for [m/s] (hypervelocity impact
/// needs an equation of state; the same limit as the FE solver's impact.velocity).
inline constexpr double kMaxModelVelocity = 1000.0;

/// Where a model's calibration box (ModelInfo::calibrated) holds for a pair at some speeds.
struct CalibrationCheck {
  bool known = false;            ///< the model has a numeric box and the substrate a yield stress
  double k2 = 0.0;               ///< sigma_y,substrate / E* of the pair [-]
  bool k2_outside = false;       ///< k2 lies outside the box
  std::vector<bool> k1_outside;  ///< per velocity: k1 = E*/(rho v^2) lies outside the box
};

/// The box check behind validity_warnings(), per velocity [m/s] (the explorer shades where a
/// model extrapolates); not `known` (and no flags) when the box or the yield stress is missing.
CalibrationCheck calibration_check(const ModelInfo& info,
                                   std::span<const double> velocities,
                                   const Material& sphere,
                                   const Material& substrate);

/// One-line warnings for `info` evaluated at `velocities` [m/s] for the pair (the substrate has a
/// yield stress; a second sphere as its reduced sphere, pair_reduced_sphere): speeds beyond every
/// model, the calibration box, a damage number above ModelInfo::accurate_damage_number. Empty
/// when every velocity is inside the model's known validity.
std::vector<std::string> validity_warnings(const ModelInfo& info,
                                           std::span<const double> velocities,
                                           const Material& sphere,
                                           const Material& substrate);

/// The warning for a radius ratio R1/R2 [-] beyond the data `info` was fitted to (R1/R2 > 1 is a
/// sphere larger than the free sphere it hits: the same impact as the smaller one hitting the
/// larger, with the bodies' roles swapped; rho* is symmetric, the fitted shares are not); empty
/// when within it or the model has no such bound.
std::string radius_ratio_warning(const ModelInfo& info, double radius_ratio);

}  // namespace corlab::restitution
