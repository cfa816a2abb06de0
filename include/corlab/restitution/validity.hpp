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

/// One-line warnings for `info` evaluated at `velocities` [m/s] for the pair (the substrate has a
/// yield stress); empty when every velocity is inside the model's known validity.
std::vector<std::string> validity_warnings(const ModelInfo& info,
                                           std::span<const double> velocities,
                                           const Material& sphere,
                                           const Material& substrate);

}  // namespace corlab::restitution
