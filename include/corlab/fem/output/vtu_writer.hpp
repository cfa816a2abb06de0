// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file vtu_writer.hpp
/// VTK XML unstructured-grid (.vtu, ASCII) output of the meshes for ParaView: the axisymmetric
/// mesh with points (r, z, 0) [m] and VTK_QUAD cells (type 9), the 3-D half model with points
/// (x, y, z) [m] and VTK_HEXAHEDRON cells (type 12, the same node order as hex8.hpp).

#include <filesystem>
#include <string>
#include <vector>

#include "corlab/fem/mesh/hex_mesh.hpp"
#include "corlab/fem/mesh/mesh.hpp"
#include "corlab/fem/output/field_snapshot.hpp"

namespace corlab::fem {

/// One named data array: `components` values per point or per cell, interleaved.
struct VtuField {
  std::string name;            ///< array name shown in ParaView
  int components = 1;          ///< values per entity (1 = scalar, 3 = vector)
  std::vector<double> values;  ///< size = components x (num_nodes or num_elements)
};

/// Writes `mesh` with point and cell fields; a cell field "body" (0 = sphere, 1 = substrate) is
/// always added. Throws InputError when a field has the wrong size or the file cannot be written.
void write_vtu(const std::filesystem::path& file,
               const Mesh& mesh,
               const std::vector<VtuField>& point_fields = {},
               const std::vector<VtuField>& cell_fields = {});

/// The same for the 3-D half model.
void write_vtu(const std::filesystem::path& file,
               const HexMesh& mesh,
               const std::vector<VtuField>& point_fields = {},
               const std::vector<VtuField>& cell_fields = {});

/// Writes a solver snapshot: point fields "displacement" and "velocity" (3 components r, z, 0)
/// [m], [m/s]; cell fields "von_mises" [Pa], "pressure" [Pa], "plastic_strain" [-] and "body".
/// Empty snapshot vectors are skipped.
void write_vtu(const std::filesystem::path& file, const FieldSnapshot& snapshot);

/// The same for the 3-D half model: "displacement" and "velocity" with components (x, y, z).
void write_vtu(const std::filesystem::path& file, const HexFieldSnapshot& snapshot);

}  // namespace corlab::fem
