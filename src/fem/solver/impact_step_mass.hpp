// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file impact_step_mass.hpp
/// In-run selective mass scaling of the axisymmetric model (docs/theory/solver.md section 12,
/// "In the run"): the crater's elements flatten during a fast impact and their stable step falls
/// well below the run's first one; when a substrate element's step falls below the floor, its
/// density is raised until its step is kInRunHeadroom x the floor, within a bound on the mass
/// added. The mass joins its nodes with their momentum kept (v m / (m + dm)): the kinetic energy
/// that takes out is booked in the energy balance (EnergySums::mass_scaling), none is created.
/// Off with subcycling (its levels are fixed at the start), on a free target and on the rigid
/// flat. Private to src/fem/solver.

#include <vector>

#include "corlab/fem/config/impact_config.hpp"
#include "fem/solver/element_loop.hpp"

namespace corlab::fem::solver {

struct ImpactModel;
struct ImpactState;

/// A scaled element's step is raised to this factor times the floor, so that it is not scaled
/// again at each step as it keeps flattening (the mass it adds is at most this squared times
/// what the floor alone would take) [-].
inline constexpr double kInRunHeadroom = 1.1;

/// The in-run scaling's arrays and running totals (part of the state).
struct InRunScaling {
  double step_floor = 0.0;   ///< element stable step below which mass is added [s] (0 = off)
  double mass_budget = 0.0;  ///< the most mass it may add, both bodies [kg]
  std::vector<double> mass, inv_mass;  ///< nodal masses with what was added [kg], [1/kg]
  std::vector<double> step_scale;      ///< each element's step scale, the in-run factor in [-]
  std::vector<double> factor;          ///< each element's in-run step factor (1 = none) [-]
  std::vector<double> element_mass;    ///< each element's physical mass [kg]
  std::vector<double> step;            ///< each element's stable step at the last force half [s]
  std::vector<int> scaled;             ///< the elements scaled so far (sorted index)
  double added_mass = 0.0;             ///< mass added so far [kg]
  /// Sum over the steps of the step taken / the one the run would have taken without the in-run
  /// scaling: the steps the run would have needed to cover the same time [-].
  double steps_unscaled = 0.0;
  bool exhausted = false;  ///< an element needed more mass than the budget had left

  bool on() const { return step_floor > 0.0; }
};

/// Sets up the in-run scaling of a state at the start (off unless solver.in_run_step_floor > 0
/// and the model allows it): the floor is that fraction of the model's first stable step
/// (dt_critical), the budget solver.in_run_added_mass x the sphere's physical mass.
void init_in_run_scaling(const SolverConfig& sc, const ImpactModel& m, ImpactState& s);

/// After the element passes of a plain step (step[] set, substrate_dt_min their smallest
/// substrate step [s]): raises the substrate elements below the floor (budget allowing), books the
/// kinetic energy taken out, and returns the substrate's smallest stable step after it [s].
double scale_below_floor(const ImpactModel& m, ImpactState& s, double substrate_dt_min);

/// The steps' tally: `dt_min` [s] the step's smallest stable step as taken, against the one the
/// scaled elements would have had without their in-run factor.
void count_in_run_step(InRunScaling& sc, double dt_min);

}  // namespace corlab::fem::solver
