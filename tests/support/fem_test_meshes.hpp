// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Small meshes for the solver's unit tests (the impact mesh generator is tested elsewhere).
#include <cmath>
#include <vector>

#include "corlab/fem/mesh/mesh.hpp"

namespace corlab::fem::testing {

/// Structured nr x nz block of quads on [r0, r0 + w] x [z0, z0 + h], counter-clockwise, appended
/// to `mesh` as `body`. Returns the index of its first node; node (i, j) is first + j (nr+1) + i.
inline int add_block(
    Mesh& mesh, Body body, double r0, double z0, double w, double h, int nr, int nz) {
  const int first = mesh.num_nodes();
  for (int j = 0; j <= nz; ++j) {
    for (int i = 0; i <= nr; ++i) {
      mesh.r.push_back(r0 + w * i / nr);
      mesh.z.push_back(z0 + h * j / nz);
      mesh.node_body.push_back(body);
    }
  }
  for (int j = 0; j < nz; ++j) {
    for (int i = 0; i < nr; ++i) {
      const int a = first + j * (nr + 1) + i;
      mesh.quads.push_back({a, a + 1, a + nr + 2, a + nr + 1});
      mesh.element_body.push_back(body);
    }
  }
  return first;
}

/// A flat-ended cylinder ("sphere" body, radius w, height h_s) touching a cylindrical substrate
/// (radius W, depth D) at z = gap: every node set of mesh.hpp filled in. Small and fast.
inline Mesh punch_mesh(double w, double h_s, double big_w, double depth, double gap, int n) {
  Mesh m;
  const int nr_sub = 2 * n;
  const int sub = add_block(m, Body::kSubstrate, 0.0, -depth, big_w, depth, nr_sub, n);
  const int sph = add_block(m, Body::kSphere, 0.0, gap, w, h_s, n, n);
  for (int j = 0; j <= n; ++j) {
    m.axis_nodes.push_back(sub + j * (nr_sub + 1));
    m.axis_nodes.push_back(sph + j * (n + 1));
  }
  for (int i = 0; i <= nr_sub; ++i) {
    m.base_nodes.push_back(sub + i);
    m.substrate_surface_nodes.push_back(sub + n * (nr_sub + 1) + i);
  }
  for (int i = 0; i <= n; ++i) m.sphere_surface_nodes.push_back(sph + i);
  return m;
}

}  // namespace corlab::fem::testing
