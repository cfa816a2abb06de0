// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file mbf_oblique.hpp
/// The elastic oblique impact of a sphere on a flat with Coulomb friction and tangential
/// compliance: the theory of Maw, Barber & Fawcett (1976, Wear 38:101; 1981, J. Lubr. Technol.
/// 103:74), the verification reference of corlab's 3-D solver in the small-angle regime
/// (issue 27). docs/theory/oblique_theory.md has the equations, the sources and the checks.
///
/// The normal motion is Hertz's. The contact is cut into annuli; each annulus sticks (its
/// tangential deflection follows the bodies' relative tangential displacement) or slips (its
/// traction at the Coulomb limit mu times its normal traction), and an annulus enters contact
/// free of tangential traction: the Mindlin-Deresiewicz incremental solution for an arbitrary
/// history of normal and tangential load, in the one-dimensional form of Popov & Hess's method of
/// dimensionality reduction (each annulus of radius r is one spring of the 1-D foundation at
/// |x| = r). Time advances by leapfrog steps.
///
/// Normalisation (MBF): with kappa the ratio of the contact's tangential to its normal stiffness
/// (2(1 - nu)/(2 - nu) for like materials) and k = I/(m R^2),
///   chi  = kappa/2 (1 + 1/k),                   [-] (the single parameter of the problem)
///   psi1 = kappa v_t / (mu v_n)  = kappa tan(theta) / mu,   [-] (the incidence)
///   psi2 = kappa u' / (mu v_n'),                [-] (the local angle of reflection)
/// where u' = v_t' - R omega' is the contact point's tangential velocity at rebound (omega > 0 in
/// the rolling sense of v_t > 0) and v_n' the rebound's normal velocity. psi2 < 0: the contact
/// point's velocity has reversed. Gross sliding throughout gives psi2 = psi1 - 4 chi (the
/// rigid-body identity) and holds for psi1 >= 4 chi - 1; for psi1 <= 1 the contact sticks at
/// first.

namespace corlab::restitution {

/// Discretisation of the annuli and of time [-].
struct MbfDiscretisation {
  int annuli = 200;        ///< annuli of width a_max/annuli (the last one unbounded), >= 4
  int time_steps = 10000;  ///< leapfrog steps per Hertz contact time 2.943 alpha_max / v_n, >= 100
  /// false: the no-slip limit (no Coulomb bound, annuli leave contact with their traction
  /// released): what psi2/psi1 tends to as psi1 -> 0
  bool coulomb = true;
};

/// The normalised rebound [-].
struct MbfNormalised {
  double psi2 = 0.0;  ///< kappa u' / (mu v_n')
  /// u'/u at incidence (psi2 e_n / psi1): the contact point's tangential restitution
  double contact_point_ratio = 0.0;
  double normal_restitution = 1.0;  ///< v_n'/v_n of the discrete Hertz motion (1 - O(dt^2))
  double contact_time = 0.0;        ///< in alpha_max / v_n (2.943 for Hertz)
  int force_reversals = 0;          ///< sign changes of the tangential force while in contact
  bool gross_sliding = false;       ///< every annulus in contact slipped at every step
};

/// The MBF rebound for `chi` > 0 and `psi1` >= 0 [-]. InputError naming the field otherwise.
MbfNormalised mbf_normalised(double chi, double psi1, const MbfDiscretisation& d = {});

/// kappa, the ratio of the tangential to the normal contact stiffness of two elastic bodies,
/// (sum (1 - nu_i)/G_i) / (sum (1 - nu_i/2)/G_i) with G_i = E_i / (2 (1 + nu_i)) [-]. Moduli in
/// [Pa]; an infinite modulus is a rigid body (its terms vanish).
double mbf_stiffness_ratio(double modulus1, double poisson1, double modulus2, double poisson2);

/// chi = kappa/2 (1 + 1/k), k = I/(m R^2) (2/5 for a solid sphere) [-].
double mbf_chi(double stiffness_ratio, double gyration);

/// A sphere hitting a flat [SI].
struct MbfImpact {
  double radius = 0.0;          ///< R [m]
  double density = 0.0;         ///< sphere's density [kg/m^3]
  double sphere_modulus = 0.0;  ///< E_1 [Pa]
  double sphere_poisson = 0.0;  ///< nu_1 [-]
  double flat_modulus = 0.0;    ///< E_2 [Pa]; +infinity: the rigid flat
  double flat_poisson = 0.0;    ///< nu_2 [-]
  double velocity = 0.0;        ///< impact speed |v| [m/s]
  double angle = 0.0;           ///< theta from the normal, in (0, 90) [deg]
  double friction = 0.0;        ///< Coulomb mu > 0 [-]
  double gyration = 0.4;        ///< k = I/(m R^2) in (0, 1] [-]
};

/// The rebound of an MbfImpact [SI unless stated].
struct MbfRebound {
  double stiffness_ratio = 0.0;         ///< kappa [-]
  double chi = 0.0;                     ///< [-]
  double psi1 = 0.0;                    ///< [-]
  double psi2 = 0.0;                    ///< [-]
  double normal_restitution = 1.0;      ///< e_n [-] (1 up to the time step's error)
  double tangential_restitution = 0.0;  ///< e_t = v_t'/v_t of the centre of mass [-]
  double spin = 0.0;                    ///< omega' in the rolling sense of v_t [rad/s]
  double rebound_angle = 0.0;           ///< atan(v_t'/v_n') of the centre of mass [deg]
  double contact_slip_velocity = 0.0;   ///< u' = v_t' - R omega' [m/s]
  double tangential_impulse = 0.0;      ///< the flat's tangential impulse on the sphere [N s]
  double contact_time = 0.0;            ///< [s]
  int force_reversals = 0;              ///< [-]
  bool gross_sliding = false;
};

/// The MBF rebound of `impact`. InputError naming the field for a value out of range.
MbfRebound mbf_rebound(const MbfImpact& impact, const MbfDiscretisation& d = {});

/// Kharaz, Gorham & Salman (2001)'s case at `angle_deg` [deg from the normal]: an alumina sphere
/// (E 380 GPa, nu 0.23, rho 4000 kg/m^3, R 2.5 mm) on soda-lime glass (E 70 GPa, nu 0.25) at
/// 3.9 m/s with mu = 0.092 (data/kharaz2001/README.md).
inline MbfImpact kharaz2001_impact(double angle_deg) {
  return {.radius = 2.5e-3,
          .density = 4000.0,
          .sphere_modulus = 380e9,
          .sphere_poisson = 0.23,
          .flat_modulus = 70e9,
          .flat_poisson = 0.25,
          .velocity = 3.9,
          .angle = angle_deg,
          .friction = 0.092};
}

}  // namespace corlab::restitution
