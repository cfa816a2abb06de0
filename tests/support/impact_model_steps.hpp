#pragma once
// The stable step of one element of a solver model, for the solver's unit tests.
#include "corlab/fem/kernels/stable_time_step.hpp"
#include "fem/solver/impact_model.hpp"

namespace corlab::fem::testing {

/// Physical stable step of (sorted) element e of `m` at the start positions, without mass
/// scaling (the model's own step is m.step_scale[e] times this) [s].
inline double physical_element_step(const solver::ImpactModel& m, int e) {
  const auto& p = e < m.n_sphere_elements ? m.sphere : m.substrate;
  return element_stable_time_step(characteristic_length(solver::initial_geometry(m, e)),
                                  p.wave_speed, p.b1);
}

}  // namespace corlab::fem::testing
