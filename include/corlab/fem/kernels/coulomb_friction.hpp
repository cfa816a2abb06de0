// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file coulomb_friction.hpp
/// Coulomb friction at one contact point, two ways.
///
/// Kinematic (kinematic_friction; Taylor & Flanagan 1989, PRONTO-3D's predictor-corrector): the
/// tangential force that makes the slave's tangential velocity relative to the master vanish at
/// the end of the step, from the predicted relative velocity (every force but friction) and the
/// pair's effective mass, t* = -m_eff v_t / dt; stick if |t*| <= mu f_n, otherwise slip with
/// t = mu f_n t* / |t*|. No spring: stick holds without a tangential displacement (no compliance
/// in series with the bodies' own) and stores no energy; what friction dissipates is its work
/// over the step, booked from the velocities before and after (friction_work).
///
/// Penalty-regularised (coulomb_friction), integrated by a return map
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

/// The kinematic update of a slave's friction force t_old [N] (0 at the step's first pass) from
/// the unit contact normal n [-], the slave's predicted velocity relative to the master at the
/// end of the step v [m/s] (with t_old acting), the pair's effective mass m_eff > 0 [kg]
/// (1 / (1/m_s + sum_j w_j^2 / m_j) for a slave on master nodes j with weights w_j; m_s on a
/// rigid master), the step dt > 0 [s], the normal force f_n >= 0 [N] and the friction
/// coefficient mu >= 0 [-]: trial t* = t_old - m_eff v_t / dt (v_t the tangential part of v), stick
/// if |t*| <= mu f_n, else t = mu f_n t* / |t*|. One slave alone (on a rigid master) sticks in one
/// update; slaves that share master nodes repeat it until the forces settle (projected
/// Gauss-Seidel). The dissipation field is left 0: the caller books friction_work once the
/// step's velocities are known.
inline FrictionUpdate kinematic_friction(const double* t_old,
                                         const double* n,
                                         const double* v,
                                         double effective_mass,
                                         double dt,
                                         double normal_force,
                                         double mu) {
  FrictionUpdate u;
  const double limit = mu * normal_force;
  if (!(limit > 0.0)) return u;
  const double vn = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
  const double scale = effective_mass / dt;
  double t[3];
  for (int i = 0; i < 3; ++i) t[i] = t_old[i] - scale * (v[i] - vn * n[i]);
  const double trial = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
  const double keep = trial <= limit ? 1.0 : limit / trial;
  for (int i = 0; i < 3; ++i) u.t[i] = keep * t[i];
  u.sliding = trial > limit;
  return u;
}

/// Work of a friction force t [N] over the central-difference step it acts in [J]:
/// 1/2 dt t . (v_before + v_after), with the slave's relative velocity v before and after the
/// step [m/s] and dt the step the force accelerates the nodes over [s] (1/2 of the two steps
/// around it). This is the force's share of the change in the product-form kinetic energy
/// 1/2 m v^{n-1/2} . v^{n+1/2}, so booking its negative as dissipated keeps the balance closed.
inline double friction_work(const double* t,
                            const double* v_before,
                            const double* v_after,
                            double dt) {
  double w = 0.0;
  for (int i = 0; i < 3; ++i) w += t[i] * (v_before[i] + v_after[i]);
  return 0.5 * dt * w;
}

}  // namespace corlab::fem
