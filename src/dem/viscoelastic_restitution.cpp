// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dem/viscoelastic_restitution.hpp"

#include <cmath>

#include "corlab/core/error.hpp"

namespace corlab::dem {

double viscoelastic_beta(const ViscoelasticHertzLaw& law, double effective_mass) {
  require_positive("stiffness", law.stiffness, "[N/m^1.5]");
  require_non_negative("damping", law.damping, "[N s/m^1.5]");
  require_positive("effective_mass", effective_mass, "[kg]");
  return law.damping * std::pow(law.stiffness, -0.6) * std::pow(effective_mass, -0.4);
}

double viscoelastic_expansion_variable(const ViscoelasticHertzLaw& law,
                                       double effective_mass,
                                       double impact_velocity) {
  require_positive("impact_velocity", impact_velocity, "[m/s]");
  return std::sqrt(viscoelastic_beta(law, effective_mass)) * std::pow(impact_velocity, 0.1);
}

double schwager_poeschel_series(const ViscoelasticHertzLaw& law,
                                double effective_mass,
                                double impact_velocity) {
  const double x = viscoelastic_expansion_variable(law, effective_mass, impact_velocity);
  const double x2 = x * x;
  return 1.0 - kViscoelasticC1 * x2 + kViscoelasticC2 * x2 * x2;
}

double schwager_poeschel_pade(const ViscoelasticHertzLaw& law,
                              double effective_mass,
                              double impact_velocity) {
  // Mueller & Poeschel (2011), Pade [1/4] of the Schwager-Poeschel (2008) series in x.
  constexpr double kA1 = 0.501086;
  constexpr double kB2 = 1.15345;
  constexpr double kB3 = 0.577977;
  constexpr double kB4 = 0.532178;
  const double x = viscoelastic_expansion_variable(law, effective_mass, impact_velocity);
  const double numerator = 1.0 + kA1 * x;
  return numerator / (numerator + x * x * (kB2 + x * (kB3 + x * kB4)));
}

}  // namespace corlab::dem
