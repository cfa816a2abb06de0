// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file sym_tensor3.hpp
/// Symmetric second-order tensor in 3-D Cartesian coordinates (x, y, z): stress [Pa], strain [-]
/// or rate of deformation [1/s] of the 3-D solid element (hex8.hpp). Its primitives mirror those
/// of AxisymTensor (axisym_tensor.hpp), so the J2 return (j2_plasticity.hpp) is written once for
/// both.

#include <cmath>

namespace corlab::fem {

/// Components xx, yy, zz and the tensor (not engineering) shears xy, yz, zx.
struct SymTensor3 {
  double xx = 0.0;
  double yy = 0.0;
  double zz = 0.0;
  double xy = 0.0;
  double yz = 0.0;
  double zx = 0.0;
};

/// Trace xx + yy + zz.
inline double trace(const SymTensor3& a) { return a.xx + a.yy + a.zz; }

/// Double contraction a : b (each shear counted twice).
inline double contract(const SymTensor3& a, const SymTensor3& b) {
  return a.xx * b.xx + a.yy * b.yy + a.zz * b.zz + 2.0 * (a.xy * b.xy + a.yz * b.yz + a.zx * b.zx);
}

/// Deviator of a given its mean p = trace(a)/3.
inline SymTensor3 deviator(const SymTensor3& a, double p) {
  return {a.xx - p, a.yy - p, a.zz - p, a.xy, a.yz, a.zx};
}

/// sqrt(3/2 s:s) of a deviator s [same unit as s].
inline double deviatoric_equivalent(const SymTensor3& s) {
  return std::sqrt(1.5 * (s.xx * s.xx + s.yy * s.yy + s.zz * s.zz) +
                   3.0 * (s.xy * s.xy + s.yz * s.yz + s.zx * s.zx));
}

/// p I + scale s: a mean p with a scaled deviator s.
inline SymTensor3 with_deviator(double p, double scale, const SymTensor3& s) {
  return {p + scale * s.xx, p + scale * s.yy, p + scale * s.zz,
          scale * s.xy,     scale * s.yz,     scale * s.zx};
}

/// a += 2G d + lambda trace(d) I (two_g = 2G, lambda [Pa], d a strain increment [-]).
inline void add_isotropic(SymTensor3& a, const SymTensor3& d, double two_g, double lambda) {
  const double dvol = trace(d);
  a.xx += two_g * d.xx + lambda * dvol;
  a.yy += two_g * d.yy + lambda * dvol;
  a.zz += two_g * d.zz + lambda * dvol;
  a.xy += two_g * d.xy;
  a.yz += two_g * d.yz;
  a.zx += two_g * d.zx;
}

/// von Mises equivalent sqrt(3 J2) of a stress [Pa].
inline double von_mises(const SymTensor3& a) {
  return deviatoric_equivalent(deviator(a, trace(a) * (1.0 / 3.0)));
}

/// Spin increment W dt [-] of an antisymmetric tensor W = 1/2 (grad v - grad v^T), by its axial
/// components: w.x = W_zy, w.y = W_xz, w.z = W_yx (so a rigid rotation about z at rate omega has
/// w.z = omega dt).
struct Spin3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
};

}  // namespace corlab::fem
