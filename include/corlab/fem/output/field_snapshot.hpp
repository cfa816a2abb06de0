// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file field_snapshot.hpp
/// The solvers' fields at one instant, for VTU output (SimulationControl::on_fields for the
/// axisymmetric model, on_hex_fields for the 3-D one).

#include <vector>

#include "corlab/fem/mesh/hex_mesh.hpp"
#include "corlab/fem/mesh/mesh.hpp"

namespace corlab::fem {

struct FieldSnapshot {
  double time = 0.0;  ///< t [s], 0 = release at the gap
  /// The mesh in its current (deformed) configuration; connectivity, bodies and node sets as in
  /// the input mesh (the sphere starts translated down by the gap: it touches at t = gap / v).
  Mesh mesh;
  std::vector<double> displacement_r;  ///< per node, from the input mesh [m]
  std::vector<double> displacement_z;  ///< per node, from the input mesh [m]
  std::vector<double> velocity_r;      ///< per node [m/s]
  std::vector<double> velocity_z;      ///< per node [m/s]
  std::vector<double> von_mises;       ///< per element [Pa]
  std::vector<double> pressure;        ///< per element, -trace(sigma)/3 [Pa]
  std::vector<double> plastic_strain;  ///< per element, equivalent plastic strain [-]
};

/// The 3-D model's fields at one instant (the half model y >= 0). Vectors are per node, three
/// components (x, y, z) interleaved.
struct HexFieldSnapshot {
  double time = 0.0;  ///< t [s], 0 = release at the gap, as FieldSnapshot
  /// The half model in its current (deformed) configuration; connectivity, bodies and node sets as
  /// generated.
  HexMesh mesh;
  std::vector<double> displacement;    ///< per node, from the generated mesh [m]
  std::vector<double> velocity;        ///< per node [m/s]
  std::vector<double> von_mises;       ///< per element [Pa]
  std::vector<double> pressure;        ///< per element, -trace(sigma)/3 [Pa]
  std::vector<double> plastic_strain;  ///< per element, equivalent plastic strain [-]
};

}  // namespace corlab::fem
