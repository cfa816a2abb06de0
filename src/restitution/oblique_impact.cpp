// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/restitution/oblique_impact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "corlab/core/error.hpp"

namespace corlab::restitution {
namespace {

// (not std::numbers: the explorer's emscripten libc++ builds this file too)
constexpr double kDegreesPerRadian = 57.295779513082320877;

void check(const char* field, double value, bool ok, const char* constraint) {
  if (!std::isfinite(value) || !ok) throw_invalid(field, value, constraint);
}

void check_contact(const ObliqueContact& c) {
  check("normal_restitution", c.normal_restitution,
        c.normal_restitution >= 0.0 && c.normal_restitution <= 1.0, "in [0, 1]");
  check("friction", c.friction, c.friction >= 0.0, ">= 0");
  check("tangential_restitution", c.tangential_restitution,
        c.tangential_restitution >= -1.0 && c.tangential_restitution <= 1.0, "in [-1, 1]");
  check("gyration", c.gyration, c.gyration > 0.0 && c.gyration <= 1.0,
        "in (0, 1] (I / (m R^2): 2/5 for a solid sphere)");
}

}  // namespace

ObliqueRebound rigid_body_rebound(const ObliqueIncidence& in, const ObliqueContact& c) {
  check("normal_velocity", in.normal_velocity, in.normal_velocity > 0.0, "> 0 (towards the flat)");
  check("tangential_velocity", in.tangential_velocity, true, "finite");
  check("spin", in.spin, true, "finite");
  check("radius", in.radius, in.radius > 0.0, "> 0");
  check_contact(c);
  // Impulses per unit mass [m/s].
  const double slip = in.tangential_velocity - in.radius * in.spin;
  const double coulomb = c.friction * (1.0 + c.normal_restitution) * in.normal_velocity;
  const double stick = (1.0 + c.tangential_restitution) * std::abs(slip) / (1.0 + 1.0 / c.gyration);
  const double impulse = std::copysign(std::min(coulomb, stick), slip);
  ObliqueRebound out;
  out.normal_velocity = c.normal_restitution * in.normal_velocity;
  out.tangential_velocity = in.tangential_velocity - impulse;
  out.spin = in.spin + impulse / (c.gyration * in.radius);
  out.tangential_restitution = in.tangential_velocity != 0.0
                                   ? out.tangential_velocity / in.tangential_velocity
                                   : std::numeric_limits<double>::quiet_NaN();
  out.rebound_angle = std::atan2(out.tangential_velocity, out.normal_velocity) * kDegreesPerRadian;
  out.slides = slip != 0.0 && coulomb <= stick;
  return out;
}

double sliding_threshold(const ObliqueContact& c) {
  check_contact(c);
  return (1.0 + 1.0 / c.gyration) * c.friction * (1.0 + c.normal_restitution) /
         (1.0 + c.tangential_restitution);
}

}  // namespace corlab::restitution
