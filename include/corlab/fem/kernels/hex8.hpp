// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file hex8.hpp
/// Kinematics of the 8-node hexahedron with one-point (uniform-strain) integration, the 3-D
/// counterpart of axisym_quad4.hpp and of ABAQUS C3D8R: the exact volume, the mean gradient
/// operator, the rate of deformation and spin, and the nodal internal forces of a constant
/// stress.
///
/// Formulation: Flanagan & Belytschko (1981, Int. J. Numer. Meth. Eng. 17:679, eqs. 12-16, 79):
/// the mean gradient b_iI = (1/V) int dN_I/dx_i dV equals (1/V) dV/dx_iI, with V the exact volume
/// of the trilinear hexahedron. V is linear in each coordinate set, so
///   12 dV/dx_0 = y1 ((z4 + z5) - (z2 + z3)) + y2 (z1 - z3) + y3 ((z1 + z2) - (z4 + z7))
///              + y4 ((z3 + z7) - (z1 + z5)) + y5 (z4 - z1) + y7 (z3 - z4)
/// (derived with sympy from int det J; the other nodes by the cube rotation that takes node 0 to
/// node I, the other directions by the cyclic exchange x -> y -> z), and V = sum_I x_I dV/dx_I.
/// These reproduce every linear velocity field exactly on any hexahedron, and a uniform stress
/// leaves every interior node of a distorted mesh in equilibrium.
///
/// Node order: isoparametric corners (xi, eta, zeta) = (-,-,-), (+,-,-), (+,+,-), (-,+,-),
/// (-,-,+), (+,-,+), (+,+,+), (-,+,+) (the bottom face counter-clockwise seen from +zeta).

#include <cmath>

#include "corlab/fem/kernels/sym_tensor3.hpp"

