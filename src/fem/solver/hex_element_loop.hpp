// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file hex_element_loop.hpp
/// The 3-D solver's element pass (hex_model.hpp): blocks of elements gathered into lanes, the
/// pure kernels (hex8.hpp, hourglass.hpp, j2_plasticity.hpp, objective_rate.hpp,
/// bulk_viscosity.hpp) vectorised across the elements of a block, forces scattered in element
/// order. Compiled for each SimdLevel (simd_variants.hpp). Private to src/fem/solver.

#include <limits>

#include "corlab/fem/solver/simd_level.hpp"
#include "fem/solver/hex_model.hpp"

namespace corlab::fem::hex_solver {

/// What one element pass adds up (half model).
struct HexElementSums {
  double internal_work = 0.0;                               ///< stress power over the step [J]
  double plastic_work = 0.0;                                ///< [J]
  double hourglass_work = 0.0;                              ///< [J]
  double viscous_work = 0.0;                                ///< bulk-viscous work [J]
  double dt_min = std::numeric_limits<double>::infinity();  ///< smallest stable step [s]
  double eps_p_max = 0.0;  ///< largest equivalent plastic strain [-]
  bool inverted = false;   ///< an element's volume at x^{n+1} or x^{n+1/2} is <= 0
};

/// One pass at positions x^{n+1} and velocities v^{n+1/2} over the step dt [s]: rates at the
/// mid-step geometry, stress update, and internal and hourglass forces at x^{n+1} subtracted from
/// s.fx, s.fy, s.fz [N]. After an inversion the state is meaningless (the run stops).
HexElementSums hex_element_pass(SimdLevel level, const HexModel& m, HexState& s, double dt);

}  // namespace corlab::fem::hex_solver
