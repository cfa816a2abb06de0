// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file gmsh_hex_reader.hpp
/// Reads the 3-D model's half sphere from a Gmsh file (mesh.file with the 3-D model); the flat,
/// rigid or the deformable block, stays corlab's own (hex_mesh_generator.hpp), whose contact
/// search needs its tensor grid.
///
/// Required physical groups (by name): 3D "sphere" (8-node hexahedra only, Gmsh's node order,
/// which is hex8.hpp's), 2D "sphere_contact" (the surface that may touch: its nodes are the
/// contact's slaves) and 2D "symmetry" (the cut plane y = 0: v_y held at zero). The half y >= 0
/// of a sphere of radius `radius` centred on the z axis with its lowest point at the origin [m].

#include <filesystem>

#include "corlab/fem/mesh/hex_mesh.hpp"

namespace corlab::fem {

/// Reads `file` (.msh, or a .geo meshed in 3D on reading). The nodes of "sphere" are numbered
/// by increasing Gmsh tag. Throws InputError naming mesh.file when the file is unreadable, a
/// group is missing or holds other elements, an element is inverted, or the body is not that
/// half sphere (a node below y = 0, a "symmetry" node off it, the lowest node off z = 0, a height
/// other than 2 radius within 1 %); "gmsh support not built" without Gmsh.
HexMesh read_gmsh_hex_sphere(const std::filesystem::path& file, double radius);

}  // namespace corlab::fem
