// The 3-D model's steps (hex_model.hpp): the kinematic and the force half of a central-difference
// step, for the time loop all geometries share (time_loop.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include <algorithm>
#include <cstddef>

#include "fem/solver/hex_element_loop.hpp"
#include "fem/solver/hex_model.hpp"

namespace corlab::fem::hex_solver {
namespace {

// The absorbing far boundary's forces at v^{n+1/2} into the nodal forces, its work over the step
// into the state (dashpots.hpp).
void apply_far_boundary(const HexModel& m, HexState& s) {
  const auto v = [&s](int n, std::size_t a) {
    const NodeKinematics& k = s.node[static_cast<std::size_t>(n)];
    return a == 0 ? k.vx : (a == 1 ? k.vy : k.vz);
  };
  const auto f = [&s](int n, std::size_t a) -> double& {
    NodeForce& g = s.nodal_force[static_cast<std::size_t>(n)];
    return a == 0 ? g.x : (a == 1 ? g.y : g.z);
  };
  const auto u = [&m, &s](int n, std::size_t a) {
    const auto i = static_cast<std::size_t>(n);
    const NodeKinematics& k = s.node[i];
    return a == 0 ? k.x - m.mesh.x[i] : (a == 1 ? k.y - m.mesh.y[i] : k.z - m.mesh.z[i]);
  };
  const solver::BoundaryWork w = solver::apply_dashpots(
      m.dashpots, s.dt, [](int) { return 1.0; }, v, u, f);
  s.energy.absorbed += w.absorbed;
  s.energy.boundary = w.stored;
}

}  // namespace

solver::NodeSums move_nodes(const HexModel& m, HexState& s) {
  const double dt = s.dt;
  const double dt_avg = 0.5 * (s.dt_prev + s.dt);
  solver::NodeSums sums;
  for (std::size_t n = 0; n < s.node.size(); ++n) {
    NodeKinematics& k = s.node[n];
    NodeForce& f = s.nodal_force[n];
    const double vx = m.free_x[n] * (k.vx + dt_avg * f.x * m.inv_mass[n]);
    const double vy = m.free_y[n] * (k.vy + dt_avg * f.y * m.inv_mass[n]);
    const double vz = m.free_z[n] * (k.vz + dt_avg * f.z * m.inv_mass[n]);
    // The kinetic energy at t^n in product form: m v^{n-1/2} . v^{n+1/2} / 2.
    const double ke = 0.5 * m.mass[n] * (k.vx * vx + k.vy * vy + k.vz * vz);
    k.vx = vx;
    k.vy = vy;
    k.vz = vz;
    k.x += dt * vx;
    k.y += dt * vy;
    k.z += dt * vz;
    f = NodeForce{0.0, 0.0, 0.0};
    sums.ke += ke;
    if (n < m.sphere_nodes) {
      sums.ke_sphere += ke;
      sums.p_sphere += m.mass[n] * vz;
      sums.mz_sphere += m.mass[n] * k.z;
    }
  }
  s.sphere_velocity = sums.p_sphere / m.sphere_mass;
  s.sphere_com_z = sums.mz_sphere / m.sphere_mass;
  return sums;
}

solver::ForceReport compute_forces(const HexModel& m, HexState& s) {
  solver::ForceReport rep;
  rep.elements = hex_element_pass(m.simd, m, s, s.dt);
  rep.inverted_element = rep.elements.bad_element;
  solver::add_element_work(rep.elements, s);
  if (!m.dashpots.empty()) apply_far_boundary(m, s);
  s.element_updates += static_cast<long long>(m.mesh.hexes.size());
  rep.penetrating = contact_forces(m, s, s.dt);
  s.force_max = std::max(s.force_max, s.force);
  s.hysteresis.sample(s.force, m.z_com_start - s.sphere_com_z);
  solver::advance_time(s);
  s.dt = m.safety_factor * rep.elements.dt_min;
  return rep;
}

double sphere_kinetic_energy(const HexModel& m, const HexState& s) {
  double ke = 0.0;
  for (std::size_t n = 0; n < m.sphere_nodes; ++n) {
    const NodeKinematics& k = s.node[n];
    ke += 0.5 * m.mass[n] * (k.vx * k.vx + k.vy * k.vy + k.vz * k.vz);
  }
  return ke;
}

}  // namespace corlab::fem::hex_solver
