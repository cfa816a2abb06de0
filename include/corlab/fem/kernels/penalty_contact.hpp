// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file penalty_contact.hpp
/// Frictionless node-to-segment penalty contact (Hallquist, Goudreau & Benson 1985, Comput.
/// Methods Appl. Mech. Eng. 51:107, one-pass "slave node on master segment"). The gap of a slave
/// point s against the master segment a -> b (substrate surface, increasing r) is
///   g = (x_s - x_a) . n,  n = (-t_z, t_r),  t = (x_b - x_a)/|x_b - x_a|,
/// n pointing out of the substrate (into the sphere). For g < 0 the penalty force f = -k g n acts
/// on the slave and -f (1 - xi), -f xi on a, b (xi = projection parameter). This force field is
/// the exact gradient of the penalty energy 1/2 k g^2, so the contact is conservative. The normal
/// law itself (normal_penalty) is the one both models' contacts use: node on segment here, node
/// on facet or on the rigid plane in 3-D (hex_contact.cpp).

#include <cmath>

namespace corlab::fem {

/// Gap and projection of one slave point on one master segment.
struct SegmentProjection {
  double gap = 0.0;  ///< signed normal distance g [m] (< 0: penetration)
  double xi = 0.0;   ///< projection parameter along a -> b [-] (in [0, 1] on the segment)
  double nr = 0.0;   ///< outward normal n (r component) [-]
  double nz = 0.0;   ///< outward normal n (z component) [-]
};

/// The normal penalty law at one slave.
struct NormalPenalty {
  double force = 0.0;   ///< f_n = -k g along the outward normal, on the slave [N] (0: no contact)
  double energy = 0.0;  ///< stored energy 1/2 k g^2 [J]
};

/// The law at the gap g [m] (< 0: penetration) and penalty stiffness k [N/m]: none for g >= 0.
inline NormalPenalty normal_penalty(double gap, double stiffness) {
  if (gap >= 0.0) return {};
  return {-stiffness * gap, 0.5 * stiffness * gap * gap};
}

/// Projects the slave (rs, zs) on the segment (ra, za) -> (rb, zb) [m].
inline SegmentProjection project_on_segment(
    double rs, double zs, double ra, double za, double rb, double zb) {
  const double tr = rb - ra;
  const double tz = zb - za;
  const double len2 = tr * tr + tz * tz;
  const double inv_len = 1.0 / std::sqrt(len2);
  SegmentProjection p;
  p.nr = -tz * inv_len;
  p.nz = tr * inv_len;
  const double dr = rs - ra;
  const double dz = zs - za;
  p.gap = dr * p.nr + dz * p.nz;
  p.xi = (dr * tr + dz * tz) / len2;
  return p;
}

/// Penalty force on the slave [N] for a penetration (g < 0), stiffness k [N/m]:
/// f = -k g n; the master nodes a, b receive -(1 - xi) f and -xi f. Returns the stored energy
/// 1/2 k g^2 [J] (zero and no force when g >= 0).
inline double penalty_force(const SegmentProjection& p,
                            double stiffness,
                            double& fr_slave,
                            double& fz_slave,
                            double& fr_a,
                            double& fz_a,
                            double& fr_b,
                            double& fz_b) {
  if (p.gap >= 0.0) return 0.0;
  const NormalPenalty normal = normal_penalty(p.gap, stiffness);
  const double fr = normal.force * p.nr;
  const double fz = normal.force * p.nz;
  fr_slave += fr;
  fz_slave += fz;
  fr_a -= (1.0 - p.xi) * fr;
  fz_a -= (1.0 - p.xi) * fz;
  fr_b -= p.xi * fr;
  fz_b -= p.xi * fz;
  return normal.energy;
}

/// Penalty stiffness at penalty_scale [-] of the stability limit of a two-mass spring:
/// k = scale * m_eff (2 / dt)^2, m_eff = m_s m_m / (m_s + m_m) [kg], dt [s]; a rigid master
/// (master_mass infinite) gives m_eff = m_s.
inline double penalty_stiffness(double scale, double slave_mass, double master_mass, double dt) {
  const double m_eff =
      std::isinf(master_mass) ? slave_mass : slave_mass * master_mass / (slave_mass + master_mass);
  return scale * m_eff * 4.0 / (dt * dt);
}

/// Gap of a slave at height z [m] above the rigid flat z = 0 (outward normal +z), as a projection
/// for penalty_force (no master nodes: the flat takes the reaction).
inline SegmentProjection project_on_rigid_flat(double z) {
  SegmentProjection p;
  p.gap = z;
  p.nz = 1.0;
  return p;
}

}  // namespace corlab::fem
