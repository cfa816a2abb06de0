// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file impact_step.hpp
/// One central-difference step, in the two halves between which the energy balance and the
/// history are sampled: move_nodes (kinematics: v^{n+1/2}, x^{n+1}, kinetic energy at t^n) and
/// compute_forces (elements and contact at x^{n+1}, time advanced, next stable step).

#include <algorithm>

#include "fem/solver/element_loop.hpp"
#include "fem/solver/impact_model.hpp"
#include "fem/solver/impact_state.hpp"
#include "fem/solver/run_state.hpp"

namespace corlab::fem::solver {

/// What the force half of a step found.
struct ForceReport {
  ElementSums elements;
  bool penetrating = false;   ///< any slave in contact at x^{n+1}
  int inverted_element = -1;  ///< mesh index of an inverted element, or -1
};

/// The element passes' work into the running energies, their plastic strain into the largest.
inline void add_element_work(const ElementSums& sums, RunState& s) {
  s.energy.internal += sums.internal_work;
  s.energy.plastic += sums.plastic_work;
  s.energy.hourglass += sums.hourglass_work;
  s.energy.viscous += sums.viscous_work;
  s.eps_p_max = std::max(s.eps_p_max, sums.eps_p_max);
}

/// The nodal arrays of the state and the model (element_loop.hpp).
NodalArrays nodal_arrays(const ImpactModel& model, ImpactState& state);

/// Kinetic energy of the rebound [J] for the stop rule's window average, from the nodal update's
/// sums: the sphere's (on a flat), or both spheres' less their common c.o.m. motion's (free
/// target) (elastic waves included, as e_energy has always counted them).
double rebound_kinetic_energy(const ImpactModel& model,
                              const ImpactState& state,
                              const NodeSums& sums);

/// The sphere's kinetic energy now [J] (at the last half step's velocities).
double sphere_kinetic_energy(const ImpactModel& model, const ImpactState& state);

/// Sends the bodies back at the approach speed for another impact (impact.repeats): each node's
/// velocity shifted so that the sphere's c.o.m. moves at -v0 and a free target's is at rest again,
/// their vibrations, stresses, plastic strain and shape kept. Returns the kinetic energy added [J].
double relaunch_bodies(const ImpactModel& model, ImpactState& state);

/// One sample of the force-indentation loop: the contact force now and the sphere's indentation
/// at its newest c.o.m. height. The plain step samples after each force half, the subcycled one
/// at each major-cycle boundary.
void sample_hysteresis(const ImpactModel& model, ImpactState& state);

/// Kinematic half: velocities and positions; returns the kinetic energies at t^n and the sphere's
/// momentum at t^{n+1/2}.
NodeSums move_nodes(const ImpactModel& model, ImpactState& state);

/// Force half: stresses, internal, hourglass and contact forces at x^{n+1}, a hysteresis sample;
/// advances t by dt and sets the next dt from the stable step.
ForceReport compute_forces(const ImpactModel& model, ImpactState& state);

/// Element subcycling (docs/theory/solver.md section 11; model.levels.max_level > 0). Base step k
/// = state.step; state.dt is the base step, changed only at major-cycle boundaries (k a multiple
/// of 2^max_level, where every node and element is in sync).

/// The largest level L <= max_level with step % 2^L == 0 (max_level for step 0).
int sync_level(long long step, int max_level);

/// Kinematic half of base step k: the nodes of level <= sync_level(k) (those due at t^k) get the
/// impulses of the elements due at t^k and move over their own step. At a major-cycle boundary
/// also the sphere's momentum and c.o.m. at t^k and a hysteresis sample; the returned kinetic
/// energy is then the whole model's.
NodeSums move_nodes_subcycled(const ImpactModel& model, ImpactState& state);

/// Force half of base step k: the elements of level <= sync_level(k + 1) over their own interval
/// ending at t^{k+1} (2^L-weighted forces into fr/fz), contact (level-0 nodes); advances t; at a
/// major-cycle end, the next base step from each level's latest stable step.
ForceReport compute_forces_subcycled(const ImpactModel& model, ImpactState& state);

}  // namespace corlab::fem::solver
