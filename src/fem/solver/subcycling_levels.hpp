// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file subcycling_levels.hpp
/// The subcycling levels of an impact model (docs/theory/solver.md section 11).

#include "corlab/fem/config/impact_config.hpp"
#include "fem/solver/impact_model.hpp"

namespace corlab::fem::solver {

/// Sets m.levels (solver.subcycling_levels > 0) and sorts the elements by level; max_level stays 0
/// (the run then steps as without subcycling) when no element can take a longer step or the
/// saving is below 1 - kMaxUpdateFraction. Needs the masses (m.step_scale, m.dt_critical).
void set_levels(const SolverConfig& sc, ImpactModel& m);

}  // namespace corlab::fem::solver
