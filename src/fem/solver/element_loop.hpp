// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file element_loop.hpp
/// The solver's two hot loops over structure-of-arrays state: the element loop (stress update,
/// internal and hourglass forces, stable step; the pure kernels of axisym_quad4.hpp,
/// j2_plasticity.hpp, objective_rate.hpp, hourglass.hpp, bulk_viscosity.hpp and
/// stable_time_step.hpp inlined and vectorised across elements) and the central-difference nodal
/// update. Private to the solver (src/fem/solver).

#include <array>
#include <limits>
#include <vector>

#include "corlab/fem/kernels/bulk_viscosity.hpp"
#include "corlab/fem/kernels/j2_plasticity.hpp"
#include "corlab/fem/kernels/stable_time_step.hpp"
#include "corlab/fem/solver/simd_level.hpp"
#include "corlab/materials/material.hpp"

namespace corlab::fem::solver {

/// The material point of a material description (elastic when it has no yield stress).
inline J2Plasticity material_point(const Material& m) {
  return J2Plasticity::from(m.youngs_modulus, m.poisson_ratio,
                            m.yield_stress.value_or(J2Plasticity::kNoYield), m.hardening_modulus);
}

/// Constant per-body parameters of the element loop.
struct BodyParams {
  J2Plasticity material;
  double density = 0.0;     ///< [kg/m^3]
  double wave_speed = 0.0;  ///< c_d [m/s]
  double hourglass = 0.0;   ///< kappa [-]
  double b1 = 0.0;          ///< linear bulk viscosity [-] (bulk_viscosity.hpp)
  double b2 = 0.0;          ///< quadratic bulk viscosity [-]

  /// Stable step [s] of an element of characteristic length `length` [m] at rest: with no
  /// volumetric rate the bulk viscosity's damping ratio is its linear part alone.
  double stable_step_at_rest(double length) const {
    return element_stable_time_step(length, wave_speed,
                                    bulk_viscous_damping_ratio(0.0, wave_speed, length, b1, b2));
  }
};

/// Constant per-element data of the element loop (part of the model), elements of one body
/// contiguous.
struct ElementConstants {
  /// Node i (0..3, counter-clockwise) of element e: corner[i][e]. One array per corner, so that a
  /// block's indices, and below its stored positions, are contiguous per corner: the gather into
  /// the lane arrays vectorises without the transposition an element-major layout needs.
  std::array<std::vector<int>, 4> corner;
  /// Mass scaling: each element's stable step / its physical one (density x step_scale^2) [-].
  std::vector<double> step_scale;
  /// Mesh index of each element (the solver sorts them by body and subcycling level).
  std::vector<int> mesh_index;

  int size() const { return static_cast<int>(step_scale.size()); }
  std::array<int, 4> nodes(int e) const {
    return {corner[0][e], corner[1][e], corner[2][e], corner[3][e]};
  }
  /// Appends element `nodes` (mesh index `index`, step scale 1).
  void push_back(const std::array<int, 4>& nodes, int index) {
    for (int i = 0; i < 4; ++i) corner[i].push_back(nodes[i]);
    step_scale.push_back(1.0);
    mesh_index.push_back(index);
  }
};

/// Mutable per-element state (part of the run's state), in the order of ElementConstants.
struct ElementState {
  std::vector<double> srr, szz, stt, srz;  ///< Cauchy stress [Pa]
  std::vector<double> eps_p;               ///< equivalent plastic strain [-]
  std::vector<double> qr, qz;              ///< hourglass generalised forces [N]
  /// Subcycling only: position of node i at element e's last update, r_prev[i][e] [m].
  std::array<std::vector<double>, 4> r_prev, z_prev;
  std::vector<double> bv;  ///< subcycling only: viscous mean stress at the last update [Pa]

