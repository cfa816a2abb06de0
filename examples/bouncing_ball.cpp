// Bouncing ball with a velocity-dependent coefficient of restitution, the way a DEM or multibody
// code would use corlab: an alumina sphere dropped onto an aluminium-alloy plate; at every bounce
// the rebound speed is e(v) * v with e from the Ma et al. 2023 model (or any registered model),
// instead of a guessed constant.
//
// Sample runs:
//   build/bin/example_bouncing_ball                  # ma2023, drop from 1 m
//   build/bin/example_bouncing_ball thornton1997 0.5 # another model, drop height 0.5 m
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/core.h>

#include <cmath>
#include <cstdlib>
#include <exception>
#include <string>

#include "corlab/core/error.hpp"
#include "corlab/materials/material_database.hpp"
#include "corlab/restitution/registry.hpp"

int main(int argc, char** argv) {
  const std::string model_name = argc > 1 ? argv[1] : "ma2023";
  const double drop_height = argc > 2 ? std::atof(argv[2]) : 1.0;  // [m]
  constexpr double kGravity = 9.81;                                // [m/s^2]
  constexpr double kRestSpeed = 1e-3;  // stop bouncing below this impact speed [m/s]
  try {
    corlab::require_positive("drop height", drop_height, "[m]");
    const auto& db = corlab::MaterialDatabase::builtin();
    const auto model = corlab::restitution::make_model(model_name, db.get("alumina_ma2023"),
                                                       db.get("aluminium_ma2023"));
    double v = std::sqrt(2.0 * kGravity * drop_height);  // impact speed [m/s]
    double t = std::sqrt(2.0 * drop_height / kGravity);  // time of first impact [s]
    fmt::print("model {} ({}), drop height {} m\n", model_name, model.info().citation, drop_height);
    fmt::print("{:>6} {:>12} {:>14} {:>10}\n", "bounce", "t [s]", "v_impact [m/s]", "e [-]");
    for (int bounce = 1; bounce <= 30 && v > kRestSpeed; ++bounce) {
      const double e = model.cor(v);
      fmt::print("{:>6} {:>12.5f} {:>14.5f} {:>10.4f}\n", bounce, t, v, e);
      v *= e;                   // rebound speed
      t += 2.0 * v / kGravity;  // flight time to the next impact
    }
  } catch (const corlab::InputError& err) {
    fmt::print(stderr, "error: {}\n", err.what());
    return 2;
  } catch (const std::exception& err) {
    fmt::print(stderr, "error: {}\n", err.what());
    return 3;
  }
  return 0;
}
