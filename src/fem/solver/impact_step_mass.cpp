// In-run selective mass scaling of the axisymmetric model (impact_step_mass.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "fem/solver/impact_step_mass.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "corlab/core/units.hpp"
#include "fem/solver/impact_model.hpp"
#include "fem/solver/impact_state.hpp"

namespace corlab::fem::solver {
namespace {

/// Adds dm [kg] to node n with its momentum kept; returns the kinetic energy that takes out [J]
/// (1/2 m v^2 dm / (m + dm) >= 0).
double add_node_mass(InRunScaling& sc, ImpactState& s, int n, double dm) {
  const auto i = static_cast<std::size_t>(n);
  const double m_old = sc.mass[i];
  const double m_new = m_old + dm;
  const double v2 = s.vr[i] * s.vr[i] + s.vz[i] * s.vz[i];
  const double keep = m_old / m_new;
  s.vr[i] *= keep;
  s.vz[i] *= keep;
  sc.mass[i] = m_new;
  sc.inv_mass[i] = 1.0 / m_new;
  return 0.5 * m_old * v2 * (1.0 - keep);
}

/// Raises element e's step from step[e] to kInRunHeadroom x the floor if the budget allows;
/// returns whether it did.
bool raise_element(const ImpactModel& m, ImpactState& s, int e) {
  InRunScaling& sc = s.scaling;
  const auto k = static_cast<std::size_t>(e);
  const double g = kInRunHeadroom * sc.step_floor / sc.step[k];
  const double s_old = sc.step_scale[k];
  const double s_new = g * s_old;
  const double dm = sc.element_mass[k] * (s_new * s_new - s_old * s_old);
  if (sc.added_mass + dm > sc.mass_budget) {
    sc.exhausted = true;
    return false;
  }
  for (int n : m.elements.nodes(e)) s.energy.mass_scaling += add_node_mass(sc, s, n, 0.25 * dm);
  if (sc.factor[k] == 1.0) sc.scaled.push_back(e);
  sc.added_mass += dm;
  sc.step_scale[k] = s_new;
  sc.factor[k] *= g;
  sc.step[k] *= g;
  return true;
}

}  // namespace

void init_in_run_scaling(const SolverConfig& sc, const ImpactModel& m, ImpactState& s) {
  const bool allowed =
      m.levels.max_level == 0 && m.contact == ContactKind::kSegments && !m.free_target;
  if (!(sc.in_run_step_floor > 0.0) || !allowed) return;
  InRunScaling& r = s.scaling;
  r.step_floor = sc.in_run_step_floor * m.dt_critical;
  r.mass_budget = sc.in_run_added_mass * m.scaling.sphere_mass_physical;
  r.mass = m.mass;
  r.inv_mass = m.inv_mass;
  r.step_scale = m.elements.step_scale;
  const auto ne = static_cast<std::size_t>(m.n_elements);
  r.factor.assign(ne, 1.0);
  r.step.assign(ne, 0.0);
  r.element_mass.assign(ne, 0.0);
  for (int e = m.n_sphere_elements; e < m.n_elements; ++e) {
    r.element_mass[static_cast<std::size_t>(e)] =
        m.substrate.density * 2.0 * units::kPi * initial_geometry(m, e).omega;
  }
}

double scale_below_floor(const ImpactModel& m, ImpactState& s, double substrate_dt_min) {
  InRunScaling& sc = s.scaling;
  if (sc.exhausted || !(substrate_dt_min < sc.step_floor)) return substrate_dt_min;
  double dt_min = substrate_dt_min;
  bool raised = false;
  for (int e = m.n_sphere_elements; e < m.n_elements && !sc.exhausted; ++e) {
    if (sc.step[static_cast<std::size_t>(e)] < sc.step_floor) raised |= raise_element(m, s, e);
  }
  if (!raised) return dt_min;
  dt_min = *std::min_element(sc.step.begin() + m.n_sphere_elements, sc.step.end());
  return dt_min;
}

void count_in_run_step(InRunScaling& sc, double dt_min) {
  double unscaled = dt_min;
  for (int e : sc.scaled) {
    const auto k = static_cast<std::size_t>(e);
    unscaled = std::min(unscaled, sc.step[k] / sc.factor[k]);
  }
  sc.steps_unscaled += dt_min / unscaled;
}

}  // namespace corlab::fem::solver
