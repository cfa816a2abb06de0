// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file hex_model.hpp
/// The 3-D explicit impact solver (issue 27; docs/theory/solver3d.md), run by simulate() for
/// solver.model = 3d: a sphere hits a flat (the rigid plane z = 0 or a deformable block below it)
/// at angle theta from the normal with Coulomb friction mu, modelled as the half (y >= 0) cut by
/// the plane of the velocity and the normal. One-point hexahedra with Flanagan-Belytschko
/// hourglass control (hex8.hpp, hourglass.hpp), the J2 material point, the Hughes-Winget rotation
/// and the bulk viscosity of the axisymmetric solver (the same kernels), penalty contact of the
/// sphere's surface points on the plane or on the block top's smooth surface (penalty_contact.hpp's
/// normal law, spline_surface.hpp) with Coulomb friction (coulomb_friction.hpp: the kinematic
/// stick of hex_friction.cpp at the same points, or the tangential penalty's return map at the
/// surface nodes), central differences at the elements' stable step. x is the tangential direction
/// of the impact (the sphere moves towards +x), z the normal (up).
///
/// The 3-D solver's model (constant) and state (mutable), shared by its steps (hex_step.cpp),
/// element pass (hex_element_loop.cpp) and contact (hex_contact.cpp); the time loop, its
/// bookkeeping and the result are the axisymmetric model's (time_loop.hpp), through the bases
/// RunConstants and RunState. Private to src/fem/solver.

#include <array>
#include <cstddef>
#include <vector>

#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/kernels/hex8.hpp"
#include "corlab/fem/kernels/hourglass.hpp"
#include "corlab/fem/kernels/j2_plasticity.hpp"
#include "corlab/fem/kernels/sym_tensor3.hpp"
#include "corlab/fem/mesh/hex_mesh.hpp"
#include "corlab/fem/solver/impact_result.hpp"
#include "corlab/fem/solver/run_cost.hpp"
#include "corlab/fem/solver/simd_level.hpp"
#include "corlab/fem/solver/simulate.hpp"
#include "fem/solver/dashpots.hpp"
#include "fem/solver/element_loop.hpp"
#include "fem/solver/hex_master_surface.hpp"
#include "fem/solver/impact_step.hpp"
#include "fem/solver/run_state.hpp"

