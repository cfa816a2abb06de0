#pragma once
/// @file objective_rate.hpp
/// Incremental rotation of the stress for the Jaumann rate with the Hughes & Winget (1980,
/// Int. J. Numer. Meth. Eng. 15:1862) algorithm: Q = (I - dW/2)^-1 (I + dW/2), sigma <- Q sigma
/// Q^T. In axisymmetry the spin acts only in the r-z plane; the hoop component is untouched.

#include "corlab/fem/kernels/axisym_tensor.hpp"

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

}  // namespace corlab::fem
