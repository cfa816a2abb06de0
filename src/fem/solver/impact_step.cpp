// One central-difference step: kinematics, then element and contact forces.
// SPDX-License-Identifier: BSD-3-Clause
#include "fem/solver/impact_step.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "corlab/fem/kernels/penalty_contact.hpp"
#include "corlab/fem/solver/contact_search.hpp"

namespace corlab::fem::solver {
namespace {

/// Node-to-segment penalty contact at the newest positions: forces into the state's fr/fz, the
/// stored penalty energy, the contact force on the sphere (s.force, s.force_max) and the deepest
/// penetration. Returns whether any slave penetrates.
bool apply_contact(const ImpactModel& m, ImpactState& s) {
  bool penetrating = false;
  double force = 0.0;
  double energy = 0.0;
  // The rigid flat's reaction goes nowhere (it has no nodes).
  double ignored_r = 0.0;
  double ignored_z = 0.0;
  for (std::size_t k = 0; k < m.slaves.size(); ++k) {
    const int i = m.slaves[k];
    SegmentProjection p;
    double* master_a[2] = {&ignored_r, &ignored_z};
    double* master_b[2] = {&ignored_r, &ignored_z};
    if (m.contact == ContactKind::kRigidPlane) {
      p = project_on_rigid_flat(s.z[i]);
      if (p.gap >= 0.0) continue;
    } else {
      const ContactCandidate c =
          find_contact(s.r.data(), s.z.data(), m.masters, s.r[i], s.z[i], s.cursor[k]);
      s.cursor[k] = c.segment;
      if (!c.active) continue;
      p = c.projection;
      const int a = m.masters[c.segment];
      const int b = m.masters[c.segment + 1];
      master_a[0] = &s.fr[a];
      master_a[1] = &s.fz[a];
      master_b[0] = &s.fr[b];
      master_b[1] = &s.fz[b];
    }
    energy += penalty_force(p, m.penalty[k], s.fr[i], s.fz[i], *master_a[0], *master_a[1],
                            *master_b[0], *master_b[1]);
    force += -m.penalty[k] * p.gap * p.nz;
    s.penetration_max = std::max(s.penetration_max, -p.gap);
    penetrating = true;
  }
  s.energy.contact = energy;
  s.force = force;
  s.force_max = std::max(s.force_max, force);
  return penetrating;
}

/// The step's element sums into the state's running energies and plastic strain; an inverted
/// element into the report (its mesh index).
void record_element_sums(const ImpactModel& m, ImpactState& s, ForceReport& rep) {
  const ElementSums& sums = rep.elements;
  if (sums.bad_element >= 0) rep.inverted_element = m.elements.mesh_index[sums.bad_element];
  add_element_work(sums, s);
}

/// Adds one pass's element sums to the step's.
void add_sums(const ElementSums& a, ElementSums& sums) {
  sums.internal_work += a.internal_work;
  sums.plastic_work += a.plastic_work;
  sums.hourglass_work += a.hourglass_work;
  sums.viscous_work += a.viscous_work;
  sums.eps_p_max = std::max(sums.eps_p_max, a.eps_p_max);
  sums.dt_min = std::min(sums.dt_min, a.dt_min);
  sums.omega_min = std::min(sums.omega_min, a.omega_min);
  if (sums.bad_element < 0) sums.bad_element = a.bad_element;
}

/// The substrate's element pass under in-run mass scaling (impact_step_mass.hpp): its stable
/// steps kept, the elements below the floor raised, the pass's sums into `sums` (the sphere's).
void substrate_scaled(const ImpactModel& m,
                      ImpactState& s,
                      const NodalArrays& x,
                      ElementSums& sums) {
  InRunScaling& sc = s.scaling;
  ElementSums substrate;
  element_loop(m.simd,
               {m.substrate, m.elements, s.elements, m.n_sphere_elements, m.n_elements, x, s.dt,
                sc.step_scale.data(), sc.step.data()},
               substrate);
  substrate.dt_min = scale_below_floor(m, s, substrate.dt_min);
  add_sums(substrate, sums);
  count_in_run_step(sc, sums.dt_min);
}

/// Element passes of one subcycled base step: levels 0..top, each over its own 2^L x dt; the
/// windows of the nodes below each level L >= 1 closed in the energy-in-transit ledger.
ElementSums subcycled_elements(const ImpactModel& m, ImpactState& s, int top) {
  const SubcyclingLevels& lv = m.levels;
  const NodalArrays x = nodal_arrays(m, s);
  ElementSums sums;
  for (int l = 0; l <= top; ++l) {
    const int sb = l == 0 ? 0 : lv.sphere_end[l - 1];
    const int ub = l == 0 ? m.n_sphere_elements : lv.substrate_end[l - 1];
    const double h = std::ldexp(s.dt, l);
    const double scale = std::ldexp(1.0, l);
    // The next base step is set at the major cycle's end only, from that pass's stable steps.
    const bool stable_step = top == lv.max_level;
    if (l > 0) s.transit.before_slow_pass(lv, l - 1, s.fr.data(), s.fz.data());
    ElementSums ls;
    element_loop_subcycled(m.simd, {m.sphere, m.elements, s.elements, sb, lv.sphere_end[l], x, h},
                           scale, stable_step, ls);
    element_loop_subcycled(m.simd,
                           {m.substrate, m.elements, s.elements, ub, lv.substrate_end[l], x, h},
                           scale, stable_step, ls);
    if (l > 0) {
      s.transit.after_slow_pass(lv, l - 1, 0.5 * h, s.fr.data(), s.fz.data(), s.vr.data(),
                                s.vz.data());
    }
    if (stable_step) s.level_dt_min[l] = std::ldexp(ls.dt_min, -l);
    s.element_updates += lv.sphere_end[l] - sb + lv.substrate_end[l] - ub;
    add_sums(ls, sums);
  }
  return sums;
}

/// The sphere's c.o.m. velocity and height from the nodal update's sums.
void set_sphere_motion(const ImpactModel& m, const NodeSums& ns, ImpactState& s) {
  s.sphere_velocity = ns.p_sphere / m.sphere_mass;
  s.sphere_com_z = ns.mz_sphere / m.sphere_mass;
}

/// A free target's z-momentum [kg m/s] and first moment sum m z [kg m] at the state's present
/// velocities and positions: a pass over its nodes, only when the target is a free sphere (the
/// flat's runs keep the nodal update as it was).
double target_momentum(const ImpactModel& m, const ImpactState& s) {
  double p = 0.0;
  for (int i = 0; i < m.n_nodes; ++i) p += m.mass[i] * s.vz[i] * (1.0 - m.is_sphere[i]);
  return p;
}

double target_first_moment(const ImpactModel& m, const ImpactState& s) {
  double mz = 0.0;
  for (int i = 0; i < m.n_nodes; ++i) mz += m.mass[i] * s.z[i] * (1.0 - m.is_sphere[i]);
  return mz;
}

void set_target_motion(const ImpactModel& m, ImpactState& s) {
  s.target_velocity = target_momentum(m, s) / m.target_mass;
  s.target_com_z = target_first_moment(m, s) / m.target_mass;
}

/// The absorbing far boundary's forces at the latest velocities into fr/fz, its work over the
/// step into the state; subcycled (`top` >= 0), only the nodes due at the next kick (level <=
/// top), each with its own step's impulse (weight 2^L).
void apply_far_boundary(const ImpactModel& m, ImpactState& s, int top) {
  if (m.dashpots.empty()) return;
  const auto weight = [&](int n) {
    if (top < 0) return 1.0;
    const int level = m.levels.node[static_cast<std::size_t>(n)];
    return level <= top ? m.levels.node_scale[static_cast<std::size_t>(n)] : 0.0;
  };
  const auto v = [&s](int n, std::size_t a) -> double {
    return a == 0 ? s.vr[static_cast<std::size_t>(n)] : s.vz[static_cast<std::size_t>(n)];
  };
  const auto f = [&s](int n, std::size_t a) -> double& {
    return a == 0 ? s.fr[static_cast<std::size_t>(n)] : s.fz[static_cast<std::size_t>(n)];
  };
  const auto u = [&m, &s](int n, std::size_t a) -> double {
    const auto i = static_cast<std::size_t>(n);
    return a == 0 ? s.r[i] - m.r0[i] : s.z[i] - m.z0[i];
  };
  const BoundaryWork w = apply_dashpots(m.dashpots, s.dt, weight, v, u, f);
  s.energy.absorbed += w.absorbed;
  s.energy.boundary = w.stored;
}

}  // namespace

NodalArrays nodal_arrays(const ImpactModel& m, ImpactState& s) {
  const bool scaled = s.scaling.on();
  return NodalArrays{s.r.data(),
                     s.z.data(),
                     s.vr.data(),
                     s.vz.data(),
                     s.fr.data(),
                     s.fz.data(),
                     scaled ? s.scaling.mass.data() : m.mass.data(),
                     scaled ? s.scaling.inv_mass.data() : m.inv_mass.data(),
                     m.free_r.data(),
                     m.free_z.data(),
                     m.is_sphere.data()};
}

double rebound_kinetic_energy(const ImpactModel& m, const ImpactState& s, const NodeSums& ns) {
  if (!m.free_target) return ns.ke_sphere;
  const double p = ns.p_sphere + s.target_velocity * m.target_mass;
  return ns.ke - 0.5 * p * p / (m.sphere_mass + m.target_mass);
}

double sphere_kinetic_energy(const ImpactModel& m, const ImpactState& s) {
  double ke = 0.0;
  for (int i = 0; i < m.n_nodes; ++i)
    ke += 0.5 * m.mass[i] * (s.vr[i] * s.vr[i] + s.vz[i] * s.vz[i]) * m.is_sphere[i];
  return ke;
}

double relaunch_bodies(const ImpactModel& m, ImpactState& s) {
  const double dv_sphere = -m.velocity - s.sphere_velocity;
  const double dv_target = -s.target_velocity;
  // The subcycled loop relaunches at a major-cycle boundary after the drift, which moved each node
  // a step of its own level (2^L dt) ahead: that drift is redone with the new velocity, or the
  // levels' positions would disagree by dt dv (a spurious strain). The plain loop relaunches after
  // the force half, every node at t^{n+1}: nothing to redo.
  const bool redo_drift = m.levels.max_level > 0;
  double added = 0.0;
  for (int i = 0; i < m.n_nodes; ++i) {
    const double dv =
        (m.is_sphere[i] != 0.0 ? dv_sphere : (m.free_target ? dv_target : 0.0)) * m.free_z[i];
    const double v = s.vz[i] + dv;
    added += 0.5 * m.mass[i] * (v * v - s.vz[i] * s.vz[i]);
    s.vz[i] = v;
    if (redo_drift) s.z[i] += s.dt * m.levels.node_scale[i] * dv;
  }
  s.sphere_velocity = -m.velocity;
  s.target_velocity = 0.0;
  // The subcycling's open windows hold their first drift's velocities: the shifted ones now.
  for (int k = 0; k < m.levels.max_level; ++k)
    s.transit.open_windows(m.levels, k, s.vr.data(), s.vz.data());
  return added;
}

void sample_hysteresis(const ImpactModel& m, ImpactState& s) {
  s.hysteresis.sample(s.force, indentation(m, s));
}

int sync_level(long long step, int max_level) {
  int l = 0;
  while (l < max_level && (step & (1LL << l)) == 0) ++l;
  return l;
}

NodeSums move_nodes_subcycled(const ImpactModel& m, ImpactState& s) {
  const SubcyclingLevels& lv = m.levels;
  const int l = sync_level(s.step, lv.max_level);
  std::array<double, kMaxSubcyclingLevels + 1> step{};
  for (int k = 0; k <= lv.max_level; ++k) step[k] = std::ldexp(s.dt, k);
  const SubcycledNodes a{nodal_arrays(m, s), lv.node_order.data(), lv.node_end[l],
                         step.data(),        lv.node_scale.data(), 0.5 * (s.dt_prev + s.dt)};
  // A free target's c.o.m. at t^k, before the drift (as the sphere's sum: move_nodes_subcycled).
  if (m.free_target && l == lv.max_level)
    s.target_com_z = target_first_moment(m, s) / m.target_mass;
  // Most nodes due (fast runs, major-cycle boundaries): one contiguous pass over all.
  const NodeSums ns = 2 * lv.node_end[l] >= m.n_nodes ? node_update_due(m.simd, a, m.n_nodes, l)
                                                      : node_update_subcycled(m.simd, a);
  // The kick just given opens the windows of the levels below l.
  for (int k = 0; k < l; ++k) s.transit.open_windows(lv, k, s.vr.data(), s.vz.data());
  if (l == lv.max_level) {
    set_sphere_motion(m, ns, s);
    if (m.free_target) s.target_velocity = target_momentum(m, s) / m.target_mass;
    sample_hysteresis(m, s);
  }
  return ns;
}

ForceReport compute_forces_subcycled(const ImpactModel& m, ImpactState& s) {
  ForceReport rep;
  const int top = sync_level(s.step + 1, m.levels.max_level);
  rep.elements = subcycled_elements(m, s, top);
  record_element_sums(m, s, rep);
  apply_far_boundary(m, s, top);
  rep.penetrating = apply_contact(m, s);
  if (rep.penetrating && !s.cycle_penetrating) s.t_first_penetrating = s.t;
  s.cycle_penetrating = s.cycle_penetrating || rep.penetrating;
  advance_time(s);
  if (top == m.levels.max_level) {
    double dt_min = s.level_dt_min[0];
    for (int l = 1; l <= top; ++l) dt_min = std::min(dt_min, s.level_dt_min[l]);
    s.dt = m.safety_factor * dt_min;
  }
  return rep;
}

NodeSums move_nodes(const ImpactModel& m, ImpactState& s) {
  const double dt_avg = 0.5 * (s.dt_prev + s.dt);
  const NodeSums ns = node_update(m.simd, nodal_arrays(m, s), m.n_nodes, s.dt, dt_avg);
  set_sphere_motion(m, ns, s);
  if (m.free_target) set_target_motion(m, s);
  return ns;
}

ForceReport compute_forces(const ImpactModel& m, ImpactState& s) {
  ForceReport rep;
  ElementSums& sums = rep.elements;
  const NodalArrays x = nodal_arrays(m, s);
  element_loop(m.simd, {m.sphere, m.elements, s.elements, 0, m.n_sphere_elements, x, s.dt}, sums);
  if (s.scaling.on()) {
    substrate_scaled(m, s, x, sums);
  } else {
    element_loop(m.simd,
                 {m.substrate, m.elements, s.elements, m.n_sphere_elements, m.n_elements, x, s.dt},
                 sums);
  }
  s.element_updates += m.n_elements;
  record_element_sums(m, s, rep);
  apply_far_boundary(m, s, -1);
  rep.penetrating = apply_contact(m, s);
  sample_hysteresis(m, s);
  advance_time(s);
  s.dt = m.safety_factor * sums.dt_min;
  return rep;
}

}  // namespace corlab::fem::solver
