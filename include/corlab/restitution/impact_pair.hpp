// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file impact_pair.hpp
/// The material quantities every analytic CoR model needs for an elastic sphere hitting an
/// elastic-perfectly-plastic flat substrate head-on (sphere = body 1, substrate = body 2).

#include <span>
#include <string_view>

#include "corlab/materials/material.hpp"

namespace corlab::restitution {

/// Pair quantities, SI units. Build with make_impact_pair() (validates) or fill directly in
/// kernels and tests.
struct ImpactPair {
  double effective_modulus = 0.0;  ///< E* [Pa], 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 (Ma eq. 3)
  double sphere_density = 0.0;     ///< rho of the sphere [kg/m^3]
  double yield_stress = 0.0;       ///< sigma_y of the substrate [Pa]
  double substrate_poisson = 0.0;  ///< nu of the substrate (the yielding body) [-]
};

/// Validates both materials (field names "sphere" and "substrate"), requires a substrate
/// yield stress (InputError naming `model`), and returns the pair quantities.
ImpactPair make_impact_pair(const Material& sphere,
                            const Material& substrate,
                            std::string_view model);

/// Largest speed a model is evaluated at [m/s], excluded: the speed of light.
inline constexpr double kMaxEvaluatedVelocity = 299'792'458.0;

/// Throws InputError "invalid velocity = <v>: must be > 0 [m/s]" unless v is finite, > 0 and
/// below kMaxEvaluatedVelocity.
void require_velocity(double velocity);

/// Same for each element; the message names the index: "invalid velocity[3] = nan: ...".
void require_velocities(std::span<const double> velocities);

}  // namespace corlab::restitution
