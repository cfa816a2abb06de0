// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file viscoelastic_restitution.hpp
/// Analytic e(v) of the viscoelastic Hertz law (ViscoelasticHertzLaw, contact_laws.hpp:
/// F = K delta^1.5 + c delta^(1/2) delta_dot) in the small-dissipation expansion of
/// Ramirez, Poeschel, Brilliantov & Schwager (1999), Phys. Rev. E 60:4465 and
/// Schwager & Poeschel (2008), Phys. Rev. E 78:051304, and its Pade approximant (Mueller &
/// Poeschel 2011, arXiv:1102.5247). The papers' text was not available here: C1 is re-derived
/// (energy loss on the elastic path), C2 = 3 C1^2/5 and the Pade numbers come from secondary
/// sources, and all are checked against corlab's contact ODE (law_info.hpp status).
///
/// e depends only on the expansion variable x = beta^(1/2) v^(1/10) [-], with
/// beta = c K^(-3/5) m*^(-2/5) [s^(1/5) m^(-1/5)] (the papers' beta = (3/2) A rho^(2/5) with
/// rho = K/m* and A = 2c/(3K)). Separation: the papers end the collision when the force
/// vanishes (F = 0, the "delayed recovery" of the surfaces, Schwager & Poeschel 2008); the law
/// integrated to delta = 0 with an attractive end phase (LAMMPS `damping viscoelastic` without
/// `limit_damping`) agrees through x^4 and differs from the x^5 term on. Accuracy against corlab's
/// contact ODE: docs/theory/dem_contact_laws.md, tests/verification/schwager_poeschel_test.cpp.

#include "corlab/dem/contact_laws.hpp"

namespace corlab::dem {

/// C1 = 2 (5/4)^(3/5) (2/5) B(3/5, 3/2) = Gamma(3/5) sqrt(pi) / (2^(1/5) 5^(2/5) Gamma(21/10))
/// = 1.153449 [-]: e = 1 - C1 x^2 + ... (Ramirez et al. 1999; h_2 = -C1 of Schwager & Poeschel).
inline constexpr double kViscoelasticC1 = 1.1534488580952886;
/// C2 = (3/5) C1^2 = 0.798267 [-]: the x^4 coefficient (Ramirez et al. 1999; h_4 = C2).
inline constexpr double kViscoelasticC2 = 0.7982665609447952;

/// beta = c K^(-3/5) m*^(-2/5) [s^(1/5) m^(-1/5)].
/// @param law K [N/m^1.5] > 0, c [N s/m^1.5] >= 0   @param effective_mass m* [kg] > 0
double viscoelastic_beta(const ViscoelasticHertzLaw& law, double effective_mass);

/// x = beta^(1/2) v^(1/10) [-] for impact speed v [m/s] > 0.
double viscoelastic_expansion_variable(const ViscoelasticHertzLaw& law,
                                       double effective_mass,
                                       double impact_velocity);

/// Series e = 1 - C1 x^2 + C2 x^4 [-] (the two orders given in closed form; the odd powers x^1 and
/// x^3 vanish). Valid for small dissipation: |error| <= 2.5e-4 for x <= 0.3 (e >= 0.90) and
/// <= 2e-3 for x <= 0.5 (e >= 0.76); it fails beyond (x = 0.7: error 0.03, e = 0.60).
/// @param law K [N/m^1.5], c [N s/m^1.5]  @param effective_mass m* [kg]
/// @param impact_velocity v [m/s]
double schwager_poeschel_series(const ViscoelasticHertzLaw& law,
                                double effective_mass,
                                double impact_velocity);

/// Pade [1/4] approximant in x of the Schwager-Poeschel (2008) series (Mueller & Poeschel 2011), e
/// = (1 + a1 x)/(1 + a1 x + b2 x^2 + b3 x^3 + b4 x^4), a1 = 0.501086, b2 = 1.15345, b3 = 0.577977,
/// b4 = 0.532178 [-]. Recommended for larger dissipation: against force-free separation |error| <=
/// 5e-4 for x <= 0.5 (e >= 0.76) and <= 2e-3 for x <= 0.7 (e >= 0.60). Same parameters as
/// schwager_poeschel_series.
double schwager_poeschel_pade(const ViscoelasticHertzLaw& law,
                              double effective_mass,
                              double impact_velocity);

}  // namespace corlab::dem
