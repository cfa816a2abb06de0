// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file impact_model.hpp
/// The constant part of one impact run (what MuJoCo calls the model, Laghos the operator's
/// data): element connectivity ordered by body, material parameters, lumped masses, boundary
/// conditions, the contact pairing and penalty stiffnesses, and the run's time scales. Built once
/// from the config and the mesh; never changed by a step.

#include <array>
#include <cstdint>
#include <vector>

#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/kernels/axisym_quad4.hpp"
#include "corlab/fem/mesh/mesh.hpp"
#include "fem/solver/dashpots.hpp"
#include "fem/solver/element_loop.hpp"
#include "fem/solver/run_state.hpp"

namespace corlab::fem::solver {

/// Largest subcycling level (solver.subcycling_levels <= this) [-].
constexpr int kMaxSubcyclingLevels = 6;

/// Subcycling is used only when it leaves at most this fraction of the element updates (sum of
/// 2^-L over the elements / their number): an update costs about 20 % more than one without
/// subcycling (the stored positions), so a smaller saving (fast impacts, whose contact zone covers
/// most of the fine mesh) would slow the run down [-].
constexpr double kMaxUpdateFraction = 0.8;

/// Mass scaling (docs/theory/solver.md section 12) adds at most this fraction of the sphere's
/// mass, both bodies together: measured, e then moves by <= 2e-4 relative (0.1-0.5 m/s) [-].
constexpr double kMaxAddedMassFraction = 1e-3;

/// Element subcycling (docs/theory/solver.md section 11): levels and the ranges they give.
struct SubcyclingLevels {
  int max_level = 0;               ///< largest level in use (0 = subcycling off) [-]
  std::vector<int> element;        ///< level of each (sorted) element [-]
  std::vector<int> node;           ///< level of each node = min over its elements [-]
  std::vector<double> node_scale;  ///< 2^level of each node [-]
  std::vector<int> node_order;     ///< nodes sorted by level
  /// node_order[0, node_end[L]) are the nodes of level <= L.
  std::array<int, kMaxSubcyclingLevels + 1> node_end{};
  /// Elements of level L of the sphere: [sphere_end[L-1] (or 0), sphere_end[L]); substrate the
  /// same from n_sphere_elements.
  std::array<int, kMaxSubcyclingLevels + 1> sphere_end{};
  std::array<int, kMaxSubcyclingLevels + 1> substrate_end{};
  /// Nodes of level L that carry an element of level L + 1, increasing index: where energy is in
  /// transit between levels (transit_ledger.hpp).
  std::array<std::vector<int>, kMaxSubcyclingLevels> interface_nodes;
};

/// Mass scaling (docs/theory/solver.md section 12): what it changed and by how much. The
/// per-element step scales are in ImpactModel::elements.step_scale.
struct MassScaling {
  double factor = 1.0;  ///< the factor F (power of two; 1 = none) [-]
  /// Step floor: the elements' smallest step after scaling the ones below the contact's
  /// h-squares, / the smallest physical one (1 = none) [-].
  double step_floor_scale = 1.0;
  double dt_critical_physical = 0.0;  ///< smallest physical element stable step at the start [s]
  std::vector<double> physical_mass;  ///< lumped masses without the scaling [kg]
  double added_mass = 0.0;            ///< mass added by the scaling, both bodies [kg]
  double sphere_mass_physical = 0.0;  ///< sphere mass without the scaling [kg]
};

/// The axisymmetric model; the time loop's constants in its base (run_state.hpp).
struct ImpactModel : RunConstants {
  int n_nodes = 0;
  int n_elements = 0;
  int n_sphere_elements = 0;  ///< elements [0, n) are the sphere's
  /// Connectivity, step scales and mesh indices, sphere elements first, then the substrate's
  /// (each body sorted by subcycling level).
  ElementConstants elements;
  BodyParams sphere;
  BodyParams substrate;
  std::vector<double> r0, z0;          ///< nodal positions at the start (sphere at contact) [m]
  std::vector<double> mass, inv_mass;  ///< lumped masses [kg] and their inverses [1/kg]
  std::vector<double> free_r, free_z;  ///< 1 where the dof is free, 0 where fixed [-]
  std::vector<double> is_sphere;       ///< 1 on sphere nodes, 0 on substrate nodes [-]
  std::vector<int> slaves;             ///< sphere surface nodes (contact slaves)
  std::vector<int> masters;            ///< substrate surface nodes, increasing r
  ContactKind contact = ContactKind::kSegments;
  std::vector<double> penalty;  ///< penalty stiffness of each slave [N/m]
  double sphere_mass = 0.0;     ///< [kg]
  /// The target is a free second sphere (substrate.shape = sphere): its c.o.m. motion enters the
  /// relative velocity, the indentation and the rebound energy. Else the target (the fixed flat,
  /// the rigid flat) is the ground, at rest.
  bool free_target = false;
  double target_mass = 0.0;         ///< the free target's mass [kg] (else 0)
  double z_com_target_start = 0.0;  ///< its c.o.m. height at the start [m] (else 0)
  double dt_critical = 0.0;         ///< smallest element stable step at the start [s]
  SubcyclingLevels levels;          ///< all 0 unless solver.subcycling_levels > 0
  MassScaling scaling;              ///< factor 1 and no floor unless solver.mass_scaling_max > 1
  /// The absorbing far boundary's dashpots (none unless substrate.boundary = absorbing; the base
  /// is then free).
  Dashpots<2> dashpots;

  /// The parameters of the body element e (sorted index) belongs to.
  const BodyParams& body_of(int e) const { return e < n_sphere_elements ? sphere : substrate; }
};

/// Geometry of (sorted) element e at the start positions.
Quad4Geometry initial_geometry(const ImpactModel& m, int e);

/// Element size at the contact [m]: the first master segment's length (the first slave
/// segment's for the rigid flat).
double contact_element_size(const ImpactModel& m);

/// Physical stable step [s] of (sorted) element e at the start positions and at rest, without
/// mass scaling (the model's own step is elements.step_scale[e] times this).
double physical_element_step(const ImpactModel& m, int e);

/// Builds the model from a config that passed validate() (simulate() checks it); throws
/// InputError for an invalid mesh (named field).
ImpactModel make_impact_model(const ImpactConfig& config, const Mesh& mesh);

}  // namespace corlab::fem::solver