namespace corlab::fem::hex_solver {

using Vec = std::vector<double>;

// One body's material point and wave speed.
struct BodyMaterial {
  J2Plasticity material;
  double density = 0.0;     // [kg/m^3]
  double wave_speed = 0.0;  // c_d [m/s]
};

// The constants of the body of material `mat` [SI].
inline BodyMaterial body_material(const Material& mat) {
  return {solver::material_point(mat), mat.density, mat.dilatational_wave_speed()};
}

// A run of consecutive elements of one body [begin, end).
struct HexElementRun {
  std::size_t begin = 0;
  std::size_t end = 0;
  Body body = Body::kSphere;
};

// The contact points per side of each of the sphere's slave faces [-]: 3 x 3 at the midpoints
// of equal sub-squares of the face's parameters. The sphere's and the block's elements are both
// h wide at the contact, so contact taken at the sphere's nodes alone samples the block's grid
// in step and feels it (a normal impact a quarter element off a node of the grid leaves
// omega R / v = 5.1e-3 at h = 1.5 mm); three points a side sample it out of step (1.9e-5;
// two: 6.4e-4; docs/theory/solver3d.md, "The contact points").
inline constexpr int kContactPointsPerSide = 3;

// A contact point of the sphere: a point of one of its slave faces (all four nodes slaves),
// the bilinear interpolation of the face's nodes with the weights w [-], and its penalty
// [N/m].
struct SlavePoint {
  std::array<int, 4> node{};   // the face's nodes
  std::array<int, 4> slave{};  // their indices among the slaves
  double w[4] = {};
  double penalty = 0.0;
};

// The constant part of a run (half model: RunConstants::extensive = 2; its velocity is the
// normal approach speed).
struct HexModel : solver::RunConstants {
  HexMesh mesh;
  std::array<std::vector<int>, 8> corner;  // mesh.hexes by corner (node i of element e): the
                                           // element pass gathers one corner of a block at once
  std::vector<HexElementRun> runs;         // the elements, by body
  std::array<BodyMaterial, 2> bodies;      // indexed by Body: sphere, substrate
  Vec mass, inv_mass;                      // lumped [kg], [1/kg]
  Vec free_x, free_y, free_z;              // 0 where the dof is held (symmetry plane, base) [-]
  solver::Dashpots<3> dashpots;            // the absorbing far boundary (else none; base free)
  Vec penalty;                             // per slave node [N/m]
  std::vector<SlavePoint> slave_points;    // where the normal contact acts on the sphere
  std::vector<int> top_nodes;              // the block's top nodes, each once (none: rigid)
  MasterSurface surface;                   // what the slaves meet on the block (none: rigid)
  std::size_t sphere_nodes = 0;            // nodes [0, n) are the sphere's
  std::size_t sphere_elements = 0;         // elements [0, n) are the sphere's
  // What the slaves meet: the block's top surface or the rigid flat z = 0.
  solver::ContactKind contact = solver::ContactKind::kBlockSurface;
  double sphere_mass = 0.0;  // half sphere [kg]
  double v_tangent = 0.0;    // [m/s] (towards +x)
  double friction = 0.0;     // mu [-]
  double h_contact = 0.0;    // [m]
  // Stick enforced kinematically (kinematic_friction) instead of by the tangential penalty.
  bool kinematic_friction = false;
  const SolverConfig* solver = nullptr;
};

// One node's position [m] and velocity [m/s], together: the element pass gathers both, from one
// or two cache lines per node instead of six.
struct NodeKinematics {
  double x, y, z, vx, vy, vz;
};

// One node's force [N].
struct NodeForce {
  double x, y, z;
};

// Where a contact point's kinematic friction force (HexState::traction) acts: the master nodes
// and their weights (`at`; no masters: the rigid flat), and the point's relative velocity when
// it was set, v^{n+1/2} [m/s]; its work is booked a step later, from v^{n+3/2} (friction_work).
struct SlaveFriction {
  SlaveContact at;
  std::array<double, 3> v_before{};
};

// A contact point that touches this step, for the kinematic friction pass: its index in
// HexModel::slave_points, the unit contact normal [-], its master nodes and weights (`at`; no
// masters: the rigid flat) and its normal force [N].
struct FrictionContact {
  std::size_t point = 0;
  double normal[3] = {0.0, 0.0, 1.0};
  SlaveContact at;
  double normal_force = 0.0;
  double t[3] = {0.0, 0.0, 0.0};       // friction force on the point [N]
  double v_pred[3] = {0.0, 0.0, 0.0};  // relative velocity at the step's end without it [m/s]
  double mass = 0.0;                   // effective mass for the point alone [kg]
};

// The mutable part (half model); the running sums in its base.
struct HexState : solver::RunState {
  std::vector<NodeKinematics> node;
  std::vector<NodeForce> nodal_force;
  std::array<Vec, 6> stress;      // per element: xx, yy, zz, xy, yz, zx [Pa]
  Vec eps_p;                      // per element [-]
  std::array<Vec, 12> hourglass;  // per element: Q[d][a] at d * 4 + a [N]
  // Friction force [N] of each contact point (kinematic) or slave node (penalty).
  std::vector<std::array<double, 3>> traction;
  std::vector<SlaveFriction> friction_link;        // where each point's kinematic friction acts
  std::vector<FrictionContact> touching;           // this step's contacts (scratch)
  std::vector<std::array<double, 3>> friction_dv;  // velocity change by friction (scratch) [m/s]
  Vec slave_normal_force;  // tangential penalty: each slave node's share of the points' normal
                           // force (scratch) [N]
};

// The top face of the block under (x, y) at the start positions, shifted by (di, dj) faces and
// clamped to the grid.
std::size_t face_under(const HexMesh& mesh, double x, double y, long di = 0, long dj = 0);

// The block's top nodes (of mesh.top_faces), each once, sorted.
std::vector<int> block_top_nodes(const HexMesh& mesh);

/// Where the sphere's slave node n meets the block's top: its projection on the smooth master
/// surface (hex_master_surface.hpp), from the start grid's parameters under its (x, y).
SlaveContact surface_contact(const HexModel& m, const HexState& s, std::size_t n);

/// The same for a point p [m] of the sphere's surface.
SlaveContact surface_contact_at(const HexModel& m, const HexState& s, const double* p);

/// The contact points of the model's slave faces (the sphere's surface faces whose four nodes
/// are all slaves), n x n to a face [-]. The slaves' penalties m.penalty are spread over them
/// with their total kept; a node among nodes of one penalty gets it back from its points. Throws
/// InputError when the sphere has no such face.
std::vector<SlavePoint> make_slave_points(const HexModel& m, int n);

/// The masters' velocity at the slave's contact point [m/s] (0 on the rigid flat).
std::array<double, 3> master_velocity(const SlaveContact& c, const HexState& s);

/// Adds the reaction to the slave's contact force [N], shared by the weights, to the masters.
void push_masters(const SlaveContact& c, const double* force, HexState& s);

/// Penalty contact of the sphere's contact points (the rigid flat z = 0 or the block's top;
/// penalty_contact.hpp's normal law) and Coulomb friction (coulomb_friction.hpp): kinematic, at
/// the touching contact points with their own normal force (kinematic_friction_forces after the
/// normal forces), or the tangential penalty at the slave nodes with each node's share of the
/// points' normal force: adds the contact forces to s.nodal_force, sets the
/// contact force s.force (+ up), the stored energy s.energy.contact and the deepest penetration,
/// adds the frictional work to s.energy.friction. Returns whether any slave penetrates.
bool contact_forces(const HexModel& m, HexState& s, double dt);

/// Kinematic Coulomb friction (coulomb_friction.hpp's kinematic_friction) at the contact points
/// in s.touching (each point's relative velocity interpolated from its face's nodes with the
/// weights w_a, its force spread back with the same weights), after every other force of the step
/// is in s.nodal_force: books the work of the previous step's friction forces into
/// s.energy.friction, sets s.traction and adds the new forces to s.nodal_force. dt [s] is the step
/// the forces will act over (predicted).
void kinematic_friction_forces(const HexModel& m, HexState& s, double dt);

// The steps of the time loop (time_loop.hpp), found there by argument-dependent lookup.

/// Kinematic half: v^{n+1/2} (the symmetry plane's v_y and the base held) and x^{n+1}; the
/// kinetic energy at t^n and the sphere's normal momentum and c.o.m. height.
solver::NodeSums move_nodes(const HexModel& m, HexState& s);

/// Force half: the element pass and the contact at x^{n+1}, a hysteresis sample; advances t by
/// dt and sets the next dt from the stable step.
solver::ForceReport compute_forces(const HexModel& m, HexState& s);

/// The sphere's kinetic energy for the stop rule's window average [J] (half model).
inline double rebound_kinetic_energy(const HexModel&, const HexState&, const solver::NodeSums& n) {
  return n.ke_sphere;
}

/// The sphere's kinetic energy now, at the last half step's velocities [J] (half model).
double sphere_kinetic_energy(const HexModel& m, const HexState& s);

/// The 3-D run's a-priori cost (estimate_run_cost for the 3-D model): its mesh, first step and
/// the steps to the expected end, 1.5 Hertz contact times.
RunCost estimate_hex_run_cost(const ImpactConfig& config);

/// The run (simulate()'s for solver.model = 3d).
ImpactResult run_hex_impact(const ImpactConfig& config, const SimulationControl& control);

}  // namespace corlab::fem::hex_solver
