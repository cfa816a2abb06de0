// The 3-D model's contact with the deformable flat (hex_contact.cpp, hex_master_surface.cpp): a
// contact point finds the surface under it after the flat's top has moved sideways by more than
// one face or risen above z = 0, as a yielding flat's does at 30 m/s (about 1 mm sideways and
// 0.5 mm up for the paper's pair); the reaction goes to the nodes around it, mirrored across
// y = 0. The sphere's contact points share its nodes' penalties exactly, and carry the kinematic
// friction with their own normal force.
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "corlab/fem/mesh/hex_mesh_generator.hpp"
#include "fem/solver/hex_model.hpp"

namespace corlab::fem::hex_solver {
namespace {

constexpr double kH = 1e-3;  // the top's face size in the fine zone [m]

// A half block with 1 mm faces around the origin, and one slave node of the sphere, its contact
// point on it.
HexModel block_and_slave() {
  HexMeshOptions o;
  o.block = true;
  o.block_half_width = 10e-3;
  o.block_depth = 5e-3;
  o.h_contact = kH;
  o.zone_radius = 6e-3;
  o.zone_depth = 2e-3;
  o.h_max = 2e-3;
  HexModel m;
  append_hex_block(o, m.mesh);
  m.mesh.x.push_back(0.3e-3);
  m.mesh.y.push_back(0.4e-3);
  m.mesh.z.push_back(0.0);
  m.mesh.node_body.push_back(Body::kSphere);
  m.mesh.sphere_surface_nodes = {m.mesh.num_nodes() - 1};
  m.top_nodes = block_top_nodes(m.mesh);
  m.surface = make_master_surface(m.mesh);
  m.contact = solver::ContactKind::kBlockSurface;
  m.h_contact = kH;
  m.penalty = {1e9};
  const int n = m.mesh.num_nodes() - 1;
  m.slave_points = {SlavePoint{
      .node = {n, n, n, n}, .slave = {0, 0, 0, 0}, .w = {1.0, 0.0, 0.0, 0.0}, .penalty = 1e9}};
  return m;
}

// The flat shifted by `shift` [m] along x and `lift` [m] up, the slave `depth` [m] below its top.
HexState shifted(const HexModel& m, double shift, double depth, double lift = 0.0) {
  HexState s;
  const auto nn = static_cast<std::size_t>(m.mesh.num_nodes());
  for (std::size_t n = 0; n < nn; ++n)
    s.node.push_back({m.mesh.x[n], m.mesh.y[n], m.mesh.z[n], 0.0, 0.0, 0.0});
  for (std::size_t n = 0; n + 1 < nn; ++n) {
    s.node[n].x += shift;
    s.node[n].z += lift;
  }
  s.node.back().z = lift - depth;
  s.nodal_force.assign(nn, NodeForce{0.0, 0.0, 0.0});
  s.traction.assign(1, {0.0, 0.0, 0.0});
  return s;
}

TEST(HexContact, FindsTheSurfaceAfterTheTopMovedSideways) {
  const HexModel m = block_and_slave();
  for (const double shift : {0.0, 0.5 * kH, 2.5 * kH, 3.5 * kH}) {
    SCOPED_TRACE(shift);
    HexState s = shifted(m, shift, 1e-6);
    ASSERT_TRUE(contact_forces(m, s, 1e-8));
    const NodeForce& slave = s.nodal_force.back();
    EXPECT_NEAR(slave.z, 1e9 * 1e-6, 1e-6);  // a flat top: the full penalty, straight up
    EXPECT_NEAR(slave.x, 0.0, 1e-9);
    // The reaction lands on the nodes of the patch around the slave (its 4 x 4 control points,
    // the rows across y = 0 mirrored onto rows 1 and 2), wherever the grid now lies.
    double reaction = 0.0;
    for (std::size_t n = 0; n + 1 < s.nodal_force.size(); ++n) {
      if (s.nodal_force[n].z == 0.0) continue;
      reaction += s.nodal_force[n].z;
      EXPECT_LE(std::abs(s.node[n].x - s.node.back().x), 2.0 * kH);
      EXPECT_LE(std::abs(s.node[n].y - s.node.back().y), 2.0 * kH);
    }
    EXPECT_NEAR(reaction, -slave.z, 1e-9);
  }
}

// A flat that piles up around the contact lifts its top above z = 0 (about 0.5 mm at 30 m/s): a
// slave sinking into it higher than half a face above z = 0 still touches it.
TEST(HexContact, TouchesAFlatThatRoseAboveItsStart) {
  const HexModel m = block_and_slave();
  HexState s = shifted(m, 0.0, 1e-6, 0.8 * kH);
  ASSERT_TRUE(contact_forces(m, s, 1e-8));
  EXPECT_NEAR(s.nodal_force.back().z, 1e9 * 1e-6, 1e-6);
}

// A slave on the symmetry plane sits on the middle of its patch's mirrored rows: no force across
// the plane, and the reaction balances the slave's.
TEST(HexContact, SlaveOnTheSymmetryPlanePushesStraightDown) {
  HexModel m = block_and_slave();
  m.mesh.y.back() = 0.0;
  HexState s = shifted(m, 0.0, 1e-6);
  ASSERT_TRUE(contact_forces(m, s, 1e-8));
  const NodeForce& slave = s.nodal_force.back();
  EXPECT_NEAR(slave.z, 1e9 * 1e-6, 1e-6);
  EXPECT_EQ(slave.y, 0.0);
  double reaction = 0.0;
  for (std::size_t n = 0; n + 1 < s.nodal_force.size(); ++n) {
    reaction += s.nodal_force[n].z;
    EXPECT_EQ(s.nodal_force[n].y, 0.0);
  }
  EXPECT_NEAR(reaction, -slave.z, 1e-9);
}

// The points of the half sphere's slave faces: n x n to a face, their weights a partition of
// unity; the slaves' stiffness is spread over them with its total kept, and where it goes with
// the nodes' share of the faces, as their masses do (the symmetry plane's nodes have half the
// faces and half the mass of the others), a node gets its own back from its points
// (sum_q w_a(q) k_q = k_a): the points' contact is as stiff as the nodes' where they touch.
TEST(HexContact, ContactPointsShareTheSlavesPenalties) {
  HexMeshOptions o;
  o.h_contact = 1.5e-3;
  o.zone_radius = 4e-3;
  o.zone_depth = 3e-3;
  o.h_max = 6e-3;
  HexModel m;
  m.mesh = generate_hex_sphere(o);
  m.sphere_elements = m.mesh.hexes.size();
  m.mass.assign(static_cast<std::size_t>(m.mesh.num_nodes()), 1.0);
  const auto& slaves = m.mesh.sphere_surface_nodes;
  constexpr double kPenalty = 1e9;  // [N/m]
  std::size_t lowest = 0;           // the slave at the sphere's lowest point
  for (std::size_t k = 0; k < slaves.size(); ++k) {
    const bool on_plane = m.mesh.y[static_cast<std::size_t>(slaves[k])] == 0.0;
    m.penalty.push_back(on_plane ? 0.5 * kPenalty : kPenalty);
    if (m.mesh.z[static_cast<std::size_t>(slaves[k])] <
        m.mesh.z[static_cast<std::size_t>(slaves[lowest])])
      lowest = k;
  }
  double nodes_total = 0.0;
  for (const double k : m.penalty) nodes_total += k;
  for (const int n : {1, 3}) {
    SCOPED_TRACE(n);
    const std::vector<SlavePoint> points = make_slave_points(m, n);
    ASSERT_EQ(points.size() % static_cast<std::size_t>(n * n), 0U);
    std::vector<double> stiffness(slaves.size(), 0.0);
    double total = 0.0;
    for (const SlavePoint& q : points) {
      EXPECT_NEAR(q.w[0] + q.w[1] + q.w[2] + q.w[3], 1.0, 1e-15);
      total += q.penalty;
      for (std::size_t a = 0; a < 4; ++a) {
        const auto k = static_cast<std::size_t>(q.slave[a]);
        EXPECT_EQ(slaves[k], q.node[a]);
        stiffness[k] += q.w[a] * q.penalty;
      }
    }
    EXPECT_NEAR(total, nodes_total, 1e-12 * total);
    EXPECT_NEAR(stiffness[lowest], m.penalty[lowest], 1e-12 * kPenalty);
    for (std::size_t k = 0; k < slaves.size(); ++k) {
      EXPECT_GT(stiffness[k], 0.5 * m.penalty[k]);
      EXPECT_LT(stiffness[k], 2.0 * m.penalty[k]);
    }
  }
}

// Kinematic friction acts at the contact point, not at its face's nodes: one point in the middle
// of a square face of four sliding nodes, pressed into the rigid flat. Below the Coulomb limit it
// stops the point's predicted tangential velocity, the force spread over the nodes with the
// point's weights (1/4 each); above it the force is mu times the point's normal force.
HexModel sliding_face(double mu) {
  HexModel m;
  for (int a = 0; a < 4; ++a) {
    m.mesh.x.push_back(a == 1 || a == 2 ? kH : 0.0);
    m.mesh.y.push_back(a >= 2 ? kH : 0.0);
    m.mesh.z.push_back(0.0);
    m.mesh.node_body.push_back(Body::kSphere);
  }
  m.mesh.sphere_surface_nodes = {0, 1, 2, 3};
  m.contact = solver::ContactKind::kRigidPlane;
  m.h_contact = kH;
  m.penalty = {1e6, 1e6, 1e6, 1e6};
  m.mass = {1e-9, 1e-9, 1e-9, 1e-9};
  m.inv_mass = {1e9, 1e9, 1e9, 1e9};
  m.free_x = m.free_y = m.free_z = {1.0, 1.0, 1.0, 1.0};
  m.slave_points = {SlavePoint{
      .node = {0, 1, 2, 3}, .slave = {0, 1, 2, 3}, .w = {0.25, 0.25, 0.25, 0.25}, .penalty = 1e6}};
  m.friction = mu;
  m.kinematic_friction = true;
  m.velocity = 1.0;
  return m;
}

HexState pressed(const HexModel& m, double dt) {
  HexState s;
  for (std::size_t n = 0; n < 4; ++n)  // 1 um deep, sliding at 1 m/s along x
    s.node.push_back({m.mesh.x[n], m.mesh.y[n], -1e-6, 1.0, 0.0, 0.0});
  s.nodal_force.assign(4, NodeForce{0.0, 0.0, 0.0});
  s.traction.assign(1, {0.0, 0.0, 0.0});
  s.friction_link.assign(1, {});
  s.dt = dt;
  return s;
}

TEST(HexContact, KinematicFrictionActsAtTheContactPoint) {
  constexpr double kDt = 1e-7;            // [s]
  constexpr double kNormal = 1e6 * 1e-6;  // the point's normal force [N]
  {
    const HexModel m = sliding_face(10.0);  // sticks: m v / dt = 4e-3 N < 10 N
    HexState s = pressed(m, kDt);
    contact_forces(m, s, kDt);
    double v = 0.0;  // the point's predicted velocity along x
    for (std::size_t n = 0; n < 4; ++n) {
      EXPECT_NEAR(s.nodal_force[n].z, 0.25 * kNormal, 1e-12);
      v += 0.25 * (s.node[n].vx + kDt * m.inv_mass[n] * s.nodal_force[n].x);
    }
    EXPECT_NEAR(v, 0.0, 1e-9);
    EXPECT_NEAR(s.traction[0][0], -4e-9 / kDt, 1e-12);
  }
  {
    const HexModel m = sliding_face(1e-3);  // slips: 1e-3 N < 4e-3 N
    HexState s = pressed(m, kDt);
    contact_forces(m, s, kDt);
    EXPECT_NEAR(s.traction[0][0], -1e-3 * kNormal, 1e-15);
    for (std::size_t n = 0; n < 4; ++n)
      EXPECT_NEAR(s.nodal_force[n].x, -0.25 * 1e-3 * kNormal, 1e-15);
  }
}

}  // namespace
}  // namespace corlab::fem::hex_solver
