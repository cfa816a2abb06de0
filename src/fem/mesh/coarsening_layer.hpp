// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file coarsening_layer.hpp
/// Coarsening a structured grid by 3:1 transitions (docs/theory/mesh.md, "3:1 transitions"): a
/// grid's points are swept layer by layer (between grid lines j and j + 1), and in each layer
/// three intervals become one wherever the transition (MeshBuilder::transition) is well shaped.
/// Private to the mesh generator (src/fem/mesh).

#include <array>
#include <cstddef>
#include <vector>

#include "fem/mesh/block_geometry.hpp"
#include "fem/mesh/mesh_builder.hpp"

namespace corlab::fem::meshing {

/// Where coarsening_layer's transitions put their interior nodes.
enum class TransitionDepth {
  kHalfway,     ///< halfway across the layer (the plain template)
  kThickLayer,  ///< by thick_layer_depth (layers that outgrow the intervals they merge)
};

/// Whether the 3:1 transition from `fine` (f0 -> f3) to c0 -> c1 is as well shaped as the rest of
/// the mesh: all four elements convex with corners in [40, 140] deg, width (area / longest edge)
/// >= 0.7 of the narrowest fine interval or of h [m], whichever is larger (h: the mesh's contact
/// element size, for grids whose fine intervals may be narrower than it), and planar
/// Flanagan-Belytschko length (the stable step's) >= 1/sqrt(2) of the narrowest fine interval (a
/// square's), so that it never sets the explicit step. For equal fine intervals w and depth 1/2:
/// a layer about 2.1 to 2.4 w thick (45/135 deg at 2 w, but its coarse side's trapezoid then only
/// 0.67 w wide; 40 deg at 2.38 w).
bool well_shaped_transition(const std::array<Point, 4>& fine,
                            Point c0,
                            Point c1,
                            double h = 0.0,
                            double depth = kHalfwayDepth);

/// Where a thick layer's transition puts its interior nodes (transition_quads' `depth`): so far
/// across that the coarse side's quads are 1.12 mean fine intervals w high, as in a layer 2.24 w
/// thick (the middle of the plain template's window, whose coarse half may be 1.05 to 1.19 w),
/// the fine side's quads taking the rest of the layer as the plain elements beside them do;
/// halfway in layers up to 2.24 w thick. For equal fine intervals well shaped at any thickness
/// from about 2.1 w (the plain template only up to 2.38 w, which a layer growing by 1.15 per step
/// can step over). Fine intervals graded by more than about 1.06 per interval fail it (the first
/// one's corner at c0, atan(w_first / 1.12 w_mean), falls below 40 deg): they merge only in the
/// plain template's window.
double thick_layer_depth(const std::array<Point, 4>& fine, Point c0, Point c1);

/// One layer of elements between grid lines j and j + 1 across the grid's intervals between the
/// indices `edges` (point(i, j) is grid point i of line j): from the first edge on, three
/// intervals become one through a 3:1 transition where it is well shaped (well_shaped_transition
/// with h [m]; its interior nodes halfway, or for TransitionDepth::kThickLayer placed by
/// thick_layer_depth) and its coarse interval is at most `max_size` [m]; the others cross as plain
/// quads. Returns the edges on line j + 1.
template <typename Grid>
std::vector<std::size_t> coarsening_layer(MeshBuilder& builder,
                                          const std::vector<std::size_t>& edges,
                                          std::size_t j,
                                          double max_size,
                                          Grid point,
                                          double h = 0.0,
                                          TransitionDepth placement = TransitionDepth::kHalfway) {
  std::vector<std::size_t> next{edges.front()};
  std::size_t k = 0;
  while (k + 1 < edges.size()) {
    bool merge = k + 3 < edges.size();
    if (merge) {
      const std::array<Point, 4> fine{point(edges[k], j), point(edges[k + 1], j),
                                      point(edges[k + 2], j), point(edges[k + 3], j)};
      const Point c0 = point(edges[k], j + 1);
      const Point c1 = point(edges[k + 3], j + 1);
      const double depth = placement == TransitionDepth::kThickLayer
                               ? thick_layer_depth(fine, c0, c1)
                               : kHalfwayDepth;
      merge = norm(c1 - c0) <= max_size && well_shaped_transition(fine, c0, c1, h, depth);
      if (merge) builder.transition(fine, c0, c1, depth);
    }
    if (!merge) {
      builder.quad({point(edges[k], j), point(edges[k + 1], j), point(edges[k + 1], j + 1),
                    point(edges[k], j + 1)});
    }
    k += merge ? 3 : 1;
    next.push_back(edges[k]);
  }
  return next;
}

/// The indices 0, 1, ..., n.
std::vector<std::size_t> all_edges(std::size_t n);

}  // namespace corlab::fem::meshing
