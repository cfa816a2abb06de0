// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file first_yield.hpp
/// Onset of yield in a Hertz impact of two bodies (sphere on a flat). Both bodies carry the same
/// Hertz pressure p0 (the half-space fields of Johnson 1985 section 4.2, each with its own nu), so
/// body i first yields when p0 = C(nu_i) sigma_y,i (Jackson & Green 2005, C = 1.295
/// exp(0.736 nu)); the pair yields at the smaller of the two, and the impact speed that first
/// reaches it is Thornton's v_y = sqrt(pi^4/40) sqrt(p_y^5/(E*^4 rho)) (independent of R).

#include "corlab/materials/material.hpp"

namespace corlab::restitution {

/// Where and when a pair first yields.
struct FirstYield {
  double pressure = 0.0;      ///< Hertz peak pressure p0 at first yield [Pa]
  double velocity = 0.0;      ///< impact speed that first reaches it [m/s]
  bool sphere_first = false;  ///< the sphere yields first (else the substrate)
};

/// Hertz peak pressure at which `body` first yields, C(nu) sigma_y; infinite for an elastic
/// body [Pa].
double first_yield_pressure(const Material& body);

/// First yield of a sphere hitting a substrate. At least one body must have a yield stress;
/// a body without one never yields. Inputs are not validated (callers validate materials).
FirstYield first_yield(const Material& sphere, const Material& substrate);

/// The same for any pair: the Hertz impact of R*, m* is that of a sphere of density
/// rho* = 3 m* / (4 pi R*^3) on a rigid flat, so `effective_density` [kg/m^3] replaces the
/// sphere's (pair_effective_density(), material.hpp).
FirstYield first_yield(const Material& sphere, const Material& substrate, double effective_density);

}  // namespace corlab::restitution
