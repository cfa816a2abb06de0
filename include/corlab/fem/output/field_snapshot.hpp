#pragma once
/// @file field_snapshot.hpp
/// The solver's fields at one instant, for VTU output (SimulationControl::on_fields).

#include <vector>

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

}  // namespace corlab::fem
