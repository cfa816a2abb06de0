// The 3:1 transition's shape test (coarsening_layer.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "fem/mesh/coarsening_layer.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <utility>

#include "corlab/core/units.hpp"
#include "corlab/fem/kernels/axisym_quad4.hpp"
#include "corlab/fem/kernels/stable_time_step.hpp"
#include "corlab/fem/mesh/mesh_quality.hpp"

namespace corlab::fem::meshing {
namespace {

constexpr double kMinTransitionAngle = 40.0 * units::kDegree;
constexpr double kMinTransitionWidth = 0.7;
constexpr double kMinTransitionLength = 1.0 / std::numbers::sqrt2;  // a square's
/// Thickness of the coarse side's quads of a thick layer's transition, in mean fine intervals:
/// the middle of the plain template's window (width >= 0.7 and corners >= 40 deg bound the
/// coarse side's half of the layer to 1.05 ... 1.19 fine intervals).
constexpr double kCoarseSideThickness = 1.12;

}  // namespace

double thick_layer_depth(const std::array<Point, 4>& fine, Point c0, Point c1) {
  const double interval = norm(fine[3] - fine[0]) / 3.0;
  const double thickness = 0.5 * (norm(c0 - fine[0]) + norm(c1 - fine[3]));
  return std::max(kHalfwayDepth, 1.0 - kCoarseSideThickness * interval / thickness);
}

bool well_shaped_transition(
    const std::array<Point, 4>& fine, Point c0, Point c1, double h, double depth) {
  double narrowest = norm(fine[1] - fine[0]);
  for (std::size_t k = 1; k < 3; ++k) narrowest = std::min(narrowest, norm(fine[k + 1] - fine[k]));
  for (const auto& q : transition_quads(fine, c0, c1, depth)) {
    std::array<double, 4> r{};
    std::array<double, 4> z{};
    for (std::size_t k = 0; k < 4; ++k) {
      r[k] = q[k].r;
      z[k] = q[k].z;
    }
    if (!is_counter_clockwise(r, z)) {
      std::swap(r[1], r[3]);
      std::swap(z[1], z[3]);
    }
    const QuadQuality shape = quad_quality(r, z);
    const double length = planar_characteristic_length(quad4_geometry(r.data(), z.data()));
    if (!(shape.min_jacobian > 0.0) || shape.min_angle < kMinTransitionAngle ||
        shape.max_angle > kPi - kMinTransitionAngle ||
        shape.width < kMinTransitionWidth * std::max(narrowest, h) ||
        length < kMinTransitionLength * narrowest) {
      return false;
    }
  }
  return true;
}

std::vector<std::size_t> all_edges(std::size_t n) {
  std::vector<std::size_t> e(n + 1);
  std::iota(e.begin(), e.end(), std::size_t{0});
  return e;
}

}  // namespace corlab::fem::meshing
