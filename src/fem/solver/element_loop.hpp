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

#include "corlab/fem/kernels/j2_plasticity.hpp"

namespace corlab::fem::solver {

// Constant per-body parameters of the element loop.
struct BodyParams {
  J2Plasticity material;
  double density = 0.0;     // [kg/m^3]
  double wave_speed = 0.0;  // c_d [m/s]
  double hourglass = 0.0;   // kappa [-]
  double b1 = 0.0;
  double b2 = 0.0;
};

// Structure-of-arrays element state, elements of one body contiguous.
struct ElementState {
  // Node i (0..3, counter-clockwise) of element e: corner[i][e]. One array per corner, so that a
  // block's indices, and below its stored positions, are contiguous per corner: the gather into
  // the lane arrays vectorises without the transposition an element-major layout needs.
  std::array<std::vector<int>, 4> corner;
  std::vector<double> srr, szz, stt, srz;  // Cauchy stress [Pa]
  std::vector<double> eps_p;               // equivalent plastic strain [-]
  std::vector<double> qr, qz;              // hourglass generalised forces [N]
  // Subcycling only: position of node i at element e's last update, r_prev[i][e] [m].
  std::array<std::vector<double>, 4> r_prev, z_prev;
  std::vector<double> bv;  // viscous mean stress at each element's last update [Pa]
  // Mass scaling: stable step / the physical one (density factor step_scale^2) [-].
  std::vector<double> step_scale;
  // Sets the element nodes (n = nodes.size() elements) and sizes the element state.
  void set_nodes(const std::vector<std::array<int, 4>>& nodes) {
    const std::size_t n = nodes.size();
    for (int i = 0; i < 4; ++i) {
      corner[i].resize(n);
      for (std::size_t e = 0; e < n; ++e) corner[i][e] = nodes[e][i];
    }
    resize(n);
  }
  void resize(std::size_t n) {
    step_scale.assign(n, 1.0);
    for (auto* v : {&srr, &szz, &stt, &srz, &eps_p, &qr, &qz}) v->assign(n, 0.0);
  }
};

// Per-step sums returned by the element loop.
struct ElementSums {
  double internal_work = 0.0;
  double plastic_work = 0.0;
  double hourglass_work = 0.0;
  double viscous_work = 0.0;
  double eps_p_max = 0.0;
  double dt_min = std::numeric_limits<double>::infinity();
  double omega_min = std::numeric_limits<double>::infinity();  // smallest volume or area
  int bad_element = -1;  // first element of the block holding an inverted element
};

// Sums of the nodal update.
struct NodeSums {
  double ke = 0.0;         // kinetic energy at t^n, product form [J]
  double ke_sphere = 0.0;  // same, sphere nodes only [J]
  double p_sphere = 0.0;   // sphere z-momentum at t^{n+1/2} [kg m/s]
  double mz_sphere = 0.0;  // sum of m z over the sphere at t^{n+1} [kg m]
};

/// One pass over the elements [begin, end) of one body (all with parameters `p`) at the nodal
/// positions r, z [m] and velocities vr, vz [m/s]; fr_out/fz_out (nodal) receive -f_int [N].
/// Stresses are updated at the mid-step geometry, forces and the stable step at x^{n+1}.
void element_loop(const BodyParams& p,
                  ElementState& es,
                  int begin,
                  int end,
                  const double* __restrict r,
                  const double* __restrict z,
                  const double* __restrict vr,
                  const double* __restrict vz,
                  double* __restrict fr_out,
                  double* __restrict fz_out,
                  double dt,
                  ElementSums& sums);

/// element_loop for one subcycling level L (docs/theory/solver.md section 11): each element of
/// [begin, end) steps over dt = 2^L x the base step from its stored positions (es.r_prev/z_prev,
/// updated) to r, z (all its nodes are in sync); the rate is (x - x_prev) / dt. fr_out/fz_out
/// receive -scale f_int, scale = 2^L: the element's impulse in base-step units, applied to its
/// nodes now (asynchronous variational integrator). stable_step: also sums.dt_min (else left
/// infinite: a pass whose stable step is not used, most of them, skips its square roots).
void element_loop_subcycled(const BodyParams& p,
                            ElementState& es,
                            int begin,
                            int end,
                            const double* __restrict r,
                            const double* __restrict z,
                            double* __restrict fr_out,
                            double* __restrict fz_out,
                            double dt,
                            double scale,
                            bool stable_step,
                            ElementSums& sums);

/// Arrays of the subcycled nodal update.
struct SubcycledNodes {
  const int* order;     // node indices to update
  int count;            // how many
  const double* step;   // step of each level [s]
  const double* scale;  // 2^level of each node [-]
  double dt_avg;        // mean of the base steps before and after now [s]
  double* r;
  double* z;
  double* vr;
  double* vz;
  double* fr;  // impulses / dt_avg [N] (zeroed)
  double* fz;
  const double* m;
  const double* im;
  const double* free_r;
  const double* free_z;
  const double* sphere;
};

/// Subcycled nodal update of the listed nodes (those due now): kick v += dt_avg f/m (f: the
/// 2^L-weighted forces of the elements due now and the contact), then drift x += h v over the
/// node's own step h = step[level]. Sums: kinetic energy in product form, sphere momentum after
/// the kick, sum m z before the drift (the whole model's when all nodes are due: a major-cycle
/// boundary).
NodeSums node_update_subcycled(const SubcycledNodes& a);

/// The same over all nn nodes in index order (a.order unused), vectorised: the nodes of level <=
/// due_level are due; the others have no force (none of their elements updated) and do not move.
/// Faster than the listed update when most nodes are due.
NodeSums node_update_due(const SubcycledNodes& a, int nn, int due_level);

/// Central-difference nodal update: v^{n+1/2} = (v^{n-1/2} + dt_avg f/m) x free, x^{n+1} = x^n +
/// dt v^{n+1/2}, forces zeroed for the next assembly; dt, dt_avg [s].
NodeSums node_update(int nn,
                     double dt,
                     double dt_avg,
                     double* __restrict pr,
                     double* __restrict pz,
                     double* __restrict pvr,
                     double* __restrict pvz,
                     double* __restrict pfr,
                     double* __restrict pfz,
                     const double* __restrict pm,
                     const double* __restrict pim,
                     const double* __restrict pfree_r,
                     const double* __restrict pfree_z,
                     const double* __restrict psph);

}  // namespace corlab::fem::solver
