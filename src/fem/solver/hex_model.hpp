// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file hex_model.hpp
/// The 3-D solver's model (constant) and state (mutable), shared by its time loop
/// (hex_impact.cpp) and its contact (hex_contact.cpp). Private to src/fem/solver.

#include <array>
#include <cstddef>
#include <vector>

#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/kernels/hex8.hpp"
#include "corlab/fem/kernels/hourglass.hpp"
#include "corlab/fem/kernels/j2_plasticity.hpp"
#include "corlab/fem/kernels/sym_tensor3.hpp"
#include "corlab/fem/mesh/hex_mesh.hpp"
#include "corlab/fem/solver/hex_impact.hpp"
#include "corlab/fem/solver/run_cost.hpp"
#include "corlab/fem/solver/simd_level.hpp"

namespace corlab::fem::hex_solver {

using Vec = std::vector<double>;

// One body's material point and wave speed.
struct BodyMaterial {
  J2Plasticity material;
  double density = 0.0;     // [kg/m^3]
  double wave_speed = 0.0;  // c_d [m/s]
};

// A run of consecutive elements of one body [begin, end).
struct HexElementRun {
  std::size_t begin = 0;
  std::size_t end = 0;
  Body body = Body::kSphere;
};

// The constant part of a run (half model).
struct HexModel {
  HexMesh mesh;
  std::array<std::vector<int>, 8> corner;  // mesh.hexes by corner (node i of element e): the
                                           // element pass gathers one corner of a block at once
  std::vector<HexElementRun> runs;         // the elements, by body
  SimdLevel simd = SimdLevel::kBaseline;   // of the element pass
  std::array<BodyMaterial, 2> bodies;      // indexed by Body: sphere, substrate
  Vec mass, inv_mass;                      // lumped [kg], [1/kg]
  Vec free_x, free_y, free_z;              // 0 where the dof is held (symmetry plane, base) [-]
  Vec penalty;                             // per slave [N/m]
  std::vector<int> top_nodes;              // the block's top nodes, each once (none: rigid)
  std::size_t sphere_nodes = 0;            // nodes [0, n) are the sphere's
  bool deformable_target = false;          // the flat's block (else the rigid flat z = 0)
  double total_mass = 0.0;                 // half sphere [kg]
  double v_normal = 0.0;                   // [m/s] (> 0, towards the flat)
  double v_tangent = 0.0;                  // [m/s] (towards +x)
  double friction = 0.0;                   // mu [-]
  double dt_initial = 0.0;                 // [s]
  double t_start = 0.0;                    // release to first contact (the clock's origin) [s]
  double t_max = 0.0;                      // from the first contact [s]
  double t_wave = 0.0;                     // 4 R / c_d [s]
  double t_expected = 0.0;                 // expected end: 1.5 Hertz contact times [s]
  double h_contact = 0.0;                  // [m]
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

// The mutable part.
struct HexState {
  std::vector<NodeKinematics> node;
  std::vector<NodeForce> force;
  std::array<Vec, 6> stress;                    // per element: xx, yy, zz, xy, yz, zx [Pa]
  Vec eps_p;                                    // per element [-]
  std::array<Vec, 12> hourglass;                // per element: Q[d][a] at d * 4 + a [N]
  std::vector<std::array<double, 3>> traction;  // friction force of each slave [N]
  double t = 0.0;
  double dt = 0.0;
  long long steps = 0;
  double w_internal = 0.0;  // [J], half model
  double w_plastic = 0.0;
  double w_hourglass = 0.0;
  double w_viscous = 0.0;
  double w_friction = 0.0;
  double e_contact = 0.0;     // penalty energy stored now
  double normal_force = 0.0;  // on the half sphere, + up [N]
  double penetration_max = 0.0;
  double eps_p_max = 0.0;
};

// The top face of the block under (x, y) at the start positions, shifted by (di, dj) faces and
// clamped to the grid.
std::size_t face_under(const HexMesh& mesh, double x, double y, long di = 0, long dj = 0);

// The block's top nodes (of mesh.top_faces), each once, sorted.
std::vector<int> block_top_nodes(const HexMesh& mesh);

/// Penalty contact (the rigid flat z = 0 or the block's top) and Coulomb friction: adds the
/// contact forces to s.force, books the stored energy and the frictional work. Returns whether any
/// slave penetrates.
bool contact_forces(const HexModel& m, HexState& s, double dt);

/// The 3-D run's a-priori cost (estimate_run_cost for the 3-D model): its mesh, first step and
/// the steps to the expected end, 1.5 Hertz contact times.
RunCost estimate_hex_run_cost(const ImpactConfig& config);

/// The run (simulate_hex_impact's body).
HexImpactResult run_hex_impact(const ImpactConfig& config, const SimulationControl& control);

}  // namespace corlab::fem::hex_solver
