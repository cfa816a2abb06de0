// SPDX-License-Identifier: BSD-3-Clause
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
///
/// The hexahedron (hex8.hpp) has four base vectors per direction, h_a = xi eta, eta zeta,
/// zeta xi, xi eta zeta at the nodes (Flanagan & Belytschko 1981, eq. 66), and
/// gamma_aI = 1/8 (h_aI - (h_a.x) b_xI - (h_a.y) b_yI - (h_a.z) b_zI): the same stiffness form
/// with Q_ia, q_ia = sum_I gamma_aI v_iI, f_iI += sum_a Q_ia gamma_aI and the same k.

#include "corlab/fem/kernels/axisym_quad4.hpp"
#include "corlab/fem/kernels/hex8.hpp"

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

/// The hexahedron's hourglass base vectors h_a at its nodes (xi eta, eta zeta, zeta xi,
/// xi eta zeta).
inline constexpr double kHex8HourglassBase[4][8] = {{1, -1, 1, -1, 1, -1, 1, -1},
                                                    {1, 1, -1, -1, -1, -1, 1, 1},
                                                    {1, -1, -1, 1, -1, 1, 1, -1},
                                                    {-1, 1, -1, 1, 1, -1, 1, -1}};

/// Hourglass shape vectors gamma[a][I] [-] of a hexahedron (gradients g, coordinates x, y, z).
inline void hex8_hourglass_shape(
    const Hex8Geometry& g, const double* x, const double* y, const double* z, double (*gamma)[8]) {
#pragma GCC unroll 4
  for (int a = 0; a < 4; ++a) {
    const double* h = kHex8HourglassBase[a];
    double hx = 0.0;
    double hy = 0.0;
    double hz = 0.0;
#pragma GCC unroll 8
    for (int i = 0; i < 8; ++i) {
      hx += h[i] * x[i];
      hy += h[i] * y[i];
      hz += h[i] * z[i];
    }
#pragma GCC unroll 8
    for (int i = 0; i < 8; ++i)
      gamma[a][i] = 0.125 * (h[i] - hx * g.bx[i] - hy * g.by[i] - hz * g.bz[i]);
  }
}

/// Generalised hourglass forces of a hexahedron, q[i][a] [N] for direction i = x, y, z and mode a.
struct Hex8HourglassForce {
  double q[3][4] = {};
};

/// Advances the hexahedron's hourglass forces by one step (nodal velocities vx, vy, vz [m/s],
/// stiffness [N/m], dt [s]) and adds sum_a Q_ia gamma_aI to the internal force fx, fy, fz.
/// Returns the work done against them in the step (trapezoid in Q) [J].
inline double hex8_hourglass_update(const double (*gamma)[8],
                                    const double* vx,
                                    const double* vy,
                                    const double* vz,
                                    double stiffness,
                                    double dt,
                                    Hex8HourglassForce& force,
                                    double* fx,
                                    double* fy,
                                    double* fz) {
  const double* v[3] = {vx, vy, vz};
  double* f[3] = {fx, fy, fz};
  double work = 0.0;
#pragma GCC unroll 3
  for (int d = 0; d < 3; ++d) {
#pragma GCC unroll 4
    for (int a = 0; a < 4; ++a) {
      double rate = 0.0;
#pragma GCC unroll 8
      for (int i = 0; i < 8; ++i) rate += gamma[a][i] * v[d][i];
      const double old_q = force.q[d][a];
      const double new_q = old_q + stiffness * rate * dt;
      work += 0.5 * dt * (old_q + new_q) * rate;
      force.q[d][a] = new_q;
#pragma GCC unroll 8
      for (int i = 0; i < 8; ++i) f[d][i] += new_q * gamma[a][i];
    }
  }
  return work;
}

}  // namespace corlab::fem
