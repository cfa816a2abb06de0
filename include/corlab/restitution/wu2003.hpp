// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file wu2003.hpp
/// Wu C.-Y., Li L.-Y., Thornton C. (2003), "Rebound behaviour of spheres for plastic impacts",
/// Int. J. Impact Eng. 28(9):929-946. UNVERIFIED: the paper's equation was not read; this is
/// "candidate form B" of the corlab model reference, chosen because it reproduces the seed
/// paper's statement that Wu's model exceeds 1 at low speed.

#include "corlab/restitution/impact_pair.hpp"

namespace corlab::restitution {

/// UNVERIFIED candidate: e = 0.62 [(p_y/E*) (v/V_y)]^(-1/4) for v > V_y, 1 below, with
/// p_y = 1.6 sigma_y and V_y Thornton's yield velocity (also unconfirmed). Not clamped by
/// default (it exceeds 1 at low speed, as the seed paper reports).
struct Wu2003 {
  ImpactPair pair;     ///< materials
  bool clamp = false;  ///< clamp e to [0, 1] (visible option)

  /// p_y = 1.6 sigma_y [Pa].
  double limiting_pressure() const;
  /// V_y (Thornton, p_y = 1.6 sigma_y) [m/s].
  double yield_velocity() const;
  /// CoR at v > 0 [m/s].
  double cor(double velocity) const;
};

}  // namespace corlab::restitution
