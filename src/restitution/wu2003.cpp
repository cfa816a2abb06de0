// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/restitution/wu2003.hpp"

#include <algorithm>
#include <cmath>

#include "corlab/restitution/thornton1997.hpp"

namespace corlab::restitution {

// Wu et al. take Thornton's p_y = 1.6 sigma_y and his yield velocity.
double Wu2003::limiting_pressure() const { return Thornton1997{.pair = pair}.limiting_pressure(); }

double Wu2003::yield_velocity() const { return Thornton1997{.pair = pair}.yield_velocity(); }

double Wu2003::cor(double velocity) const {
  const double vy = yield_velocity();
  if (velocity <= vy) return 1.0;
  // 0.62 [(p_y/E*)(v/V_y)]^(-1/4) in logs
  const double e = 0.62 * std::exp(-0.25 * (std::log(limiting_pressure() / pair.effective_modulus) +
                                            std::log(velocity) - std::log(vy)));
  return clamp ? std::clamp(e, 0.0, 1.0) : e;
}

}  // namespace corlab::restitution
