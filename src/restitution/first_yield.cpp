// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/restitution/first_yield.hpp"

#include <cmath>
#include <limits>

#include "corlab/restitution/jackson_green2005.hpp"
#include "corlab/restitution/thornton1997.hpp"

namespace corlab::restitution {
double first_yield_pressure(const Material& body) {
  if (!body.yield_stress) return std::numeric_limits<double>::infinity();
  return jackson_green_c(body.poisson_ratio) * *body.yield_stress;
}

FirstYield first_yield(const Material& sphere, const Material& substrate) {
  return first_yield(sphere, substrate, sphere.density);
}

FirstYield first_yield(const Material& sphere,
                       const Material& substrate,
                       double effective_density) {
  const double p_sphere = first_yield_pressure(sphere);
  const double p_substrate = first_yield_pressure(substrate);
  FirstYield y;
  y.sphere_first = p_sphere < p_substrate;
  y.pressure = y.sphere_first ? p_sphere : p_substrate;
  y.velocity =
      thornton_yield_velocity(y.pressure, effective_modulus(sphere, substrate), effective_density);
  return y;
}

}  // namespace corlab::restitution
