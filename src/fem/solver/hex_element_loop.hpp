// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file hex_element_loop.hpp
/// The 3-D solver's element pass (hex_model.hpp): blocks of elements gathered into lanes, the
/// pure kernels (hex8.hpp, hourglass.hpp, j2_plasticity.hpp, objective_rate.hpp,
/// bulk_viscosity.hpp) vectorised across the elements of a block, forces scattered in element
/// order. Compiled for each SimdLevel (simd_variants.hpp). Private to src/fem/solver.

#include "corlab/fem/solver/simd_level.hpp"
#include "fem/solver/hex_model.hpp"

namespace corlab::fem::hex_solver {

/// One pass at positions x^{n+1} and velocities v^{n+1/2} over the step dt [s]: rates at the
/// mid-step geometry, stress update, and internal and hourglass forces at x^{n+1} subtracted from
/// s.nodal_force [N]. The sums are the axisymmetric pass's (lane_results.hpp; half model;
/// omega_min: the smallest element volume at x^{n+1} or x^{n+1/2} [m^3]; bad_element: the first
/// element where that is not > 0, after which the state is meaningless and the run stops).
solver::ElementSums hex_element_pass(SimdLevel level, const HexModel& m, HexState& s, double dt);

}  // namespace corlab::fem::hex_solver
