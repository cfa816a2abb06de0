// The 3-D solver's contact: the sphere's contact points (n x n on each slave face) on the rigid
// plane or on the flat's smooth surface (hex_master_surface.cpp), with the normal penalty law of
// penalty_contact.hpp, and Coulomb friction: kinematic at the same points (hex_friction.cpp), or
// the tangential penalty at the slave nodes (hex_model.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "corlab/core/error.hpp"
#include "corlab/fem/kernels/coulomb_friction.hpp"
#include "corlab/fem/kernels/penalty_contact.hpp"
#include "fem/solver/hex_model.hpp"

namespace corlab::fem::hex_solver {

std::size_t face_under(const HexMesh& mesh, double x, double y, long di, long dj) {
  auto cell = [](const std::vector<double>& lines, double v, long shift) {
    const auto it = std::upper_bound(lines.begin(), lines.end(), v);
    const long i = static_cast<long>(it - lines.begin()) - 1 + shift;
    return static_cast<std::size_t>(std::clamp(i, 0L, static_cast<long>(lines.size()) - 2));
  };
  return cell(mesh.top_y, y, dj) * (mesh.top_x.size() - 1) + cell(mesh.top_x, x, di);
}

std::vector<int> block_top_nodes(const HexMesh& mesh) {
  std::vector<int> nodes;
  for (const auto& face : mesh.top_faces) nodes.insert(nodes.end(), face.begin(), face.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

namespace {

// The highest point of the block's top now [m] (0 on the rigid flat): a yielding flat piles up
// around the contact, about 0.5 mm for the paper's pair at 30 m/s.
double top_height(const HexModel& m, const HexState& s) {
  double z = 0.0;
  for (const int n : m.top_nodes) z = std::max(z, s.node[static_cast<std::size_t>(n)].z);
  return z;
}

// The point q of the sphere's surface now [m].
std::array<double, 3> point_position(const SlavePoint& q, const HexState& s) {
  std::array<double, 3> p{0.0, 0.0, 0.0};
  for (std::size_t a = 0; a < 4; ++a) {
    const NodeKinematics& k = s.node[static_cast<std::size_t>(q.node[a])];
    p[0] += q.w[a] * k.x;
    p[1] += q.w[a] * k.y;
    p[2] += q.w[a] * k.z;
  }
  return p;
}

// The normal penalty at the contact points: each point's force f n goes to its face's nodes
// with the weights w_a and to its masters, so that it is -d(1/2 k g^2)/d(positions) (g the
// point's gap, linear in its nodes); with the tangential penalty each slave node's share
// sum w_a f into s.slave_normal_force (its f_n), and each touching point into
// s.touching (the kinematic friction's contacts, where m.friction > 0). Sets the contact force
// s.force (+ up), the deepest penetration; returns the stored energy [J] and, in
// `penetrating`, whether any point penetrates.
double normal_contact_forces(const HexModel& m, HexState& s, bool& penetrating) {
  double stored = 0.0;
  double normal_force = 0.0;
  const bool block = m.contact == solver::ContactKind::kBlockSurface;
  // Points below this height look for the block's surface; higher ones cannot touch it [m].
  const double search_below = top_height(m, s) + 0.5 * m.h_contact;
  // The nodes' shares only for the tangential penalty; the kinematic friction acts at the points.
  const bool node_shares = !m.kinematic_friction;
  if (node_shares) s.slave_normal_force.assign(m.mesh.sphere_surface_nodes.size(), 0.0);
  s.touching.clear();
  const bool kinematic = m.kinematic_friction && m.friction > 0.0;
  for (std::size_t i = 0; i < m.slave_points.size(); ++i) {
    const SlavePoint& q = m.slave_points[i];
    const std::array<double, 3> p = point_position(q, s);
    SlaveContact c;
    c.gap = project_on_rigid_flat(p[2]).gap;  // no block below: the plane of the top
    if (block && p[2] < search_below) c = surface_contact_at(m, s, p.data());
    const NormalPenalty normal = normal_penalty(c.gap, q.penalty);
    const double fn = normal.force;
    if (!(fn > 0.0)) continue;
    penetrating = true;
    s.penetration_max = std::max(s.penetration_max, -c.gap);
    const double force[3] = {fn * c.normal[0], fn * c.normal[1], fn * c.normal[2]};
    for (std::size_t a = 0; a < 4; ++a) {
      NodeForce& f = s.nodal_force[static_cast<std::size_t>(q.node[a])];
      f.x += q.w[a] * force[0];
      f.y += q.w[a] * force[1];
      f.z += q.w[a] * force[2];
      if (node_shares) s.slave_normal_force[static_cast<std::size_t>(q.slave[a])] += q.w[a] * fn;
    }
    push_masters(c, force, s);
    if (kinematic)
      s.touching.push_back({.point = i,
                            .normal = {c.normal[0], c.normal[1], c.normal[2]},
                            .at = c,
                            .normal_force = fn});
    normal_force += fn * c.normal[2];
    stored += normal.energy;
  }
  s.force = normal_force;
  return stored;
}

}  // namespace

std::vector<SlavePoint> make_slave_points(const HexModel& m, int n) {
  const auto& slaves = m.mesh.sphere_surface_nodes;
  std::vector<int> slave_of(m.mass.size(), -1);
  for (std::size_t k = 0; k < slaves.size(); ++k)
    slave_of[static_cast<std::size_t>(slaves[k])] = static_cast<int>(k);
  // The faces of the sphere's elements with four slave corners, counted: a face of two elements
  // is inside the sphere (each corner loop counter-clockwise seen from outside or inside alike).
  constexpr std::array<std::array<std::size_t, 4>, 6> kFaces{
      {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};
  std::map<std::array<int, 4>, std::pair<std::array<int, 4>, int>> faces;
  for (std::size_t e = 0; e < m.sphere_elements; ++e) {
    for (const auto& corners : kFaces) {
      std::array<int, 4> face{};
      bool slave = true;
      for (std::size_t a = 0; a < 4; ++a) {
        face[a] = m.mesh.hexes[e][corners[a]];
        slave = slave && slave_of[static_cast<std::size_t>(face[a])] >= 0;
      }
      if (!slave) continue;
      std::array<int, 4> key = face;
      std::sort(key.begin(), key.end());
      auto& entry = faces[key];
      entry.first = face;
      ++entry.second;
    }
  }
  std::vector<SlavePoint> points;
  for (const auto& [key, entry] : faces) {
    if (entry.second != 1) continue;
    SlavePoint q;
    q.node = entry.first;
    for (std::size_t a = 0; a < 4; ++a) q.slave[a] = slave_of[static_cast<std::size_t>(q.node[a])];
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double xi = (i + 0.5) / n;
        const double eta = (j + 0.5) / n;
        q.w[0] = (1.0 - xi) * (1.0 - eta);
        q.w[1] = xi * (1.0 - eta);
        q.w[2] = xi * eta;
        q.w[3] = (1.0 - xi) * eta;
        points.push_back(q);
      }
  }
  if (points.empty())
    throw_invalid("mesh.sphere_surface_nodes", 0.0, "the corners of at least one surface face");
  // k_q = sum_a w_a k_a / s_a with s_a = sum_q w_a(q): the total sum_q k_q = sum_a k_a, and
  // where k_a / s_a is one value about a node (the penalties go with the nodes' masses, and
  // those with the nodes' share of the faces) the node gets sum_q w_a k_q = k_a back; the
  // stiffness a node sees stays about its own, so the nodes' stability margin holds.
  std::vector<double> share(slaves.size(), 0.0);
  for (const SlavePoint& q : points)
    for (std::size_t a = 0; a < 4; ++a) share[static_cast<std::size_t>(q.slave[a])] += q.w[a];
  for (SlavePoint& q : points)
    for (std::size_t a = 0; a < 4; ++a) {
      const auto k = static_cast<std::size_t>(q.slave[a]);
      q.penalty += q.w[a] * m.penalty[k] / share[k];
    }
  return points;
}

bool contact_forces(const HexModel& m, HexState& s, double dt) {
  bool penetrating = false;
  double stored = normal_contact_forces(m, s, penetrating);
  if (m.kinematic_friction) {
    if (m.friction > 0.0) kinematic_friction_forces(m, s, s.dt);
    s.energy.contact = stored;
    return penetrating;
  }
  // The tangential penalty: at each slave node, with its share of the points' normal force.
  const bool block = m.contact == solver::ContactKind::kBlockSurface;
  const auto& slaves = m.mesh.sphere_surface_nodes;
  for (std::size_t k = 0; k < slaves.size(); ++k) {
    const auto n = static_cast<std::size_t>(slaves[k]);
    const double fn = s.slave_normal_force[k];
    const double stiffness = m.penalty[k];
    // The slave's friction acts at its own point of the master, along its tangent plane.
    SlaveContact c;
    if (block && fn > 0.0) c = surface_contact(m, s, n);
    const std::array<double, 3> v_master = master_velocity(c, s);
    const double du[3] = {(s.node[n].vx - v_master[0]) * dt, (s.node[n].vy - v_master[1]) * dt,
                          (s.node[n].vz - v_master[2]) * dt};
    const FrictionUpdate f =
        coulomb_friction(s.traction[k].data(), c.normal, du, fn, stiffness, m.friction);
    s.traction[k] = {f.t[0], f.t[1], f.t[2]};
    s.energy.friction += f.dissipation;
    if (!(fn > 0.0)) continue;
    s.nodal_force[n].x += f.t[0];
    s.nodal_force[n].y += f.t[1];
    s.nodal_force[n].z += f.t[2];
    push_masters(c, f.t, s);
    stored += friction_stored_energy(f.t, stiffness);
  }
  s.energy.contact = stored;
  return penetrating;
}

}  // namespace corlab::fem::hex_solver
