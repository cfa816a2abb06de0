// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file coulomb_friction.hpp
/// Penalty-regularised Coulomb friction at one contact point, integrated by a return map
/// (Wriggers 2006, Computational Contact Mechanics, 2nd ed., section 5.2.2; the elastic-plastic
/// analogy: stick is the elastic part, slip the plastic flow). Each step:
///   t_old is turned into the current tangent plane (its magnitude kept: a rotating contact does
///   not lose friction),
///   trial t* = t_old - k_t du_t, du_t the tangential part of the slave's displacement increment
///   relative to the master (v_rel dt),
///   |t*| <= mu f_n: stick, t = t*;  otherwise slip: t = mu f_n t* / |t*|, with the slip
///   increment (|t*| - mu f_n) / k_t along t* and the dissipation mu f_n (|t*| - mu f_n) / k_t.
/// t is the tangential force on the slave [N] (the master takes -t); 1/2 |t|^2 / k_t is the
/// energy stored in the tangential penalty spring. When the contact opens (f_n = 0) the spring
/// is released and that energy is booked as dissipated, so the energy balance stays closed.

#include <cmath>

namespace corlab::fem {

/// One friction update.
struct FrictionUpdate {
  double t[3] = {0.0, 0.0, 0.0};  ///< tangential force on the slave [N]
  double dissipation = 0.0;       ///< frictional work of the step, >= 0 [J]
  bool sliding = false;           ///< the point slips in this step
};

/// Energy stored in the tangential penalty spring, 1/2 |t|^2 / k_t [J].
inline double friction_stored_energy(const double* t, double stiffness) {
  return 0.5 * (t[0] * t[0] + t[1] * t[1] + t[2] * t[2]) / stiffness;
}

/// The update from the previous force t_old [N], the unit contact normal n [-], the relative
/// displacement increment du [m], the normal force f_n >= 0 [N], the tangential penalty
/// stiffness k_t > 0 [N/m] and the friction coefficient mu >= 0 [-].
inline FrictionUpdate coulomb_friction(const double* t_old,
                                       const double* n,
                                       const double* du,
                                       double normal_force,
                                       double stiffness,
                                       double mu) {
  FrictionUpdate u;
  if (normal_force <= 0.0) {
    u.dissipation = friction_stored_energy(t_old, stiffness);
    return u;
  }
  const double tn = t_old[0] * n[0] + t_old[1] * n[1] + t_old[2] * n[2];
  double t[3] = {t_old[0] - tn * n[0], t_old[1] - tn * n[1], t_old[2] - tn * n[2]};
  const double old_norm =
      std::sqrt(t_old[0] * t_old[0] + t_old[1] * t_old[1] + t_old[2] * t_old[2]);
  const double in_plane = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
  if (in_plane > 0.0) {
    const double keep = old_norm / in_plane;
    for (double& c : t) c *= keep;
  }
  const double dn = du[0] * n[0] + du[1] * n[1] + du[2] * n[2];
  for (int i = 0; i < 3; ++i) t[i] -= stiffness * (du[i] - dn * n[i]);
  const double trial = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
  const double limit = mu * normal_force;
  if (trial <= limit) {
    for (int i = 0; i < 3; ++i) u.t[i] = t[i];
    return u;
  }
  const double scale = limit / trial;
  for (int i = 0; i < 3; ++i) u.t[i] = t[i] * scale;
  u.dissipation = limit * (trial - limit) / stiffness;
  u.sliding = true;
  return u;
}

}  // namespace corlab::fem
