// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file subcycling_level.hpp
/// The element subcycling level rule (docs/theory/solver.md section 11), one for the solver's
/// levels (stable steps) and the mesh's explicit-cost model (characteristic lengths).

#include <cmath>

namespace corlab::fem {

/// An element gets level L only if 2^L x the smallest step <= kSubcyclingLevelMargin x its own,
/// so that it may deform (its stable step shrink by 1 - kSubcyclingLevelMargin) before it limits
/// the base step [-].
constexpr double kSubcyclingLevelMargin = 0.8;

/// A node of level L may carry an element of level L + 1 only if every element of level L at it
/// has its own step >= kInterfaceStepRatio x 2^L x the smallest [-]: long enough for level L + 1
/// by the margin above, had a neighbour or the contact not held it at L. The slower element's
/// impulse comes every 2^(L+1) base steps dt; a level-L element at its stable limit has modes
/// with omega 2^L dt ~ 2 x safety factor, so omega 2^(L+1) dt ~ pi: the resonance of impulse
/// multiple-time-step methods (Biesiadecki & Skeel 1993, J. Comput. Phys. 109, 318), where the
/// slow impulses pump energy into the fast modes while the slow force is large (measured: a 3:1
/// transition under the contact, its coarse level-1 element on h-wide level-0 columns, gained
/// 1.4e-4 of E0 during the contact, e = 1.00006 for an elastic impact). At this ratio
/// omega 2^(L+1) dt <= 1.28 (docs/theory/solver.md section 11, "Impulse resonance").
constexpr double kInterfaceStepRatio = 2.0 / kSubcyclingLevelMargin;

/// The largest level L <= max_level with 2^L x smallest <= kSubcyclingLevelMargin x own; smallest
/// and own in the same unit (stable steps [s], or characteristic lengths [m]).
inline int subcycling_level(double smallest, double own, int max_level) {
  int level = 0;
  while (level < max_level && std::ldexp(smallest, level + 1) <= kSubcyclingLevelMargin * own) {
    ++level;
  }
  return level;
}

}  // namespace corlab::fem
