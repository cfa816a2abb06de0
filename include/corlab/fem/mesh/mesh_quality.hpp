// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file mesh_quality.hpp
/// Shape and size measures of a quad mesh (pure functions, per body).

#include <array>

#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/mesh/mesh.hpp"

namespace corlab::fem {

/// Quality of one quadrilateral with corners (r[k], z[k]), k = 0..3 counter-clockwise.
struct QuadQuality {
  double min_angle = 0.0;     ///< smallest interior angle [rad]
  double max_angle = 0.0;     ///< largest interior angle [rad]
  double aspect_ratio = 0.0;  ///< longest / shortest edge [-]
  double min_jacobian = 0.0;  ///< smallest corner Jacobian det (bilinear map from [-1,1]^2) [m^2]
  double characteristic_length = 0.0;  ///< area / longest diagonal, the stable-step length [m]
  double width = 0.0;   ///< area / longest edge, the element thickness (h for an h-square) [m]
  double area = 0.0;    ///< (r, z) area [m^2]
  double volume = 0.0;  ///< axisymmetric volume, integral of 2 pi r dA [m^3]
};

/// Quality of one quad.
QuadQuality quad_quality(const std::array<double, 4>& r, const std::array<double, 4>& z);

/// Aggregate quality of the elements of one body.
struct MeshQuality {
  int elements = 0;                        ///< element count [-]
  int nodes = 0;                           ///< nodes of the body [-]
  double min_angle = 0.0;                  ///< smallest interior angle [rad]
  double max_angle = 0.0;                  ///< largest interior angle [rad]
  double max_aspect_ratio = 0.0;           ///< largest edge ratio [-]
  double min_jacobian = 0.0;               ///< smallest corner Jacobian det [m^2]
  double min_characteristic_length = 0.0;  ///< smallest area / longest diagonal [m]
  double min_width = 0.0;                  ///< smallest area / longest edge [m]
  double min_edge = 0.0;                   ///< shortest element edge [m]
  double max_edge = 0.0;                   ///< longest element edge [m]
  double area = 0.0;                       ///< total (r, z) area [m^2]
  double volume = 0.0;                     ///< total axisymmetric volume [m^3]
};

/// Quality of the elements of `body` (all zeros when it has none).
MeshQuality mesh_quality(const Mesh& mesh, Body body);

/// Quality of element e of `mesh`.
QuadQuality element_quality(const Mesh& mesh, int e);

/// Largest subcycling level of the explicit-cost model: the solver's default [-].
constexpr int kCostLevels = SolverConfig{}.subcycling_levels;

/// Explicit cost of one body under element subcycling, from geometry alone (equal wave speeds):
/// an element of characteristic length L_e steps at 2^L times the base step, L =
/// subcycling_level(L_min, L_e, kCostLevels), L_min the model's shortest length.
struct ExplicitCost {
  std::array<int, kCostLevels + 1> elements_at_level{};  ///< element count of each level [-]
  double updates = 0.0;  ///< sum of 2^-L: element updates per base step [-]
};

/// Explicit cost of the elements of `body`, levels against `shortest` [m] (the smallest
/// characteristic length of the model, which sets the base step).
ExplicitCost explicit_cost(const Mesh& mesh, Body body, double shortest);

}  // namespace corlab::fem
