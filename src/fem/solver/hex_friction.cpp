// The 3-D solver's kinematic Coulomb friction (hex_model.hpp, coulomb_friction.hpp): the
// predictor-corrector stick of Taylor & Flanagan (1989, PRONTO-3D) at the normal penalty's
// contact points, solved for all of them together by projected Gauss-Seidel.
// SPDX-License-Identifier: BSD-3-Clause
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "corlab/fem/kernels/coulomb_friction.hpp"
#include "fem/solver/hex_model.hpp"

namespace corlab::fem::hex_solver {
namespace {

// A node's velocity (its held components 0) [m/s], or its predicted velocity at the end of the
// step dt [s] under its force now.
void node_velocity(const HexModel& m, const HexState& s, std::size_t n, double dt, double* v) {
  const NodeKinematics& k = s.node[n];
  const NodeForce& f = s.nodal_force[n];
  const double a = dt * m.inv_mass[n];
  v[0] = m.free_x[n] * (k.vx + a * f.x);
  v[1] = m.free_y[n] * (k.vy + a * f.y);
  v[2] = m.free_z[n] * (k.vz + a * f.z);
}

// Calls f(node, weight, mirror) for each master node of the contact point (none on the rigid
// flat): its weight [-] and -1 where it stands as its mirror image across y = 0 [-].
template <class F>
void for_each_master(const SlaveContact& at, F&& f) {
  for (std::size_t j = 0; j < at.masters.size() && at.masters[j].node >= 0; ++j)
    f(static_cast<std::size_t>(at.masters[j].node), at.weight[j], at.masters[j].mirror);
}

// The contact point's velocity (its face's nodes' with the weights w_a) relative to its master
// point (the rigid flat: at rest) [m/s], now (dt = 0) or predicted at the end of the step dt [s].
void relative_velocity(const HexModel& m,
                       const HexState& s,
                       const SlavePoint& q,
                       const SlaveContact& at,
                       double dt,
                       double* v) {
  v[0] = v[1] = v[2] = 0.0;
  for (std::size_t a = 0; a < 4; ++a) {
    double vs[3];
    node_velocity(m, s, static_cast<std::size_t>(q.node[a]), dt, vs);
    for (int d = 0; d < 3; ++d) v[d] += q.w[a] * vs[d];
  }
  for_each_master(at, [&](std::size_t node, double w, double mirror) {
    double vm[3];
    node_velocity(m, s, node, dt, vm);
    v[0] -= w * vm[0];
    v[1] -= w * mirror * vm[1];
    v[2] -= w * vm[2];
  });
}

// The pair's effective mass for a tangential impulse at this contact point alone,
// 1 / (sum_a w_a^2 / m_a + sum_j C_j^2 / m_j) over its face's nodes a and its masters j [kg].
double effective_mass(const HexModel& m, const SlavePoint& q, const SlaveContact& at) {
  double inverse = 0.0;
  for (std::size_t a = 0; a < 4; ++a)
    inverse += q.w[a] * q.w[a] * m.inv_mass[static_cast<std::size_t>(q.node[a])];
  for_each_master(at,
                  [&](std::size_t node, double w, double) { inverse += w * w * m.inv_mass[node]; });
  return 1.0 / inverse;
}

// Books the work of the previous step's friction forces, which acted over 1/2 (dt_prev + dt),
// from v^{n+1/2} (stored) and v^{n+3/2} (now), and clears them.
void book_previous_work(const HexModel& m, HexState& s) {
  const double acted = 0.5 * (s.dt_prev + s.dt);
  for (std::size_t k = 0; k < m.slave_points.size(); ++k) {
    auto& t = s.traction[k];
    if (t[0] == 0.0 && t[1] == 0.0 && t[2] == 0.0) continue;
    const SlaveFriction& link = s.friction_link[k];
    double v_after[3];
    relative_velocity(m, s, m.slave_points[k], link.at, 0.0, v_after);
    s.energy.friction -= friction_work(t.data(), link.v_before.data(), v_after, acted);
    t = {0.0, 0.0, 0.0};
  }
}

// The sweeps of projected Gauss-Seidel at most, and the change of a sweep that ends them: the
// largest velocity change it made, over the model's approach speed [-].
constexpr int kMaxSweeps = 200;
constexpr double kSettled = 1e-9;

}  // namespace

void kinematic_friction_forces(const HexModel& m, HexState& s, double dt) {
  book_previous_work(m, s);
  if (s.touching.empty()) return;
  s.friction_dv.resize(s.node.size(), {0.0, 0.0, 0.0});
  for (FrictionContact& c : s.touching) {
    const SlavePoint& q = m.slave_points[c.point];
    relative_velocity(m, s, q, c.at, dt, c.v_pred);
    c.mass = effective_mass(m, q, c.at);
  }
  // Each sweep: every point's force from its relative velocity with the others' forces so far
  // (the velocity changes dv they make), until no sweep changes a velocity.
  auto& dv = s.friction_dv;
  const double settled = kSettled * m.velocity;
  int sweep = 0;
  for (double change = settled + 1.0; change > settled && sweep < kMaxSweeps; ++sweep) {
    change = 0.0;
    for (FrictionContact& c : s.touching) {
      const SlavePoint& q = m.slave_points[c.point];
      double v[3] = {c.v_pred[0], c.v_pred[1], c.v_pred[2]};
      for (std::size_t a = 0; a < 4; ++a) {
        const auto n = static_cast<std::size_t>(q.node[a]);
        for (std::size_t d = 0; d < 3; ++d) v[d] += q.w[a] * dv[n][d];
      }
      for_each_master(c.at, [&](std::size_t node, double w, double mirror) {
        v[0] -= w * dv[node][0];
        v[1] -= w * mirror * dv[node][1];
        v[2] -= w * dv[node][2];
      });
      const FrictionUpdate u =
          kinematic_friction(c.t, c.normal, v, c.mass, dt, c.normal_force, m.friction);
      double dt_force[3];
      for (int d = 0; d < 3; ++d) {
        dt_force[d] = dt * (u.t[d] - c.t[d]);
        c.t[d] = u.t[d];
      }
      const auto add = [&](std::size_t node, double w, double mirror) {
        const double a = w * m.inv_mass[node];
        dv[node][0] += m.free_x[node] * a * dt_force[0];
        dv[node][1] += m.free_y[node] * a * mirror * dt_force[1];
        dv[node][2] += m.free_z[node] * a * dt_force[2];
      };
      for (std::size_t a = 0; a < 4; ++a) add(static_cast<std::size_t>(q.node[a]), q.w[a], 1.0);
      for_each_master(c.at,
                      [&](std::size_t node, double w, double mirror) { add(node, -w, mirror); });
      change = std::max(change, std::sqrt(dt_force[0] * dt_force[0] + dt_force[1] * dt_force[1] +
                                          dt_force[2] * dt_force[2]) /
                                    c.mass);
    }
  }
  for (FrictionContact& c : s.touching) {
    const SlavePoint& q = m.slave_points[c.point];
    s.traction[c.point] = {c.t[0], c.t[1], c.t[2]};
    SlaveFriction& link = s.friction_link[c.point];
    link.at = c.at;
    relative_velocity(m, s, q, c.at, 0.0, link.v_before.data());
    for (std::size_t a = 0; a < 4; ++a) {
      const auto n = static_cast<std::size_t>(q.node[a]);
      dv[n] = {0.0, 0.0, 0.0};
      NodeForce& f = s.nodal_force[n];
      f.x += q.w[a] * c.t[0];
      f.y += q.w[a] * c.t[1];
      f.z += q.w[a] * c.t[2];
    }
    for_each_master(c.at, [&](std::size_t node, double, double) { dv[node] = {0.0, 0.0, 0.0}; });
    push_masters(c.at, c.t, s);
  }
}

}  // namespace corlab::fem::hex_solver
