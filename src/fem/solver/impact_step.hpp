#pragma once
/// @file impact_step.hpp
/// One central-difference step, in the two halves between which the energy balance and the
/// history are sampled: move_nodes (kinematics: v^{n+1/2}, x^{n+1}, kinetic energy at t^n) and
/// compute_forces (elements and contact at x^{n+1}, time advanced, next stable step).

#include "fem/solver/element_loop.hpp"
#include "fem/solver/impact_model.hpp"
#include "fem/solver/impact_state.hpp"

namespace corlab::fem::solver {

/// What the force half of a step found.
struct ForceReport {
  ElementSums elements;
  bool penetrating = false;   ///< any slave in contact at x^{n+1}
  int inverted_element = -1;  ///< mesh index of an inverted element, or -1
};

/// Kinematic half: velocities and positions; returns the kinetic energies at t^n and the sphere's
/// momentum at t^{n+1/2}.
NodeSums move_nodes(const ImpactModel& model, ImpactState& state);

/// Force half: stresses, internal, hourglass and contact forces at x^{n+1}; advances t by dt and
/// sets the next dt from the stable step.
ForceReport compute_forces(const ImpactModel& model, ImpactState& state);

}  // namespace corlab::fem::solver
