// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file oblique_impact.hpp
/// Rigid-body theory of an oblique impact of a sphere on a fixed flat with Coulomb friction: the
/// analytic reference of the oblique-impact work (issue 27) and the tangential half of a DEM
/// contact law. The contact's normal impulse is P_n = m (1 + e_n) v_n. The tangential impulse
/// P_t opposes the contact point's slip u = v_t - R omega (omega > 0 in the rolling sense) and
/// is the smaller of
///   - the Coulomb limit mu P_n: the contact slides throughout, and
///   - the impulse that turns u into -beta u: P_stick = m (1 + beta) u / (1 + 1/k), with k =
///     I/(m R^2) (2/5 for a solid sphere) and beta in [-1, 1] the contact point's tangential
///     restitution (0: the sphere leaves rolling; Walton 1993, in Granular Matter, ch. 2;
///     Maw, Barber & Fawcett 1976, Wear 38:101, for the elastic origin of beta > 0).
/// Then v_t' = v_t - P_t/m and omega' = omega + P_t R / I. In the sliding regime, whatever the
/// plasticity behind e_n, e_t = v_t'/v_t = 1 - mu (1 + e_n) v_n / v_t and the rebound spin is
/// omega' R = omega R + mu (1 + e_n) v_n / k (5/2 mu (1 + e_n) v_n for a solid sphere at rest):
/// the identity an FE model with Coulomb friction must reproduce where its contact slides.

namespace corlab::restitution {

/// The sphere's motion just before contact [SI].
struct ObliqueIncidence {
  double normal_velocity = 0.0;      ///< v_n > 0, towards the flat [m/s]
  double tangential_velocity = 0.0;  ///< v_t, along the flat (any sign) [m/s]
  double spin = 0.0;                 ///< omega, positive in the rolling sense of v_t > 0 [rad/s]
  double radius = 0.0;               ///< R > 0 [m]
};

/// The contact's coefficients [-].
struct ObliqueContact {
  double normal_restitution = 1.0;      ///< e_n in [0, 1]
  double friction = 0.0;                ///< Coulomb coefficient mu >= 0
  double tangential_restitution = 0.0;  ///< beta in [-1, 1], used where the contact sticks
  double gyration = 0.4;                ///< k = I / (m R^2) in (0, 1]: 2/5 for a solid sphere
};

/// The rebound [SI].
struct ObliqueRebound {
  double normal_velocity = 0.0;      ///< e_n v_n, away from the flat [m/s]
  double tangential_velocity = 0.0;  ///< v_t' [m/s]
  double spin = 0.0;                 ///< omega' [rad/s]
  /// e_t = v_t' / v_t [-]; NaN for v_t = 0 (a normal impact)
  double tangential_restitution = 0.0;
  double rebound_angle = 0.0;  ///< atan(v_t' / v_n') from the normal [deg]
  bool slides = false;         ///< the Coulomb limit held the impulse: the contact slid throughout
};

/// The rebound of `incidence` under `contact`. InputError naming the field for a value outside
/// its range (v_n <= 0, R <= 0, e_n, mu, beta or k out of range, a non-finite value).
ObliqueRebound rigid_body_rebound(const ObliqueIncidence& incidence, const ObliqueContact& contact);

/// tan(theta) = v_t / v_n from which a sphere without spin slides throughout:
/// (1 + 1/k) mu (1 + e_n) / (1 + beta) [-] (7/2 mu (1 + e_n) for a solid sphere with beta = 0).
double sliding_threshold(const ObliqueContact& contact);

}  // namespace corlab::restitution
