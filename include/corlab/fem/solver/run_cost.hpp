// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file run_cost.hpp
/// A-priori cost of one impact run, for scheduling (longest first) and budgets: the mesh the run
/// would use, its smallest stable step, and the expected number of steps to the end of a
/// rebound (1.3 Hertz contact times + 4 sphere wave transits, as the progress estimate; 1.5 Hertz
/// contact times for the 3-D model).

#include "corlab/fem/config/impact_config.hpp"

namespace corlab::fem {

struct RunCost {
  int elements = 0;           ///< elements of the built-in (or file) mesh [-]
  double time_step = 0.0;     ///< first stable step x safety factor [s]
  double expected_steps = 0;  ///< steps to the expected end of the run [-]
  /// elements x expected_steps: proportional to the run's CPU time [-]
  double element_steps() const { return elements * expected_steps; }
};

/// Builds the mesh of `config` (milliseconds) and estimates the run's cost. Throws InputError
/// like simulate() for an invalid config.
RunCost estimate_run_cost(const ImpactConfig& config);

}  // namespace corlab::fem
