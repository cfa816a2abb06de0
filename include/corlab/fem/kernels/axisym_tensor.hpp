// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file axisym_tensor.hpp
/// Symmetric second-order tensor of an axisymmetric (torsion-free) state: the four non-zero
/// components in cylindrical coordinates (r, z, theta). Used for stress [Pa], strain [-] and
/// rate of deformation [1/s].

#include <cmath>

namespace corlab::fem {

/// Components rr, zz, tt (hoop, theta-theta) and rz (tensor, not engineering, shear).
struct AxisymTensor {
  double rr = 0.0;  ///< radial-radial component
  double zz = 0.0;  ///< axial-axial component
  double tt = 0.0;  ///< hoop (theta-theta) component
  double rz = 0.0;  ///< in-plane shear component (tensor)
};

/// Trace rr + zz + tt.
inline double trace(const AxisymTensor& a) { return a.rr + a.zz + a.tt; }

/// Double contraction a : b = a_rr b_rr + a_zz b_zz + a_tt b_tt + 2 a_rz b_rz.
inline double contract(const AxisymTensor& a, const AxisymTensor& b) {
  return a.rr * b.rr + a.zz * b.zz + a.tt * b.tt + 2.0 * a.rz * b.rz;
}

// The primitives of the J2 return (j2_plasticity.hpp), one set per tensor type
// (sym_tensor3.hpp has the 3-D set): the return is written once over them.

/// Deviator of a given its mean stress p = trace(a)/3.
inline AxisymTensor deviator(const AxisymTensor& a, double p) {
  return {a.rr - p, a.zz - p, a.tt - p, a.rz};
}

/// sqrt(3/2 s:s) of a deviator s [same unit as s].
inline double deviatoric_equivalent(const AxisymTensor& s) {
  return std::sqrt(1.5 * (s.rr * s.rr + s.zz * s.zz + s.tt * s.tt) + 3.0 * s.rz * s.rz);
}

/// p I + scale s: a mean stress p with a scaled deviator s.
inline AxisymTensor with_deviator(double p, double scale, const AxisymTensor& s) {
  return {p + scale * s.rr, p + scale * s.zz, p + scale * s.tt, scale * s.rz};
}

/// a += 2G d + lambda trace(d) I: the isotropic elastic increment of the strain increment d [-]
/// (two_g = 2G, lambda [Pa]).
inline void add_isotropic(AxisymTensor& a, const AxisymTensor& d, double two_g, double lambda) {
  const double dvol = trace(d);
  a.rr += two_g * d.rr + lambda * dvol;
  a.zz += two_g * d.zz + lambda * dvol;
  a.tt += two_g * d.tt + lambda * dvol;
  a.rz += two_g * d.rz;
}

/// von Mises equivalent sqrt(3 J2), J2 = 1/2 (s_rr^2 + s_zz^2 + s_tt^2) + s_rz^2, s = dev(a).
inline double von_mises(const AxisymTensor& a) {
  const double p = trace(a) / 3.0;
  const double srr = a.rr - p;
  const double szz = a.zz - p;
  const double stt = a.tt - p;
  return std::sqrt(1.5 * (srr * srr + szz * szz + stt * stt) + 3.0 * a.rz * a.rz);
}

}  // namespace corlab::fem
