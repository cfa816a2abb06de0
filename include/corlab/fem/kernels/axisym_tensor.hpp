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

/// von Mises equivalent sqrt(3 J2), J2 = 1/2 (s_rr^2 + s_zz^2 + s_tt^2) + s_rz^2, s = dev(a).
inline double von_mises(const AxisymTensor& a) {
  const double p = trace(a) / 3.0;
  const double srr = a.rr - p;
  const double szz = a.zz - p;
  const double stt = a.tt - p;
  return std::sqrt(1.5 * (srr * srr + szz * szz + stt * stt) + 3.0 * a.rz * a.rz);
}

}  // namespace corlab::fem
