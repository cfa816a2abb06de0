// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file transit_ledger.hpp
/// The subcycling's energy in transit (docs/theory/solver.md section 11): an element of level
/// L + 1 on a node of level L gives the node its impulse 2^{L+1} dt g every second node step,
/// while it books its work as the trapezoid of its forces over its own interval. Over one such
/// window (node step h, velocities v1 then v2 over the node's two drifts, g_start and g_end the
/// slow elements' summed force on the node at the window's ends) the product-form kinetic energy
/// plus the booked work change by
///     1/2 h (v2 - v1) . (g_end - g_start)
/// more than they would with every element at the node's step: energy that is in neither. The
/// ledger adds these terms up, so that the energy balance subtracts them. Private to the solver.

#include <array>
#include <vector>

#include "fem/solver/impact_model.hpp"

namespace corlab::fem::solver {

/// What one window adds to the kinetic plus booked energy beyond the work done, per node
/// component: h the node's step [s], v1/v2 its velocities over the window's two drifts [m/s],
/// g_start/g_end the slow elements' force on it at the window's ends [N]; result [J].
[[nodiscard]] constexpr double window_transit(
    double h, double v1, double v2, double g_start, double g_end) {
  return 0.5 * h * (v2 - v1) * (g_end - g_start);
}

/// The ledger's per-level records for the interface nodes of that level
/// (SubcyclingLevels::interface_nodes[L], same order).
struct TransitLevel {
  std::vector<double> g_r, g_z;  ///< slow elements' force at the window's start [N]
  std::vector<double> v_r, v_z;  ///< velocity over the window's first drift [m/s]
  std::vector<double> f_r, f_z;  ///< nodal force sums before the slow elements' pass [N]
};

/// Energy in transit so far and the open windows of every level.
struct TransitLedger {
  std::array<TransitLevel, kMaxSubcyclingLevels> levels;
  double energy = 0.0;  ///< sum of window_transit over the windows closed so far [J]

  /// Sizes the records (the run's start: no slow force yet, the nodes at rest or at v0 as given).
  void reset(const SubcyclingLevels& lv, const double* vr, const double* vz);
  /// Before the pass of the elements of level L + 1: the force sums fr, fz [N] of level L's
  /// interface nodes.
  void before_slow_pass(const SubcyclingLevels& lv, int level, const double* fr, const double* fz);
  /// After that pass (its forces scattered as 2^{L+1} g into fr, fz): closes level L's windows at
  /// node step h [s] with the nodes' present velocities (their second drift), adds their transit.
  void after_slow_pass(const SubcyclingLevels& lv,
                       int level,
                       double h,
                       const double* fr,
                       const double* fz,
                       const double* vr,
                       const double* vz);
  /// After the kick that opens level L's next windows: their first drift's velocities.
  void open_windows(const SubcyclingLevels& lv, int level, const double* vr, const double* vz);
};

}  // namespace corlab::fem::solver
