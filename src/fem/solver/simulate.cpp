// simulate(): config -> mesh -> the explicit solver of solver.model (axisymmetric or 3-D).
#include "corlab/fem/solver/simulate.hpp"

#include "corlab/fem/mesh/mesh_generator.hpp"
#include "corlab/fem/solver/explicit_solver.hpp"
#include "fem/solver/hex_model.hpp"

namespace corlab::fem {

ImpactResult simulate(const ImpactConfig& config, const SimulationControl& control) {
  if (!control.config_validated) validate(config);
  if (uses_3d_model(config)) return hex_solver::run_hex_impact(config, control);
  return run_impact(config, build_impact_mesh(config), control);
}

}  // namespace corlab::fem
