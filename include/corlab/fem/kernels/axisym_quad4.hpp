// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file axisym_quad4.hpp
/// Kinematics of the 4-node axisymmetric quadrilateral with one-point (uniform-strain)
/// integration at one instant: the gradient operators, the rate of deformation and the nodal
/// internal forces of a constant stress.
///
/// Formulation: the uniform-strain (mean-gradient) element of Flanagan & Belytschko (1981,
/// Int. J. Numer. Meth. Eng. 17:679, eqs. 12-16), B_bar = (1/V) int B dV, carried over to
/// axisymmetry with dV = 2 pi r dA. Per radian, with Omega = int r dA:
///   Br_I = int r dN_I/dr dA,  Bz_I = int r dN_I/dz dA,  H_I = int N_I dA,
/// all exact for a straight-edged bilinear quad (edge integrals, see docs/theory/solver.md), so
///   d_rr = sum Br_I v_rI / Omega,  d_zz = sum Bz_I v_zI / Omega,  d_tt = sum H_I v_rI / Omega,
///   d_rz = 1/2 sum (Bz_I v_rI + Br_I v_zI) / Omega,  spin w = 1/2 sum (Bz_I v_rI - Br_I
///   v_zI)/Omega, f_rI = 2 pi (Br_I s_rr + Bz_I s_rz + H_I s_tt),  f_zI = 2 pi (Bz_I s_zz + Br_I
///   s_rz).
/// These reproduce every linear velocity field exactly (hoop included) and keep a uniform
/// hydrostatic stress in equilibrium on distorted meshes; the centroid formulas (rbar, b at the
/// centroid) do not (measured: docs/theory/solver.md). The planar centroid gradients b_r, b_z
/// (Flanagan & Belytschko 1981 eq. 16 in 2D) are kept for the hourglass base vectors and the
/// characteristic length.
///
/// Node order: counter-clockwise in (r, z); isoparametric corners (xi, eta) = (-1,-1), (1,-1),
/// (1,1), (-1,1).

#include "corlab/core/units.hpp"
#include "corlab/fem/kernels/axisym_tensor.hpp"

