// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/restitution/impact_pair.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "corlab/core/error.hpp"

namespace corlab::restitution {

ImpactPair make_impact_pair(const Material& sphere,
                            const Material& substrate,
                            std::string_view model) {
  validate(sphere, "sphere");
  if (!substrate.yield_stress) {
    throw_invalid(
        "substrate.sigma_y", "missing",
        fmt::format("given for model '{}' (elastic-plastic substrate; add sy=<Pa>)", model));
  }
  validate(substrate, "substrate", /*require_yield=*/true);
  return ImpactPair{.effective_modulus = effective_modulus(sphere, substrate),
                    .sphere_density = sphere.density,
                    .yield_stress = *substrate.yield_stress,
                    .substrate_poisson = substrate.poisson_ratio};
}

void require_velocity(double velocity) { require_positive("velocity", velocity, "[m/s]"); }

void require_velocities(std::span<const double> velocities) {
  for (std::size_t i = 0; i < velocities.size(); ++i) {
    const double v = velocities[i];
    if (!(std::isfinite(v) && v > 0.0)) {
      require_positive(fmt::format("velocity[{}]", i), v, "[m/s]");
    }
  }
}

}  // namespace corlab::restitution
