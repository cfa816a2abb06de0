// The 3-D solver's contact: node on the rigid plane or on the flat's smooth surface
// (hex_master_surface.cpp), with the normal penalty law of penalty_contact.hpp and Coulomb
// friction (hex_model.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include <algorithm>
#include <cmath>
#include <vector>

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

}  // namespace

bool contact_forces(const HexModel& m, HexState& s, double dt) {
  bool penetrating = false;
  double stored = 0.0;
  double normal_force = 0.0;
  const bool block = m.contact == solver::ContactKind::kBlockSurface;
  // Slaves below this height look for the block's surface; higher ones cannot touch it [m].
  const double search_below = top_height(m, s) + 0.5 * m.h_contact;
  const auto& slaves = m.mesh.sphere_surface_nodes;
  s.touching.clear();
  for (std::size_t k = 0; k < slaves.size(); ++k) {
    const auto n = static_cast<std::size_t>(slaves[k]);
    SlaveContact c;
    c.gap = project_on_rigid_flat(s.node[n].z).gap;  // no block below: the plane of the top
    if (block && s.node[n].z < search_below) c = surface_contact(m, s, n);
    const double stiffness = m.penalty[k];
    const NormalPenalty normal = normal_penalty(c.gap, stiffness);
    const double fn = normal.force;
    const std::array<double, 3> v_master = master_velocity(c, s);
    const double v_rel[3] = {s.node[n].vx - v_master[0], s.node[n].vy - v_master[1],
                             s.node[n].vz - v_master[2]};
    const double du[3] = {v_rel[0] * dt, v_rel[1] * dt, v_rel[2] * dt};
    FrictionUpdate f;  // the penalty's (the kinematic friction comes after this loop)
    if (!m.kinematic_friction) {
      f = coulomb_friction(s.traction[k].data(), c.normal, du, fn, stiffness, m.friction);
      s.traction[k] = {f.t[0], f.t[1], f.t[2]};
      s.energy.friction += f.dissipation;
    }
    if (!(fn > 0.0)) continue;
    if (m.kinematic_friction && m.friction > 0.0)
      s.touching.push_back({.slave = k,
                            .normal = {c.normal[0], c.normal[1], c.normal[2]},
                            .at = c,
                            .normal_force = fn});
    penetrating = true;
    s.penetration_max = std::max(s.penetration_max, -c.gap);
    const double force[3] = {fn * c.normal[0] + f.t[0], fn * c.normal[1] + f.t[1],
                             fn * c.normal[2] + f.t[2]};
    s.nodal_force[n].x += force[0];
    s.nodal_force[n].y += force[1];
    s.nodal_force[n].z += force[2];
    push_masters(c, force, s);
    normal_force += fn * c.normal[2];
    stored += normal.energy + friction_stored_energy(f.t, stiffness);
  }
  if (m.kinematic_friction && m.friction > 0.0) kinematic_friction_forces(m, s, s.dt);
  s.energy.contact = stored;
  s.force = normal_force;
  return penetrating;
}

}  // namespace corlab::fem::hex_solver
