// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dem/ev_damping.hpp"

#include <algorithm>
#include <cmath>

#include "corlab/core/error.hpp"
#include "corlab/dem/hysteresis_chi.hpp"

namespace corlab::dem {

UniformTable chi_table(double v_min, double v_max, const std::vector<double>& restitution) {
  std::vector<double> chi;
  chi.reserve(restitution.size());
  for (const double e : restitution) chi.push_back(exact_chi(std::min(e, 1.0)));
  return {v_min, v_max, std::move(chi)};
}

HysteresisLaw onset_law(const UniformTable& chi,
                        double rate,
                        double effective_modulus,
                        double effective_radius) {
  const double k = hertz_stiffness(effective_modulus, effective_radius);
  if (!(rate > 0.0)) return {.stiffness = k, .chi = 0.0, .impact_velocity = 1.0};
  return {.stiffness = k, .chi = chi(rate), .impact_velocity = rate};
}

}  // namespace corlab::dem
