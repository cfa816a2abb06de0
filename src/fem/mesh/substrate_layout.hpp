// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file substrate_layout.hpp
/// The substrate's mesh (docs/theory/mesh.md, "Substrate"): a tensor grid or three blocks around
/// the uniform zone, whichever is cheaper to integrate. Private to the mesh generator
/// (src/fem/mesh).

#include "corlab/fem/mesh/mesh.hpp"
#include "corlab/fem/mesh/mesh_generator.hpp"
#include "fem/mesh/mesh_builder.hpp"

namespace corlab::fem::meshing {

/// Substrate: the three blocks around the zone as given when they are well shaped; else, of the
/// three blocks around a zone as deep as it is wide (uniform h deeper than asked, but the
/// elements grow in both directions away from it: cheaper for small contacts) and the tensor
/// grid of the zone as given, the cheaper to integrate (explicit_cost of the plain tensor grid,
/// whose fine columns and rows run on to the base and to r = W). With o.transitions the tensor
/// grid is built with 3:1 transitions that merge those fine columns and rows on the way
/// (docs/theory/mesh.md, "Substrate"). Adds them as Body::kSubstrate and sets
/// mesh.substrate_surface_nodes and mesh.base_nodes (both from the axis outwards).
void generate_substrate(const MeshOptions& o, MeshBuilder& builder, Mesh& mesh);

}  // namespace corlab::fem::meshing
