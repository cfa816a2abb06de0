// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file stable_time_step.hpp
/// Stable time step of the explicit central-difference scheme for one element: the Courant
/// estimate dt = L_e / c_d with the Flanagan & Belytschko (1981, eq. 79) characteristic length of
/// the one-point quad, L_e = 1 / sqrt(sum_I b_I . b_I) (= h / sqrt(2) for a square of side h, the
/// exact 2-D lattice limit), reduced for damping as in ABAQUS/Explicit:
/// dt = (2 / omega_max)(sqrt(1 + xi^2) - xi). For axisymmetry the hoop stiffness adds
/// sum_I (H_I / Omega)^2 under the root (it matters only next to the axis).

#include <cmath>

#include "corlab/fem/kernels/axisym_quad4.hpp"

namespace corlab::fem {

/// Planar characteristic length 1 / sqrt(sum_I b_I . b_I) [m] (h / sqrt(2) for a square of side
/// h), without the hoop term: the element's shape alone, as the mesh generator judges it.
inline double planar_characteristic_length(const Quad4Geometry& g) {
  return 1.0 / std::sqrt(quad4_gradient_norm2(g));
}

/// Characteristic length L_e [m] of the element (hoop term included).
inline double characteristic_length(const Quad4Geometry& g) {
  double s = quad4_gradient_norm2(g);
  const double inv = 1.0 / g.omega;
#pragma GCC unroll 4
  for (const double h : g.hoop) s += h * h * inv * inv;
  return 1.0 / std::sqrt(s);
}

/// Critical step [s] of an element of length L_e [m], wave speed c_d [m/s], damping ratio xi [-].
inline double element_stable_time_step(double length, double wave_speed, double damping_ratio) {
  const double inv_c = 1.0 / wave_speed;  // loop-invariant in the solver: hoisted
  return length * inv_c * (std::sqrt(1.0 + damping_ratio * damping_ratio) - damping_ratio);
}

}  // namespace corlab::fem
