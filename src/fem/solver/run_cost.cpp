// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/run_cost.hpp"

#include "corlab/fem/mesh/mesh_generator.hpp"
#include "fem/solver/hex_model.hpp"
#include "fem/solver/impact_model.hpp"

namespace corlab::fem {

RunCost estimate_run_cost(const ImpactConfig& config) {
  validate(config);  // a public entry point: the solver's model takes only checked configs
  if (uses_3d_model(config)) return hex_solver::estimate_hex_run_cost(config);
  const solver::ImpactModel m = solver::make_impact_model(config, build_impact_mesh(config));
  RunCost cost;
  cost.elements = m.n_elements;
  cost.time_step = m.dt_initial;
  cost.expected_steps = (m.t_expected - m.t_start) / m.dt_initial;
  return cost;
}

}  // namespace corlab::fem
