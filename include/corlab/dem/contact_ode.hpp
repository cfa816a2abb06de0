// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file contact_ode.hpp
/// Two-body head-on impact under a normal contact law: m* delta'' = -F(delta, delta', history),
/// delta(0) = 0, delta'(0) = v. Integrated with GSL's gsl_odeiv2 (Runge-Kutta-Prince-Dormand 8(9),
/// adaptive) in variables scaled by the quasi-static overlap, with two events located to round-off
/// by Brent root finding on a single step: velocity reversal (sets history.max_overlap and
/// history.unloading) and separation (delta = 0 while receding), where e = -delta'/v.

#include <functional>
#include <stdexcept>

#include "corlab/dem/contact_laws.hpp"

namespace corlab::dem {

/// F [N] from delta [m], delta_dot [m/s] and the contact's history.
using ForceLaw = std::function<double(double overlap, double overlap_rate, const ContactHistory&)>;

/// Integration settings (dimensionless tolerances on the scaled state).
struct ImpactOptions {
  double tolerance = 1e-11;  ///< absolute = relative tolerance of the scaled state [-]
  long max_steps = 2000000;  ///< step budget; exceeding it throws std::runtime_error
};

/// What one impact gives.
struct ImpactOutcome {
  double restitution = 0.0;   ///< e = separation speed / impact speed [-]
  double contact_time = 0.0;  ///< duration of contact [s]
  double max_overlap = 0.0;   ///< largest overlap [m]
};

/// What simulate_impact throws when the bodies do not separate (an overdamped law holds them
/// together: no rebound) within its step budget.
struct NotSeparated : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Integrates one impact at impact speed v > 0 [m/s] of effective mass m* > 0 [kg].
/// Throws corlab::InputError for bad m*/v and NotSeparated if the bodies never separate.
ImpactOutcome simulate_impact(const ForceLaw& law,
                              double effective_mass,
                              double impact_velocity,
                              const ImpactOptions& options = {});

}  // namespace corlab::dem