namespace corlab::fem {

/// Gradient operator of one hexahedron at one configuration. Left uninitialised on purpose, as
/// Quad4Geometry: hex8_geometry sets every entry.
struct Hex8Geometry {
  double volume;  ///< V [m^3]
  double bx[8];   ///< mean dN_I/dx [1/m]
  double by[8];   ///< mean dN_I/dy [1/m]
  double bz[8];   ///< mean dN_I/dz [1/m]
};

/// The node relabelling of the cube rotation that takes node 0 to node I (row I: the node that
/// plays local node k of the node-0 formula).
inline constexpr int kHex8Rotation[8][8] = {{0, 1, 2, 3, 4, 5, 6, 7}, {1, 0, 4, 5, 2, 3, 7, 6},
                                            {2, 3, 0, 1, 6, 7, 4, 5}, {3, 2, 6, 7, 0, 1, 5, 4},
                                            {4, 5, 1, 0, 7, 6, 2, 3}, {5, 4, 7, 6, 1, 0, 3, 2},
                                            {6, 7, 3, 2, 5, 4, 0, 1}, {7, 6, 5, 4, 3, 2, 1, 0}};

/// 12 dV/dx of node p[0] from the other two coordinate sets (y, z) [m^2]; with (z, x) it is
/// 12 dV/dy, with (x, y) 12 dV/dz.
inline double hex8_volume_derivative12(const double* y, const double* z, const int* p) {
  const double y1 = y[p[1]], y2 = y[p[2]], y3 = y[p[3]], y4 = y[p[4]], y5 = y[p[5]], y7 = y[p[7]];
  const double z1 = z[p[1]], z2 = z[p[2]], z3 = z[p[3]], z4 = z[p[4]], z5 = z[p[5]], z7 = z[p[7]];
  return y1 * ((z4 + z5) - (z2 + z3)) + y2 * (z1 - z3) + y3 * ((z1 + z2) - (z4 + z7)) +
         y4 * ((z3 + z7) - (z1 + z5)) + y5 * (z4 - z1) + y7 * (z3 - z4);
}

/// All eight 12 dV/dx_I [m^2] from the other two coordinate sets (y, z) into d[8] (with (z, x):
/// 12 dV/dy, with (x, y): 12 dV/dz): hex8_volume_derivative12 of every node, with the
/// differences the eight share computed once (found by sympy's common-subexpression elimination
/// of the eight: 63 operations instead of 184; a test compares the two).
inline void hex8_volume_derivatives12(const double* y, const double* z, double* d) {
  const double z14 = z[1] - z[4], z13 = z[1] - z[3], z34 = z[3] - z[4], z25 = z[2] - z[5];
  const double z57 = z[5] - z[7], z27 = z[2] - z[7], z05 = z[0] - z[5], z02 = z[0] - z[2];
  const double z46 = z[4] - z[6], z36 = z[3] - z[6], z16 = z[1] - z[6], z07 = z[0] - z[7];
  const double a = z34 + z25;
  const double b = z13 + z57;
  const double c = z14 + z27;
  const double e = z02 + z46;
  const double f = z05 + z36;
  const double g = z16 + z07;
  d[0] = -z14 * y[5] + c * y[3] + z13 * y[2] + z34 * y[7] - a * y[1] - b * y[4];
  d[1] = z05 * y[4] - z02 * y[3] + e * y[5] - f * y[2] - z25 * y[6] + a * y[0];
  d[2] = -z36 * y[7] + f * y[1] + z16 * y[5] - z13 * y[0] - g * y[3] + b * y[6];
  d[3] = z27 * y[6] - c * y[0] + z02 * y[1] - e * y[7] - z07 * y[4] + g * y[2];
  d[4] = -z05 * y[1] + f * y[7] + z07 * y[3] - g * y[5] - z57 * y[6] + b * y[0];
  d[5] = z14 * y[0] - c * y[6] + z46 * y[7] - e * y[1] - z16 * y[2] + g * y[4];
  d[6] = -z27 * y[3] + c * y[5] + z25 * y[1] - a * y[7] + z57 * y[4] - b * y[2];
  d[7] = -z46 * y[5] + e * y[3] + z36 * y[2] - f * y[4] - z34 * y[0] + a * y[6];
}

/// Geometry of the element with node coordinates x[8], y[8], z[8] [m]. A tangled element has
/// V <= 0 (the caller checks: its gradients are then meaningless).
inline Hex8Geometry hex8_geometry(const double* x, const double* y, const double* z) {
  Hex8Geometry g;
  constexpr double kTwelfth = 1.0 / 12.0;
  hex8_volume_derivatives12(y, z, g.bx);
  hex8_volume_derivatives12(z, x, g.by);
  hex8_volume_derivatives12(x, y, g.bz);
  double volume = 0.0;
#pragma GCC unroll 8
  for (int i = 0; i < 8; ++i) {
    g.bx[i] *= kTwelfth;
    g.by[i] *= kTwelfth;
    g.bz[i] *= kTwelfth;
    volume += x[i] * g.bx[i];
  }
  g.volume = volume;
  const double inv = 1.0 / volume;
#pragma GCC unroll 8
  for (int i = 0; i < 8; ++i) {
    g.bx[i] *= inv;
    g.by[i] *= inv;
    g.bz[i] *= inv;
  }
  return g;
}

/// Rate of deformation d [1/s] and spin (axial components of W = 1/2 (grad v - grad v^T)) [1/s].
struct StrainRate3 {
  SymTensor3 d;
  Spin3 spin;
};

/// d and W of the nodal velocities vx, vy, vz [m/s]: grad v = sum_I v_I (x) b_I.
inline StrainRate3 hex8_strain_rate(const Hex8Geometry& g,
                                    const double* vx,
                                    const double* vy,
                                    const double* vz) {
  double l[3][3] = {};  // l[i][j] = dv_i/dx_j
#pragma GCC unroll 8
  for (int n = 0; n < 8; ++n) {
    const double b[3] = {g.bx[n], g.by[n], g.bz[n]};
#pragma GCC unroll 3
    for (int j = 0; j < 3; ++j) {
      l[0][j] += vx[n] * b[j];
      l[1][j] += vy[n] * b[j];
      l[2][j] += vz[n] * b[j];
    }
  }
  StrainRate3 r;
  r.d = {l[0][0],
         l[1][1],
         l[2][2],
         0.5 * (l[0][1] + l[1][0]),
         0.5 * (l[1][2] + l[2][1]),
         0.5 * (l[2][0] + l[0][2])};
  r.spin = {0.5 * (l[2][1] - l[1][2]), 0.5 * (l[0][2] - l[2][0]), 0.5 * (l[1][0] - l[0][1])};
  return r;
}

/// Adds the internal force of a uniform stress s [Pa], f_iI = V s_ij b_jI [N], to fx, fy, fz
/// (the force on the nodes is its negative).
inline void hex8_add_internal_force(
    const Hex8Geometry& g, const SymTensor3& s, double* fx, double* fy, double* fz) {
  const double v = g.volume;
#pragma GCC unroll 8
  for (int n = 0; n < 8; ++n) {
    fx[n] += v * (s.xx * g.bx[n] + s.xy * g.by[n] + s.zx * g.bz[n]);
    fy[n] += v * (s.xy * g.bx[n] + s.yy * g.by[n] + s.yz * g.bz[n]);
    fz[n] += v * (s.zx * g.bx[n] + s.yz * g.by[n] + s.zz * g.bz[n]);
  }
}

/// sum_I b_I . b_I [1/m^2].
inline double hex8_gradient_norm2(const Hex8Geometry& g) {
  double s = 0.0;
#pragma GCC unroll 8
  for (int n = 0; n < 8; ++n) s += g.bx[n] * g.bx[n] + g.by[n] * g.by[n] + g.bz[n] * g.bz[n];
  return s;
}

/// Characteristic length L_e = 1 / sqrt(2 sum_I b_I . b_I) [m]: the uniform-strain element's
/// highest frequency is at most c sqrt(n sum_I b_I . b_I) for n lumped nodes (Flanagan &
/// Belytschko 1981, eq. 79), so dt = 2 / omega = L_e / c with n = 8; a cube of side h gives
/// h / sqrt(3), the 3-D lattice limit (the quad's 1 / sqrt(sum b.b), n = 4, gives h / sqrt(2)).
inline double hex8_characteristic_length(const Hex8Geometry& g) {
  return 1.0 / std::sqrt(2.0 * hex8_gradient_norm2(g));
}

}  // namespace corlab::fem
