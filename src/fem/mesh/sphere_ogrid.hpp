// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file sphere_ogrid.hpp
/// The sphere's multi-block O-grid (docs/theory/mesh.md, "Sphere: multi-block O-grid"): bottom,
/// right and top ring blocks around a curved core; with MeshOptions::transitions the bottom
/// ring's columns merge 3:1 below the refined depth. Private to the mesh generator
/// (src/fem/mesh).

#include "corlab/fem/mesh/mesh.hpp"
#include "corlab/fem/mesh/mesh_generator.hpp"
#include "fem/mesh/mesh_builder.hpp"

namespace corlab::fem::meshing {

/// Adds the sphere's blocks (bottom, right, top, core) as Body::kSphere and sets
/// mesh.sphere_surface_nodes: from the lowest point up to the first node past the equator.
void generate_sphere(const MeshOptions& o, MeshBuilder& builder, Mesh& mesh);

/// The O-grid's elements without transitions (each block a full tensor grid), from its 1-D
/// distributions alone (no node is built): an upper bound of generate_sphere's count [-].
double sphere_block_elements(const MeshOptions& o);

}  // namespace corlab::fem::meshing
