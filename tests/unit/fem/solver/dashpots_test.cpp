// The absorbing far boundary's dashpots of both models (dashpots.hpp): none on the fixed default,
// and summed over the nodes, each axis gets rho c_p x the far area normal to it plus rho c_s x
// the far area along it; the base is then free.
// SPDX-License-Identifier: BSD-3-Clause
#include "fem/solver/dashpots.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "corlab/core/units.hpp"
#include "corlab/fem/mesh/hex_mesh_generator.hpp"
#include "corlab/fem/mesh/mesh_generator.hpp"
#include "fem/solver/impact_model.hpp"

namespace corlab::fem {
namespace {

ImpactConfig small_flat(SubstrateBoundary boundary) {
  ImpactConfig c;
  c.sphere.radius = 2.5e-3;
  c.substrate.radius = 4e-3;
  c.substrate.depth = 3e-3;
  c.substrate.boundary = boundary;
  c.mesh.h_min = 0.1e-3;
  c.mesh.h_max = 0.5e-3;
  return c;
}

BoundaryImpedance impedance(const ImpactConfig& c) {
  const Material& s = c.substrate.material;
  return lysmer_impedance(s.density, s.p_wave_modulus(), s.shear_modulus());
}

template <std::size_t D>
std::array<double, D> sums(const solver::Dashpots<D>& d) {
  std::array<double, D> s{};
  for (const auto& c : d.c)
    for (std::size_t a = 0; a < D; ++a) s[a] += c[a];
  return s;
}

TEST(Dashpots, NoneOnTheFixedDefault) {
  const ImpactConfig c = small_flat(SubstrateBoundary::kFixed);
  const Mesh mesh = build_impact_mesh(c);
  EXPECT_TRUE(
      solver::axisymmetric_dashpots(c, mesh, std::vector<double>(mesh.quads.size(), 1.0)).empty());
  const solver::ImpactModel m = solver::make_impact_model(c, mesh);
  EXPECT_TRUE(m.dashpots.empty());
  for (const int n : mesh.base_nodes) EXPECT_EQ(m.free_z[static_cast<std::size_t>(n)], 0.0);
}

TEST(Dashpots, AxisymmetricSumsAreTheImpedancesTimesTheFarAreas) {
  const ImpactConfig c = small_flat(SubstrateBoundary::kAbsorbing);
  const Mesh mesh = build_impact_mesh(c);
  const solver::ImpactModel m = solver::make_impact_model(c, mesh);
  ASSERT_FALSE(m.dashpots.empty());
  const BoundaryImpedance z = impedance(c);
  const double w = c.substrate.radius;
  const double side = 2.0 * units::kPi * w * c.substrate.depth;  // [m^2]
  const double base = units::kPi * w * w;
  const auto s = sums(m.dashpots);
  EXPECT_NEAR(s[0], z.normal * side + z.shear * base, 1e-9 * s[0]);
  EXPECT_NEAR(s[1], z.shear * side + z.normal * base, 1e-9 * s[1]);
  for (const int n : mesh.base_nodes) EXPECT_EQ(m.free_z[static_cast<std::size_t>(n)], 1.0);
  for (const auto& k : m.dashpots.k) EXPECT_EQ(k, (std::array<double, 2>{0.0, 0.0}));
}

TEST(Dashpots, ViscousSpringAddsSpringsOfAlphaGOverTheDistance) {
  const ImpactConfig c = small_flat(SubstrateBoundary::kViscousSpring);
  const Mesh mesh = build_impact_mesh(c);
  const solver::ImpactModel m = solver::make_impact_model(c, mesh);
  const ImpactConfig dashpots_only = small_flat(SubstrateBoundary::kAbsorbing);
  const solver::ImpactModel d = solver::make_impact_model(dashpots_only, mesh);
  ASSERT_EQ(m.dashpots.node, d.dashpots.node);
  EXPECT_EQ(m.dashpots.c, d.dashpots.c);  // the same dashpots
  // The spring over the dashpot is alpha G / (rho c) / distance, per axis as the dashpot's.
  const Material& s = c.substrate.material;
  const BoundaryImpedance z = impedance(c);
  for (std::size_t j = 0; j < m.dashpots.node.size(); ++j) {
    const auto n = static_cast<std::size_t>(m.dashpots.node[j]);
    const double distance = std::hypot(mesh.r[n], mesh.z[n]);
    const BoundaryStiffness k = spring_stiffness(s.shear_modulus(), distance);
    // A node on one face only: the base's nodes off the side (r < W), the side's above the base.
    if (mesh.r[n] < c.substrate.radius && mesh.z[n] == -c.substrate.depth) {
      EXPECT_NEAR(m.dashpots.k[j][1] / m.dashpots.c[j][1], k.normal / z.normal,
                  1e-9 * k.normal / z.normal);
      EXPECT_NEAR(m.dashpots.k[j][0] / m.dashpots.c[j][0], k.shear / z.shear,
                  1e-9 * k.shear / z.shear);
    }
  }
}

TEST(Dashpots, HexSumsAreTheImpedancesTimesTheFarAreas) {
  ImpactConfig c = small_flat(SubstrateBoundary::kAbsorbing);
  c.solver.model = SolverModel::kThreeD;
  c.mesh.contact_elements = 0.0;
  const solver::Dashpots<3> d = solver::hex_dashpots(c, build_hex_impact_mesh(c));
  const BoundaryImpedance z = impedance(c);
  const double w = c.substrate.radius;
  const double depth = c.substrate.depth;
  const double x_faces = 2.0 * w * depth;  // x = -w and x = w [m^2]
  const double y_face = 2.0 * w * depth;   // y = w
  const double base = 2.0 * w * w;
  const auto s = sums(d);
  EXPECT_NEAR(s[0], z.normal * x_faces + z.shear * (y_face + base), 1e-9 * s[0]);
  EXPECT_NEAR(s[1], z.normal * y_face + z.shear * (x_faces + base), 1e-9 * s[1]);
  EXPECT_NEAR(s[2], z.normal * base + z.shear * (x_faces + y_face), 1e-9 * s[2]);
}

}  // namespace
}  // namespace corlab::fem
