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

std::optional<WallContact> wall_contact(const Wall& wall,
                                        const std::array<double, 3>& x,
                                        double radius) {
  if (wall.shape == WallShape::plane) {
    double gap = 0.0;
    for (int a = 0; a < 3; ++a) gap += (x[a] - wall.point[a]) * wall.normal[a];
    if (!(radius > gap)) return std::nullopt;
    return WallContact{radius - gap, wall.normal};
  }
  const int axis = wall.axis;
  if (x[axis] < wall.lo || x[axis] > wall.hi) return std::nullopt;
  const int o1 = axis == 0 ? 1 : 0;
  const int o2 = axis == 2 ? 1 : 2;
  const double d1 = x[o1] - wall.centre[0];
  const double d2 = x[o2] - wall.centre[1];
  const double rho = std::sqrt(d1 * d1 + d2 * d2);
  if (!(radius > wall.radius - rho)) return std::nullopt;
  WallContact c{radius - (wall.radius - rho), {0.0, 0.0, 0.0}};
  const double inv = 1.0 / std::max(rho, 1e-300);
  c.normal[o1] = -d1 * inv;
  c.normal[o2] = -d2 * inv;
  return c;
}

}  // namespace corlab::dem
