// The 3-D element pass (hex_element_loop.cpp) on a row of cubes, at every SIMD level this CPU
// runs: a rigid translation leaves no stress and no force, and its sums are the cubes' (the
// smallest volume, the stable step); an inverted element is named by its own index, not by its
// block's, in full blocks (the vector gather) and in the short last one.
// SPDX-License-Identifier: BSD-3-Clause
#include "fem/solver/hex_element_loop.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>

#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/kernels/stable_time_step.hpp"
#include "corlab/materials/material.hpp"

namespace corlab::fem::hex_solver {
namespace {

constexpr double kSide = 1e-3;  // cube side h [m]
constexpr double kDt = 1e-8;    // [s]

// Elastic steel [SI].
Material steel() {
  Material m;
  m.youngs_modulus = 210e9;
  m.poisson_ratio = 0.3;
  m.density = 7850.0;
  return m;
}

// n cubes of side kSide along x, one elastic steel body; node (i, j, k) at (i, j, k) h is node
// 4 i + 2 j + k, every node moving at velocity v [m/s].
struct CubeRow {
  SolverConfig solver;
  HexModel m;
  HexState s;

  CubeRow(int n, const double (&v)[3]) {
    const auto count = static_cast<std::size_t>(n);
    m.solver = &solver;
    m.bodies[static_cast<std::size_t>(Body::kSubstrate)] = body_material(steel());
    m.runs = {{0, count, Body::kSubstrate}};
    // The corners in hex8.hpp's order: (-,-,-), (+,-,-), (+,+,-), (-,+,-), then the same at +z.
    constexpr int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                   {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    for (int c = 0; c < 8; ++c) {
      auto& corner = m.corner[static_cast<std::size_t>(c)];
      for (int e = 0; e < n; ++e)
        corner.push_back(node(e + kCorner[c][0], kCorner[c][1], kCorner[c][2]));
    }
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; j < 2; ++j) {
        for (int k = 0; k < 2; ++k) {
          s.node.push_back({i * kSide, j * kSide, k * kSide, v[0], v[1], v[2]});
        }
      }
    }
    s.nodal_force.assign(s.node.size(), NodeForce{0.0, 0.0, 0.0});
    for (Vec& a : s.stress) a.assign(count, 0.0);
    s.eps_p.assign(count, 0.0);
    for (Vec& a : s.hourglass) a.assign(count, 0.0);
  }

  static int node(int i, int j, int k) { return 4 * i + 2 * j + k; }

  // The stable step of an undeformed cube with no volume change [s]: L_e = h / sqrt 3 and the
  // bulk viscosity's damping ratio xi = b1.
  double cube_step() const {
    return element_stable_time_step(kSide / std::sqrt(3.0), steel().dilatational_wave_speed(),
                                    solver.bulk_viscosity_linear);
  }
};

TEST(HexElementPass, ARigidTranslationLeavesNoStressAndNoForce) {
  // The rates sum v_I b_I of a uniform v vanish to round-off: bounded by 1e-12 of the stress a
  // strain increment |v| dt / h would give, and of that stress's force on a face.
  const double v[3] = {3.0, -2.0, 5.0};
  for (const SimdLevel level : supported_simd_levels()) {
    CubeRow row(40, v);
    const solver::ElementSums sums = hex_element_pass(level, row.m, row.s, kDt);
    const double stress = steel().youngs_modulus * 5.0 * kDt / kSide;  // |v| <= 5 m/s [Pa]
    const double force = stress * kSide * kSide;                       // [N]
    for (const Vec& a : row.s.stress) {
      for (const double x : a) ASSERT_LE(std::abs(x), 1e-12 * stress) << to_string(level);
    }
    for (const NodeForce& f : row.s.nodal_force) {
      ASSERT_LE(std::abs(f.x), 1e-12 * force) << to_string(level);
      ASSERT_LE(std::abs(f.y), 1e-12 * force) << to_string(level);
      ASSERT_LE(std::abs(f.z), 1e-12 * force) << to_string(level);
    }
    EXPECT_EQ(sums.bad_element, -1) << to_string(level);
    // The volume to round-off of coordinates up to 40 h.
    EXPECT_NEAR(sums.omega_min, kSide * kSide * kSide, 1e-13 * kSide * kSide * kSide)
        << to_string(level);
    EXPECT_NEAR(sums.dt_min, row.cube_step(), 1e-14 * row.cube_step()) << to_string(level);
    const double work = 40.0 * 1e-12 * stress * 5.0 * kDt / kSide * kSide * kSide * kSide;  // [J]
    EXPECT_LE(std::abs(sums.internal_work), work) << to_string(level);
    EXPECT_LE(std::abs(sums.hourglass_work), work) << to_string(level);
  }
}

TEST(HexElementPass, NamesTheInvertedElementNotItsBlock) {
  // 40 elements: blocks of 16, 16 and 8 lanes. Element `bad`'s far corner (+, +, +) is moved
  // 5 h back along x: the trilinear volume is linear in it, with dV/dx = h^2 / 4, so the cube's
  // volume becomes h^3 (1 - 5/4) < 0; the other element on that node (its corner (-, +, +))
  // grows.
  for (const SimdLevel level : supported_simd_levels()) {
    for (const int bad : {0, 13, 21, 39}) {
      CubeRow row(40, {0.0, 0.0, 0.0});
      row.s.node[static_cast<std::size_t>(CubeRow::node(bad + 1, 1, 1))].x -= 5.0 * kSide;
      const solver::ElementSums sums = hex_element_pass(level, row.m, row.s, kDt);
      EXPECT_EQ(sums.bad_element, bad) << to_string(level);
      EXPECT_NEAR(sums.omega_min, -0.25 * kSide * kSide * kSide, 1e-12 * kSide * kSide * kSide)
          << to_string(level);
    }
  }
}

}  // namespace
}  // namespace corlab::fem::hex_solver