  /// n elements at rest (no stress, strain or hourglass force).
  void resize(std::size_t n) {
    for (auto* v : {&srr, &szz, &stt, &srz, &eps_p, &qr, &qz}) v->assign(n, 0.0);
  }
};

/// The nodal arrays both nodal updates and the element loop work on: the state's kinematics and
/// forces, the model's masses and constraints.
struct NodalArrays {
  double* r;  ///< positions [m]
  double* z;
  double* vr;  ///< velocities [m/s]
  double* vz;
  double* fr;  ///< forces being assembled [N] (subcycling: impulses / the mean base step)
  double* fz;
  const double* m;       ///< lumped masses [kg]
  const double* im;      ///< their inverses [1/kg]
  const double* free_r;  ///< 1 where the dof is free, 0 where fixed [-]
  const double* free_z;
  const double* sphere;  ///< 1 on sphere nodes, 0 elsewhere [-]
};

/// Per-pass sums of the element loop.
struct ElementSums {
  double internal_work = 0.0;                                  ///< [J]
  double plastic_work = 0.0;                                   ///< [J]
  double hourglass_work = 0.0;                                 ///< [J]
  double viscous_work = 0.0;                                   ///< [J]
  double eps_p_max = 0.0;                                      ///< [-]
  double dt_min = std::numeric_limits<double>::infinity();     ///< smallest stable step [s]
  double omega_min = std::numeric_limits<double>::infinity();  ///< smallest volume or area
  int bad_element = -1;  ///< the first element found inverted (sorted index), or -1
};

/// Sums of the nodal update.
struct NodeSums {
  double ke = 0.0;         ///< kinetic energy at t^n, product form [J]
  double ke_sphere = 0.0;  ///< same, sphere nodes only [J]
  double p_sphere = 0.0;   ///< sphere z-momentum at t^{n+1/2} [kg m/s]
  double mz_sphere = 0.0;  ///< sum of m z over the sphere at t^{n+1} [kg m]
};

/// One pass of the element loop: the elements [begin, end) of one body (all with parameters
/// `body`) at the nodal arrays `x`, over a step dt [s].
struct ElementPass {
  const BodyParams& body;
  const ElementConstants& elements;
  ElementState& state;
  int begin;
  int end;
  NodalArrays x;
  double dt;
  /// In-run mass scaling (impact_step_mass.hpp): the step scales to use instead of
  /// elements.step_scale (null: those), indexed as the elements.
  const double* step_scale = nullptr;
  /// Receives each element's stable step [s] at its index (null: not kept).
  double* step_out = nullptr;
};

/// The pass at the nodal positions x.r, x.z [m] and velocities x.vr, x.vz [m/s]; x.fr/x.fz
/// receive -f_int [N]. Stresses are updated at the mid-step geometry, forces and the stable step
/// at x^{n+1}. Runs the code compiled for `simd`.
void element_loop(SimdLevel simd, const ElementPass& pass, ElementSums& sums);

/// element_loop for one subcycling level L (docs/theory/solver.md section 11): each element of
/// the pass steps over dt = 2^L x the base step from its stored positions (state.r_prev/z_prev,
/// updated) to x.r, x.z (all its nodes are in sync); the rate is (x - x_prev) / dt. x.fr/x.fz
/// receive -scale f_int, scale = 2^L: the element's impulse in base-step units, applied to its
/// nodes now (asynchronous variational integrator). stable_step: also sums.dt_min (else left
/// infinite: a pass whose stable step is not used, most of them, skips its square roots).
void element_loop_subcycled(
    SimdLevel simd, const ElementPass& pass, double scale, bool stable_step, ElementSums& sums);

/// What the subcycled nodal update needs beyond the nodal arrays.
struct SubcycledNodes {
  NodalArrays x;
  const int* order;     ///< node indices to update
  int count;            ///< how many
  const double* step;   ///< step of each level [s]
  const double* scale;  ///< 2^level of each node [-]
  double dt_avg;        ///< mean of the base steps before and after now [s]
};

/// Subcycled nodal update of the listed nodes (those due now): kick v += dt_avg f/m (f: the
/// 2^L-weighted forces of the elements due now and the contact), then drift x += h v over the
/// node's own step h = step[level]. Sums: kinetic energy in product form, sphere momentum after
/// the kick, sum m z before the drift (the whole model's when all nodes are due: a major-cycle
/// boundary).
NodeSums node_update_subcycled(SimdLevel simd, const SubcycledNodes& a);

/// The same over all nn nodes in index order (a.order unused), vectorised: the nodes of level <=
/// due_level are due; the others have no force (none of their elements updated) and do not move.
/// Faster than the listed update when most nodes are due.
NodeSums node_update_due(SimdLevel simd, const SubcycledNodes& a, int nn, int due_level);

/// Central-difference nodal update of the nn nodes: v^{n+1/2} = (v^{n-1/2} + dt_avg f/m) x free,
/// x^{n+1} = x^n + dt v^{n+1/2}, forces zeroed for the next assembly; dt, dt_avg [s].
NodeSums node_update(SimdLevel simd, const NodalArrays& x, int nn, double dt, double dt_avg);

}  // namespace corlab::fem::solver
