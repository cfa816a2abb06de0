// simulate(): config -> mesh -> explicit solver.
#include "corlab/fem/simulate.hpp"

#include "corlab/fem/explicit_solver.hpp"
#include "corlab/fem/mesh_generator.hpp"

namespace corlab::fem {

ImpactResult simulate(const ImpactConfig& config, const SimulationControl& control) {
  if (!control.config_validated) validate(config);
  const Mesh mesh = build_impact_mesh(config);
  return run_impact(config, mesh, control);
}

}  // namespace corlab::fem
