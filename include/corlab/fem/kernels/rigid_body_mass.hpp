// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file rigid_body_mass.hpp
/// Lumped nodal masses corrected so that a body keeps the rigid-body inertia of the shape it
/// stands for. A sphere meshed with flat-faced elements misses the lenses between its facets and
/// the true surface (2.1 % of the volume at R = 2.5 mm, h_max = 1 mm), and lumping moves the mass
/// that remains outwards, to the nodes: its gyration I/(m R^2) is 0.4019, not 2/5. In an oblique
/// impact the tangential restitution follows the gyration closely (MBF: 0.01 in k moves e_t by
/// 0.015 at psi1 = 1), so the 3-D sphere's lumped masses m_n are rescaled to m_n (a + b d_n^2),
/// d_n the node's distance from the spin axis, with (a, b) the pair that restores the body's mass
/// and its second moment about that axis exactly (docs/theory/solver3d.md, "The sphere's mass").

namespace corlab::fem {

/// The lumped masses' moments about an axis: sum m, sum m d^2, sum m d^4 [kg, kg m^2, kg m^4].
struct MassMoments {
  double m0 = 0.0;
  double m2 = 0.0;
  double m4 = 0.0;
};

/// The rescaling m_n -> m_n (a + b d_n^2) [-, 1/m^2].
struct MassRescaling {
  double a = 1.0;
  double b = 0.0;
  /// The factor a + b d^2 at the squared distance d2 [m^2].
  double factor(double d2) const { return a + b * d2; }
};

/// The rescaling whose masses sum to `mass` [kg] and whose second moment sum m d^2 is `moment`
/// [kg m^2], from the lumped masses' moments `lumped`: the 2 x 2 system
///   a m0 + b m2 = mass,  a m2 + b m4 = moment.
/// Its determinant m0 m4 - m2^2 is > 0 unless every mass sits at one distance (Cauchy-Schwarz);
/// then a uniform factor is the only choice left and the moment is not matched (a = mass/m0,
/// b = 0).
inline MassRescaling rigid_body_rescaling(const MassMoments& lumped, double mass, double moment) {
  const double det = lumped.m0 * lumped.m4 - lumped.m2 * lumped.m2;
  if (!(det > 1e-12 * lumped.m0 * lumped.m4)) return {mass / lumped.m0, 0.0};
  return {(mass * lumped.m4 - moment * lumped.m2) / det,
          (lumped.m0 * moment - lumped.m2 * mass) / det};
}

}  // namespace corlab::fem
