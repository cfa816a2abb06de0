// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file dem_walls.hpp
/// The walls of a DEM export: planes at any position and orientation and cylinders, each of one
/// wall material, as `corlab dem --wall [LABEL=]MATERIAL[@SHAPE]` gives them. Each code writes
/// them with its own primitives (LAMMPS region + fix wall/gran/region; LIGGGHTS primitive walls,
/// a mesh for an oblique plane; YADE utils.wall, facets).
#include <array>
#include <string>
#include <string_view>

namespace corlab::dem {

enum class WallShape { plane, cylinder };

/// One wall. A plane bounds the half-space its normal points into (the particles' side); a
/// cylinder holds the particles inside it.
struct Wall {
  WallShape shape = WallShape::plane;
  std::array<double, 3> point{0.0, 0.0, 0.0};   ///< plane: a point of it [m]
  std::array<double, 3> normal{0.0, 0.0, 1.0};  ///< plane: unit normal into the particles [-]
  /// Plane: half-width [m] of the square (centred on `point`) that LIGGGHTS's mesh and YADE's
  /// facets make of an oblique plane (0: axis-aligned, infinite in every code).
  double half_width = 0.0;
  int axis = 2;                            ///< cylinder: its axis, 0 = x, 1 = y, 2 = z
  std::array<double, 2> centre{0.0, 0.0};  ///< cylinder: the axis in the other two coordinates [m]
  double radius = 0.0;                     ///< cylinder radius [m]
  double lo = 0.0;                         ///< cylinder: lower end along its axis [m]
  double hi = 0.0;                         ///< cylinder: upper end along its axis [m]
  int material = 0;                        ///< wall material (0: ExportSpec::wall, k: extra_walls)
};

/// Parses a wall's SHAPE (InputError naming `wall shape`, exit 2 in the CLI):
///   plane:PX,PY,PZ,NX,NY,NZ[,HALF]  a point [m], the normal into the particles (normalised;
///                                   not zero), HALF [m] > 0 required when the normal is not
///                                   along x, y or z (the square of LIGGGHTS's and YADE's facets)
///   cylinder:AXIS,C1,C2,R,LO,HI     AXIS x|y|z, the axis at (C1, C2) [m], radius R > 0 [m],
///                                   the particles inside, from LO to HI > LO [m] along it
///   floor                           plane:0,0,0,0,0,1 (the default)
Wall parse_wall_shape(std::string_view text);

/// The axis (0, 1, 2) a plane's normal lies along, or -1 for an oblique plane.
int plane_axis(const Wall& wall);

/// The corners [m] of an oblique plane's square (half-width `half_width` about `point`), in
/// order around it, the normal by the right-hand rule.
std::array<std::array<double, 3>, 4> plane_square(const Wall& wall);

/// An ASCII STL of an oblique plane's square (two triangles): LIGGGHTS's mesh of that wall.
std::string wall_stl(const Wall& wall);

}  // namespace corlab::dem