namespace corlab::fem {

/// Gradient operators of one element at one configuration. The arrays are left uninitialised on
/// purpose (quad4_geometry sets every entry): zero-filling them would block the vectorisation of
/// the element loop across elements.
struct Quad4Geometry {
  double area = 0.0;   ///< A, area in the r-z plane [m^2]
  double omega = 0.0;  ///< Omega = int r dA, volume per radian [m^3]; volume V = 2 pi Omega
  double br[4];        ///< Br_I = int r dN_I/dr dA [m^2]
  double bz[4];        ///< Bz_I = int r dN_I/dz dA [m^2]
  double hoop[4];      ///< H_I = int N_I dA [m^2]
  double pr[4];        ///< planar centroid gradient dN_I/dr [1/m]
  double pz[4];        ///< planar centroid gradient dN_I/dz [1/m]
};

/// Rate of deformation d [1/s] and in-plane spin w = W_rz = 1/2 (dv_r/dz - dv_z/dr) [1/s].
struct StrainRate {
  AxisymTensor d;
  double spin = 0.0;
};

/// Geometry of the element with node coordinates r[4], z[4] [m].
inline Quad4Geometry quad4_geometry(const double* r, const double* z) {
  Quad4Geometry g;
  const double two_a = (r[2] - r[0]) * (z[3] - z[1]) + (r[1] - r[3]) * (z[2] - z[0]);
  g.area = 0.5 * two_a;
  const double inv = 1.0 / two_a;
  g.pr[0] = (z[1] - z[3]) * inv;
  g.pr[1] = (z[2] - z[0]) * inv;
  g.pr[2] = (z[3] - z[1]) * inv;
  g.pr[3] = (z[0] - z[2]) * inv;
  g.pz[0] = (r[3] - r[1]) * inv;
  g.pz[1] = (r[0] - r[2]) * inv;
  g.pz[2] = (r[1] - r[3]) * inv;
  g.pz[3] = (r[2] - r[0]) * inv;
  // det J = j0 + j1 xi + j2 eta (the xi*eta term cancels for a bilinear map).
  const double a1 = 0.25 * (-r[0] + r[1] + r[2] - r[3]);
  const double a2 = 0.25 * (-r[0] - r[1] + r[2] + r[3]);
  const double a3 = 0.25 * (r[0] - r[1] + r[2] - r[3]);
  const double b1 = 0.25 * (-z[0] + z[1] + z[2] - z[3]);
  const double b2 = 0.25 * (-z[0] - z[1] + z[2] + z[3]);
  const double b3 = 0.25 * (z[0] - z[1] + z[2] - z[3]);
  const double j0 = a1 * b2 - a2 * b1;
  // Products with reciprocals, not divisions by constants: without -ffast-math the compiler must
  // keep a division, and divisions are the slowest instructions of the element loop.
  constexpr double kThird = 1.0 / 3.0;
  constexpr double kSixth = 1.0 / 6.0;
  const double j1 = (a1 * b3 - a3 * b1) * kThird;
  const double j2 = (a3 * b2 - a2 * b3) * kThird;
  // H_I = int N_I det J dxi deta = j0 + (j1 xi_I + j2 eta_I) / 3.
  g.hoop[0] = j0 - j1 - j2;
  g.hoop[1] = j0 + j1 - j2;
  g.hoop[2] = j0 + j1 + j2;
  g.hoop[3] = j0 - j1 + j2;
  g.omega = g.hoop[0] * r[0] + g.hoop[1] * r[1] + g.hoop[2] * r[2] + g.hoop[3] * r[3];
// Edge integrals int N_I r n ds over the two edges at node I, edge (a, b): n ds = (dz, -dr),
// int_edge N_a r ds = L (2 r_a + r_b) / 6. Then Br_I = int d(N_I r)/dr dA - H_I, Bz_I.
#pragma GCC unroll 4
  for (int i = 0; i < 4; ++i) {
    const int n = (i + 1) & 3;
    const int p = (i + 3) & 3;
    const double w_next = (2.0 * r[i] + r[n]) * kSixth;  // edge i -> n
    const double w_prev = (r[p] + 2.0 * r[i]) * kSixth;  // edge p -> i
    g.br[i] = w_next * (z[n] - z[i]) + w_prev * (z[i] - z[p]) - g.hoop[i];
    g.bz[i] = -w_next * (r[n] - r[i]) - w_prev * (r[i] - r[p]);
  }
  return g;
}

/// Rate of deformation and spin from nodal velocities vr[4], vz[4] [m/s].
inline StrainRate quad4_strain_rate(const Quad4Geometry& g, const double* vr, const double* vz) {
  double srr = 0.0, szz = 0.0, stt = 0.0, sa = 0.0, sb = 0.0;
#pragma GCC unroll 4
  for (int i = 0; i < 4; ++i) {
    srr += g.br[i] * vr[i];
    szz += g.bz[i] * vz[i];
    stt += g.hoop[i] * vr[i];
    sa += g.bz[i] * vr[i];
    sb += g.br[i] * vz[i];
  }
  const double inv = 1.0 / g.omega;
  StrainRate out;
  out.d.rr = srr * inv;
  out.d.zz = szz * inv;
  out.d.tt = stt * inv;
  out.d.rz = 0.5 * (sa + sb) * inv;
  out.spin = 0.5 * (sa - sb) * inv;
  return out;
}

/// Internal forces of the constant stress s [Pa] (total over 2 pi, [N]), written to fr, fz:
/// f_rI = 2 pi (Br_I s_rr + Bz_I s_rz + H_I s_tt),  f_zI = 2 pi (Bz_I s_zz + Br_I s_rz).
/// The force the element exerts on its nodes is the negative of this.
inline void quad4_internal_forces(const Quad4Geometry& g,
                                  const AxisymTensor& s,
                                  double* fr,
                                  double* fz) {
  constexpr double kTwoPi = 2.0 * units::kPi;
#pragma GCC unroll 4
  for (int i = 0; i < 4; ++i) {
    fr[i] = kTwoPi * (g.br[i] * s.rr + g.bz[i] * s.rz + g.hoop[i] * s.tt);
    fz[i] = kTwoPi * (g.bz[i] * s.zz + g.br[i] * s.rz);
  }
}

/// Sum over the nodes of b_r^2 + b_z^2 of the planar centroid gradients [1/m^2].
inline double quad4_gradient_norm2(const Quad4Geometry& g) {
  double s = 0.0;
#pragma GCC unroll 4
  for (int i = 0; i < 4; ++i) s += g.pr[i] * g.pr[i] + g.pz[i] * g.pz[i];
  return s;
}

}  // namespace corlab::fem
