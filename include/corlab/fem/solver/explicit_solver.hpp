// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file explicit_solver.hpp
/// The explicit axisymmetric impact solver on a given mesh (simulate() builds the mesh from the
/// config and calls this). Central differences, one-point quads with hourglass control,
/// J2 plasticity, bulk viscosity, node-to-segment penalty contact; see docs/theory/solver.md.

#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/mesh/mesh.hpp"
#include "corlab/fem/solver/impact_result.hpp"
#include "corlab/fem/solver/simulate.hpp"

namespace corlab::fem {

/// Runs one impact on `mesh` (laid out as mesh.hpp says: sphere above the substrate at the gap).
/// The config's mesh.* keys are ignored here; the config must have passed validate() (simulate()
/// checks it: a config is validated once, where it enters). Throws InputError for an invalid mesh;
/// every other outcome (clean rebound, no rebound by t_max, inverted element, collapsed step,
/// non-finite state, step budget, cancel) is the result's `status` (run_status.hpp), and e is
/// NaN unless the status is kSeparated.
ImpactResult run_impact(const ImpactConfig& config,
                        const Mesh& mesh,
                        const SimulationControl& control = {});

}  // namespace corlab::fem
