// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file gmsh_reader.hpp
/// Reads an axisymmetric two-body quad mesh from a Gmsh file (via the Gmsh C++ API).
///
/// Required physical groups (by name): 2D "sphere" and "substrate" (quadrilaterals only), 1D
/// "axis" (r = 0), "base" (fixed bottom), "sphere_contact" (sphere surface that may touch) and
/// "substrate_contact" (substrate top surface). Coordinates: x = r [m], y = z [m].

#include <filesystem>

#include "corlab/fem/mesh/mesh.hpp"

namespace corlab::fem {

/// Whether corlab was built with Gmsh support (CORLAB_WITH_GMSH).
bool gmsh_available();

/// Reads `file` (.msh or .geo, meshed in 2D when no mesh is stored). Throws InputError when the
/// file is missing or unreadable, a physical group is missing (naming it), a 2D group holds
/// anything but quadrilaterals, or Gmsh support is not built ("gmsh support not built").
Mesh read_gmsh(const std::filesystem::path& file);

}  // namespace corlab::fem
