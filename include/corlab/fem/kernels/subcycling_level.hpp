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
