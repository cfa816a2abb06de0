// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file lane_results.hpp
/// What each lane (element) of an element pass's block reports, and how a block's lanes add to
/// the pass's ElementSums: one definition for the axisymmetric pass (element_loop.cpp) and the
/// 3-D one (hex_element_loop.cpp). Private to src/fem/solver.

#include <algorithm>

#include "fem/solver/element_loop.hpp"

namespace corlab::fem::solver {

/// Per-lane results of a block of kBlock elements, written by the lane loop (no reductions
/// inside it, so that it vectorises without reassociation).
template <int kBlock>
struct LaneResults {
  alignas(64) double w_int[kBlock];  ///< internal work over the step [J]
  alignas(64) double w_p[kBlock];    ///< plastic work over the step [J]
  alignas(64) double w_hg[kBlock];   ///< hourglass work over the step [J]
  alignas(64) double w_v[kBlock];    ///< bulk-viscous work over the step [J]
  alignas(64) double dt[kBlock];     ///< the element's stable step [s]
  alignas(64) double eps_p[kBlock];  ///< equivalent plastic strain after the step [-]
  /// The element's smallest measure at the step's geometries: volume [m^3] (3-D) or the smaller
  /// of the weighted volume and the area (axisymmetric) [m^3 or m^2]; not > 0: inverted.
  alignas(64) double omega[kBlock];
};

/// Adds lanes [0, nb) of the block that starts at element e0 to `sums`, lane by lane (so the
/// sums' order, and their bits, do not depend on the block size). The first lane whose omega is
/// not > 0 (NaN included) becomes sums.bad_element unless one is already there. kStableStep
/// false: the lanes' dt were not computed and are left out.
template <bool kStableStep, int kBlock>
[[gnu::always_inline]] inline void add_lane_sums(const LaneResults<kBlock>& out,
                                                 int e0,
                                                 int nb,
                                                 ElementSums& sums) {
  for (int l = 0; l < nb; ++l) {
    sums.internal_work += out.w_int[l];
    sums.plastic_work += out.w_p[l];
    sums.hourglass_work += out.w_hg[l];
    sums.viscous_work += out.w_v[l];
    if constexpr (kStableStep) sums.dt_min = std::min(sums.dt_min, out.dt[l]);
    sums.eps_p_max = std::max(sums.eps_p_max, out.eps_p[l]);
    sums.omega_min = std::min(sums.omega_min, out.omega[l]);
    if (!(out.omega[l] > 0.0) && sums.bad_element < 0) sums.bad_element = e0 + l;
  }
}

}  // namespace corlab::fem::solver
