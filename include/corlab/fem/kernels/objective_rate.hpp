// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file objective_rate.hpp
/// Incremental rotation of the stress for the Jaumann rate with the Hughes & Winget (1980,
/// Int. J. Numer. Meth. Eng. 15:1862) algorithm: Q = (I - dW/2)^-1 (I + dW/2), sigma <- Q sigma
/// Q^T. In axisymmetry the spin acts only in the r-z plane; the hoop component is untouched. In
/// 3-D, with A = dW/2 of axial vector a = w dt / 2, Q = I + 2 (A + A^2) / (1 + |a|^2) (the Cayley
/// transform; A^2 = a a^T - |a|^2 I), again an exact rotation.

#include "corlab/fem/kernels/axisym_tensor.hpp"
#include "corlab/fem/kernels/sym_tensor3.hpp"

namespace corlab::fem {

/// Rotates the r-z block of s by the spin increment w dt [-] (w = W_rz = 1/2(dv_r/dz - dv_z/dr)).
/// For dW = [[0, a], [-a, 0]], Q = [[c, s], [-s, c]] with c = (1 - a^2/4)/(1 + a^2/4),
/// s = a/(1 + a^2/4): an exact rotation (orthogonal), second-order accurate in a.
inline void rotate_hughes_winget(AxisymTensor& stress, double spin_increment) {
  const double h = 0.5 * spin_increment;
  const double inv = 1.0 / (1.0 + h * h);
  const double c = (1.0 - h * h) * inv;
  const double s = 2.0 * h * inv;
  const double a = stress.rr;
  const double d = stress.zz;
  const double b = stress.rz;
  const double cc = c * c;
  const double ss = s * s;
  const double cs = c * s;
  stress.rr = cc * a + 2.0 * cs * b + ss * d;
  stress.zz = ss * a - 2.0 * cs * b + cc * d;
  stress.rz = cs * (d - a) + (cc - ss) * b;
}

/// Rotates s by the spin increment w dt [-] (axial components, sym_tensor3.hpp: a rigid rotation
/// about z by a small angle phi has w_dt.z = phi).
inline void rotate_hughes_winget(SymTensor3& stress, const Spin3& w_dt) {
  const double ax = 0.5 * w_dt.x;
  const double ay = 0.5 * w_dt.y;
  const double az = 0.5 * w_dt.z;
  const double f = 2.0 / (1.0 + ax * ax + ay * ay + az * az);
  // A_ij = -eps_ijk a_k; Q = I + f (A + a a^T - |a|^2 I).
  const double a2 = ax * ax + ay * ay + az * az;
  const double q[3][3] = {{1.0 + f * (ax * ax - a2), f * (-az + ax * ay), f * (ay + ax * az)},
                          {f * (az + ay * ax), 1.0 + f * (ay * ay - a2), f * (-ax + ay * az)},
                          {f * (-ay + az * ax), f * (ax + az * ay), 1.0 + f * (az * az - a2)}};
  const double m[3][3] = {{stress.xx, stress.xy, stress.zx},
                          {stress.xy, stress.yy, stress.yz},
                          {stress.zx, stress.yz, stress.zz}};
  double qm[3][3];
#pragma GCC unroll 3
  for (int i = 0; i < 3; ++i)
#pragma GCC unroll 3
    for (int j = 0; j < 3; ++j)
      qm[i][j] = q[i][0] * m[0][j] + q[i][1] * m[1][j] + q[i][2] * m[2][j];
  auto qmqt = [&](int i, int j) {
    return qm[i][0] * q[j][0] + qm[i][1] * q[j][1] + qm[i][2] * q[j][2];
  };
  stress = {qmqt(0, 0), qmqt(1, 1), qmqt(2, 2), qmqt(0, 1), qmqt(1, 2), qmqt(2, 0)};
}

}  // namespace corlab::fem
