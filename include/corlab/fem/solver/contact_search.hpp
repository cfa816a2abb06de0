// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file contact_search.hpp
/// Closest-segment search of one slave node on the master polyline (the substrate surface,
/// nodes ordered by increasing r), started from the segment found at the previous step. The
/// contact zone moves by much less than one segment per step, so the search walks at most a few
/// segments: O(1) per slave and step, no spatial sort (a "cursor" search, as in one-pass
/// node-to-segment contact; Hallquist, Goudreau & Benson 1985).

#include <span>

#include "corlab/fem/kernels/penalty_contact.hpp"

namespace corlab::fem {

/// The slave is taken off the end of the master surface when it projects beyond the last
/// segment's far node by more than this fraction of that segment [-] (round-off guard).
inline constexpr double kContactEndTolerance = 1e-9;

/// Result of the search for one slave: the segment and the projection on it.
struct ContactCandidate {
  int segment = 0;  ///< index of the master segment masters[s] -> masters[s + 1]
  SegmentProjection projection;
  bool active = false;  ///< penetrating (gap < 0) and on the master surface
};

/// Walks from `segment` to the segment the slave (rs, zs) [m] projects on; `r`, `z` [m] are the
/// nodal coordinates, `masters` the master node indices (>= 2). A slave between two segments'
/// projections (a convex corner) stays on the current one. The projection parameter of an
/// active candidate is clamped to [0, 1].
inline ContactCandidate find_contact(const double* r,
                                     const double* z,
                                     std::span<const int> masters,
                                     double rs,
                                     double zs,
                                     int segment) {
  const int n_seg = static_cast<int>(masters.size()) - 1;
  auto project = [&](int s) {
    const int a = masters[static_cast<std::size_t>(s)];
    const int b = masters[static_cast<std::size_t>(s) + 1];
    return project_on_segment(rs, zs, r[a], z[a], r[b], z[b]);
  };
  int seg = segment;
  SegmentProjection p;
  while (true) {
    p = project(seg);
    if (p.xi < 0.0 && seg > 0 && project(seg - 1).xi <= 1.0) {
      --seg;
      continue;
    }
    if (p.xi > 1.0 && seg < n_seg - 1 && project(seg + 1).xi >= 0.0) {
      ++seg;
      continue;
    }
    break;
  }
  ContactCandidate c{seg, p, false};
  const bool off_the_end = p.xi > 1.0 + kContactEndTolerance && seg == n_seg - 1;
  if (p.gap < 0.0 && !off_the_end) {
    c.active = true;
    c.projection.xi = p.xi < 0.0 ? 0.0 : (p.xi > 1.0 ? 1.0 : p.xi);
  }
  return c;
}

/// The segment under radius `rs` [m] on the undeformed surface (the search's starting cursor).
inline int initial_segment(const double* r, std::span<const int> masters, double rs) {
  const int n_seg = static_cast<int>(masters.size()) - 1;
  int seg = 0;
  while (seg < n_seg - 1 && r[masters[static_cast<std::size_t>(seg) + 1]] < rs) ++seg;
  return seg;
}

}  // namespace corlab::fem
