// simulate(): config -> mesh -> explicit solver.
#include "corlab/fem/solver/simulate.hpp"

#include "corlab/fem/mesh/mesh_generator.hpp"
#include "corlab/fem/solver/explicit_solver.hpp"

namespace corlab::fem {

ImpactResult simulate(const ImpactConfig& config, const SimulationControl& control) {
  if (!control.config_validated) validate(config);
  const Mesh mesh = build_impact_mesh(config);
  return run_impact(config, mesh, control);
}

}  // namespace corlab::fem
