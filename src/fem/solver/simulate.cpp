// simulate(): config -> mesh -> the explicit solver of solver.model (axisymmetric or 3-D).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/simulate.hpp"

#include "corlab/fem/mesh/mesh_generator.hpp"
#include "corlab/fem/solver/explicit_solver.hpp"
#include "corlab/fem/solver/run_quality.hpp"
#include "fem/solver/hex_model.hpp"

namespace corlab::fem {

ImpactResult simulate(const ImpactConfig& config, const SimulationControl& control) {
  if (!control.config_validated) validate(config);
  ImpactResult r = uses_3d_model(config) ? hex_solver::run_hex_impact(config, control)
                                         : run_impact(config, build_impact_mesh(config), control);
  if (r.separated) r.suspect = suspect_reason(r);  // again, with every impact's e (repeats)
  return r;
}

}  // namespace corlab::fem
