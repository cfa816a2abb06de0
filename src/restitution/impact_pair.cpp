// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/restitution/impact_pair.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <string_view>

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

namespace {

// > 0, finite and below the speed of light (corlab2026 at 1e307 m/s gave e = -nan; every model
// warns beyond kMaxModelVelocity long before).
void require_speed(std::string_view field, double velocity) {
  require_positive(field, velocity, "[m/s]");
  if (!(velocity < kMaxEvaluatedVelocity)) {
    throw_invalid(field, velocity,
                  fmt::format("< {:g} [m/s] (the speed of light; the models warn above 1000 m/s)",
                              kMaxEvaluatedVelocity));
  }
}

}  // namespace

void require_velocity(double velocity) { require_speed("velocity", velocity); }

void require_velocities(std::span<const double> velocities) {
  for (std::size_t i = 0; i < velocities.size(); ++i) {
    const double v = velocities[i];
    if (!(std::isfinite(v) && v > 0.0 && v < kMaxEvaluatedVelocity)) {
      require_speed(fmt::format("velocity[{}]", i), v);
    }
  }
}

}  // namespace corlab::restitution
