#include "corlab/restitution/wu2003.hpp"

#include <algorithm>
#include <cmath>

#include "corlab/restitution/thornton1997.hpp"

namespace corlab::restitution {

double Wu2003::limiting_pressure() const { return 1.6 * pair.yield_stress; }

double Wu2003::yield_velocity() const {
  return thornton_yield_velocity(limiting_pressure(), pair.effective_modulus, pair.sphere_density);
}

double Wu2003::cor(double velocity) const {
  const double vy = yield_velocity();
  if (velocity <= vy) return 1.0;
  // 0.62 [(p_y/E*)(v/V_y)]^(-1/4) in logs
  const double e = 0.62 * std::exp(-0.25 * (std::log(limiting_pressure() / pair.effective_modulus) +
                                            std::log(velocity) - std::log(vy)));
  return clamp ? std::clamp(e, 0.0, 1.0) : e;
}

}  // namespace corlab::restitution
