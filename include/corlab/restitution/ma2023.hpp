// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file ma2023.hpp
/// Seed model: Ma J., Jie H., Bai M., Peng J., Chen H., Chen D. (2023), "Research on normal
/// restitution coefficient based on dimensionless analyses", Chinese J. Theor. Appl. Mech.
/// 55(4):982-990, eqs. 5, 6, 12, 18, 19.

#include "corlab/restitution/impact_pair.hpp"

namespace corlab::restitution {

/// Ma et al. 2023 eq. 18 constant: c sigma0^-4.5 E0*^3.5 = 0.05 * 10^2.5 = 15.811 (printed 15.81)
/// [SI: m^2/s^2 * kg/m^3 * Pa^-1]. The printed value is used.
inline constexpr double kMaYieldConstant = 15.81;

/// Ma et al. 2023 eq. 19:
///   e = 1                                                   v <  v_y
///   e = 1.16 + 0.253 ln(sigma_y/E*) + 0.056 ln(E*/(rho v^2))  v >= v_y
/// with v_y from eq. 18 (or, with `exact_crossing`, the velocity v_y* where the log branch
/// equals 1 exactly, so that e is continuous and never above 1).
struct Ma2023 {
  ImpactPair pair;              ///< materials
  bool exact_crossing = false;  ///< use v_y* instead of eq. 18's v_y
  bool clamp = true;            ///< clamp e to [0, 1]

  /// Eq. 18: v_y = sqrt(15.81 sigma_y^4.5 / (rho E*^3.5)) [m/s].
  double published_yield_velocity() const;
  /// Exact crossing of the log branch with e = 1:
  /// v_y* = sqrt(exp(0.16/0.056) (sigma_y/E*)^(0.253/0.056) E*/rho) [m/s].
  double exact_yield_velocity() const;
  /// The yield velocity in use (published or exact) [m/s].
  double yield_velocity() const;
  /// The log branch of eq. 19 at v [m/s], without the v_y switch or clamping [-].
  double log_branch(double velocity) const;
  /// CoR at impact speed v > 0 [m/s] (no input check; see registry.hpp for checked calls).
  double cor(double velocity) const;
};

}  // namespace corlab::restitution
