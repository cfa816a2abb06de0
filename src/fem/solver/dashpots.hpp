// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file dashpots.hpp
/// The absorbing far boundary of a run (substrate.boundary absorbing or viscous_spring; solver.md,
/// "Far boundary"): the Lysmer-Kuhlemeyer dashpots of absorbing_boundary.hpp lumped to the
/// substrate's far nodes (far_boundary.hpp), and their forces, for both models. Private to
/// src/fem/solver.

#include <array>
#include <cstddef>
#include <vector>

#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/kernels/absorbing_boundary.hpp"
#include "corlab/fem/mesh/hex_mesh.hpp"
#include "corlab/fem/mesh/mesh.hpp"

namespace corlab::fem::solver {

/// The dashpots of a model whose nodes have D velocity components.
template <std::size_t D>
struct Dashpots {
  std::vector<int> node;                 ///< the far nodes, increasing
  std::vector<std::array<double, D>> c;  ///< each one's coefficient per axis [N s/m]
  std::vector<std::array<double, D>> k;  ///< the viscous-spring boundary's springs [N/m] (or 0)

  bool empty() const { return node.empty(); }
};

/// Whether the config's far faces absorb (substrate.boundary other than fixed, on the flat).
inline bool absorbing_boundary(const ImpactConfig& config) {
  return config.substrate.shape == SubstrateShape::kFlat &&
         config.substrate.boundary != SubstrateBoundary::kFixed;
}

/// What the far boundary did over a step [J].
struct BoundaryWork {
  double absorbed = 0.0;  ///< the dashpots' work over the step
  double stored = 0.0;    ///< the springs' energy now
};

/// The axisymmetric model's dashpots (none unless absorbing_boundary(config)): the far segments'
/// ring areas x the substrate's impedances x `impedance_scale[e]` of the element e (mesh index)
/// each bounds (mass scaling's step scale: the scaled body's impedance is that times rho c).
Dashpots<2> axisymmetric_dashpots(const ImpactConfig& config,
                                  const Mesh& mesh,
                                  const std::vector<double>& impedance_scale);

/// The 3-D model's dashpots on its half block's far faces (none unless absorbing_boundary with
/// the boundary hex_resolution() gives: the key's, or the model's default block's).
Dashpots<3> hex_dashpots(const ImpactConfig& config, const HexMesh& mesh);

/// Adds each dashpot's force at the velocities `v(node, axis)` [m/s] and each spring's at the
/// displacements `u(node, axis)` [m] to `f(node, axis)` [N], weighted by `weight(node)` (0: not
/// due; subcycling's 2^L: the impulse of the node's own step); returns the dashpots' work over
/// the step dt [s] and the springs' energy now (all nodes).
template <std::size_t D, class Weight, class Velocity, class Displacement, class Force>
BoundaryWork apply_dashpots(
    const Dashpots<D>& d, double dt, Weight weight, Velocity v, Displacement u, Force f) {
  BoundaryWork work;
  for (std::size_t j = 0; j < d.node.size(); ++j) {
    const int n = d.node[j];
    const double w = weight(n);
    for (std::size_t a = 0; a < D; ++a) {
      const double ua = u(n, a);
      work.stored += 0.5 * d.k[j][a] * ua * ua;
      if (w == 0.0) continue;
      const double va = v(n, a);
      f(n, a) += w * (dashpot_force(d.c[j][a], va) - d.k[j][a] * ua);
      work.absorbed += w * dashpot_work(d.c[j][a], va, dt);
    }
  }
  return work;
}

}  // namespace corlab::fem::solver
