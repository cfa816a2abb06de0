#pragma once
/// @file hourglass.hpp
/// Flanagan & Belytschko (1981, Int. J. Numer. Meth. Eng. 17:679, eqs. 52-59) hourglass
/// control of the one-point quad, stiffness form. Base vector h = (1, -1, 1, -1); the
/// hourglass shape vector gamma_I = 1/4 (h_I - (h.r) b_rI - (h.z) b_zI) (b = planar centroid
/// gradients) is orthogonal to every linear velocity field, so rigid motions and uniform strains
/// excite no hourglass force. Generalised force (per direction i = r, z), incrementally:
///   Q_i <- Q_i + k q_i dt,  q_i = sum_I gamma_I v_iI,  k = kappa G V sum_I (b_I . b_I),
///   f_iI -= Q_i gamma_I  (force on the nodes; as an internal force f_int,iI += Q_i gamma_I),
/// with V = 2 pi Omega the element volume. kappa = 0.05 gives about 2 % of the hourglass-mode
/// stiffness of a fully integrated square element (docs/theory/solver.md).

#include "corlab/fem/kernels/axisym_quad4.hpp"

namespace corlab::fem {

/// Hourglass shape vector gamma_I [-] of the element (planar gradients in g, coordinates r, z).
inline void hourglass_shape(const Quad4Geometry& g,
                            const double* r,
                            const double* z,
                            double* gamma) {
  const double hr = r[0] - r[1] + r[2] - r[3];
  const double hz = z[0] - z[1] + z[2] - z[3];
  constexpr double h[4] = {1.0, -1.0, 1.0, -1.0};
#pragma GCC unroll 4
  for (int i = 0; i < 4; ++i) gamma[i] = 0.25 * (h[i] - hr * g.pr[i] - hz * g.pz[i]);
}

/// Hourglass stiffness k = kappa G V sum(b.b) [N/m].
inline double hourglass_stiffness(double kappa, double shear_modulus, double volume, double bb) {
  return kappa * shear_modulus * volume * bb;
}

/// Advances the generalised hourglass forces q_r, q_z [N] by one step (nodal velocities vr, vz
/// [m/s], stiffness [N/m], step dt [s]) and adds the hourglass part Q gamma_I of the internal
/// force to f_int (fr, fz); the force on the nodes is its negative. Returns the work done against
/// the hourglass forces in the step (trapezoid in Q) [J].
inline double hourglass_update(const double* gamma,
                               const double* vr,
                               const double* vz,
                               double stiffness,
                               double dt,
                               double& q_r,
                               double& q_z,
                               double* fr,
                               double* fz) {
  double rate_r = 0.0;
  double rate_z = 0.0;
#pragma GCC unroll 4
  for (int i = 0; i < 4; ++i) {
    rate_r += gamma[i] * vr[i];
    rate_z += gamma[i] * vz[i];
  }
  const double new_r = q_r + stiffness * rate_r * dt;
  const double new_z = q_z + stiffness * rate_z * dt;
  const double work = 0.5 * dt * ((q_r + new_r) * rate_r + (q_z + new_z) * rate_z);
  q_r = new_r;
  q_z = new_z;
#pragma GCC unroll 4
  for (int i = 0; i < 4; ++i) {
    fr[i] += q_r * gamma[i];
    fz[i] += q_z * gamma[i];
  }
  return work;
}

}  // namespace corlab::fem
