// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file jackson_green2010.hpp
/// Jackson R.L., Green I., Marghitu D.B. (2010), "Predicting the coefficient of restitution of
/// impacting elastic-perfectly plastic spheres", Nonlinear Dyn. 60(3):217-229, as reconstructed
/// in the corlab model reference (published equations not read):
///  - energy models "J-G1"/"J-G2": load with the Jackson-Green (2005) law to W_load = m v^2/2,
///    unload elastically with a residual model, e^2 = W_unload / W_load;
///  - the empirical fit e(V' = v/V_c).

#include "corlab/restitution/impact_pair.hpp"
#include "corlab/restitution/jackson_green2005.hpp"

namespace corlab::restitution {

/// Residual (unloading) model used after loading to omega_max.
enum class JacksonGreenResidual {
  /// J-G1 (UNVERIFIED constants): Etsion, Kligerman & Kadin (2005) unloading
  ///   P/P_max = ((omega - omega_res)/(omega_max - omega_res))^n, n = 1.5 omega*_max^-0.0331,
  ///   omega_res/omega_max = 1.02 [1 - ((omega*_max + 5.9)/6.9)^-0.54] (normalised so that
  ///   omega_res = 0 at omega*_max = 1), W_unload = P_max (omega_max - omega_res)/(n + 1).
  kEtsion2005,
  /// J-G2: Hertz unloading with the contact radius continuous at reversal:
  ///   R_bar = 4E' a_m^3/(3 P_max), omega_bar = omega_max - 3 P_max/(4E' a_m),
  ///   W_unload = 8/15 E' sqrt(R_bar) (omega_max - omega_bar)^2.5, a_m from the JG 2005 law.
  kContinuousContactRadius,
};

/// Energy-integral CoR model (J-G1 / J-G2). e is independent of R (R only sets the scale of
/// omega_c, P_c and m); R = 1 m by default.
struct JacksonGreen2010 {
  ImpactPair pair;                                                                 ///< materials
  JacksonGreenResidual residual = JacksonGreenResidual::kContinuousContactRadius;  ///< variant
  double radius = 1.0;  ///< sphere radius R [m]
  bool clamp = true;    ///< clamp e to [0, 1]

  /// The loading law for this pair and radius.
  JacksonGreen2005 loading_law() const;
  /// V_c [m/s].
  double yield_velocity() const;
  /// Sphere mass m = 4/3 pi R^3 rho [kg].
  double mass() const;
  /// Loading work W(omega) = integral_0^omega P d(omega) [J] (Hertz part analytic, the rest by
  /// composite 8-point Gauss-Legendre on a geometrically graded grid).
  double loading_work(double interference) const;
  /// omega_max [m] with W(omega_max) = m v^2/2 (bracketing + safeguarded Newton, dW/domega = P).
  double max_interference(double velocity) const;
  /// Elastic unloading work [J] from omega_max [m] with the chosen residual model.
  double unloading_work(double max_interference) const;
  /// CoR at v > 0 [m/s]: 1 for v <= V_c, else sqrt(W_unload/W_load).
  double cor(double velocity) const;
};

/// Definition of the yield strain in the empirical fit (unconfirmed which one JGM 2010 uses).
enum class JacksonGreenFitStrain {
  kYieldOverModulus,        ///< eps = S_y / E'
  kCTimesYieldOverModulus,  ///< eps = C(nu) S_y / E'
};

/// Jackson, Green & Marghitu (2010) empirical fit (one public source):
/// e = 1 - 0.0361 eps^-0.114 ln(V') (V' - 1)^(9.5 eps), V' = v/V_c > 1; e = 1 for V' <= 1.
struct JacksonGreen2010Fit {
  ImpactPair pair;                                                          ///< materials
  JacksonGreenFitStrain strain = JacksonGreenFitStrain::kYieldOverModulus;  ///< eps choice
  bool clamp = true;                                                        ///< clamp e to [0, 1]

  /// eps [-].
  double yield_strain() const;
  /// V_c [m/s].
  double yield_velocity() const;
  /// CoR at v > 0 [m/s].
  double cor(double velocity) const;
};

}  // namespace corlab::restitution
