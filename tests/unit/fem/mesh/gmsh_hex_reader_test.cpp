// The 3-D model's half sphere from a Gmsh file (gmsh_hex_reader.hpp): corlab's own sphere written
// as MSH 2.2 reads back node for node and gives the built-in run's result; a file that is not
// the half sphere is refused with the one-line error.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/mesh/gmsh_hex_reader.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "corlab/core/error.hpp"
#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/mesh/gmsh_reader.hpp"
#include "corlab/fem/mesh/hex_mesh_generator.hpp"
#include "corlab/fem/solver/simulate.hpp"
#include "support/hex_cases.hpp"
#include "support/scratch_files.hpp"

namespace corlab::fem {
namespace {

// The sphere's hexahedra's faces whose four nodes all lie in `nodes` (each face once), as Gmsh
// quads.
std::vector<std::array<int, 4>> faces_within(const HexMesh& m, const std::vector<int>& nodes) {
  constexpr int kFace[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                               {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  const std::set<int> in(nodes.begin(), nodes.end());
  std::set<std::array<int, 4>> seen;
  std::vector<std::array<int, 4>> faces;
  for (std::size_t e = 0; e < m.hexes.size(); ++e)
    for (const auto& f : kFace) {
      if (m.element_body[e] != Body::kSphere) break;
      std::array<int, 4> q{};
      for (int k = 0; k < 4; ++k) q[k] = m.hexes[e][static_cast<std::size_t>(f[k])];
      if (!std::all_of(q.begin(), q.end(), [&](int n) { return in.count(n) != 0; })) continue;
      std::array<int, 4> key = q;
      std::sort(key.begin(), key.end());
      if (seen.insert(key).second) faces.push_back(q);
    }
  return faces;
}

// The sphere of `m` (its Body::kSphere part) as an MSH 2.2 file: physical 3D "sphere", 2D
// "sphere_contact" and "symmetry". `element_type` 5 writes hexahedra; `first_hex` replaces the
// first element's line (a damaged element).
std::filesystem::path write_msh(const std::string& name,
                                const HexMesh& m,
                                const std::string& first_hex = "") {
  std::string text = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n3\n";
  text += "3 1 \"sphere\"\n2 2 \"sphere_contact\"\n2 3 \"symmetry\"\n$EndPhysicalNames\n";
  std::size_t nodes = 0;
  while (nodes < m.node_body.size() && m.node_body[nodes] == Body::kSphere) ++nodes;
  text += fmt::format("$Nodes\n{}\n", nodes);
  for (std::size_t n = 0; n < nodes; ++n)
    text += fmt::format("{} {:.17g} {:.17g} {:.17g}\n", n + 1, m.x[n], m.y[n], m.z[n]);
  text += "$EndNodes\n";
  std::vector<std::string> elements;
  for (std::size_t e = 0; e < m.hexes.size(); ++e) {
    if (m.element_body[e] != Body::kSphere) continue;
    std::string line = "5 2 1 1";
    for (const int n : m.hexes[e]) line += fmt::format(" {}", n + 1);
    elements.push_back(line);
  }
  if (!first_hex.empty()) elements.front() = first_hex;
  for (const auto& [physical, set] :
       {std::pair{2, &m.sphere_surface_nodes}, std::pair{3, &m.symmetry_nodes}})
    for (const auto& q : faces_within(m, *set))
      elements.push_back(fmt::format("3 2 {} {} {} {} {} {}", physical, physical, q[0] + 1,
                                     q[1] + 1, q[2] + 1, q[3] + 1));
  text += fmt::format("$Elements\n{}\n", elements.size());
  for (std::size_t k = 0; k < elements.size(); ++k)
    text += fmt::format("{} {}\n", k + 1, elements[k]);
  text += "$EndElements\n";
  const auto path = test::fresh_dir(name) / name;  // one folder per file: all stay readable
  test::spit(path, text);
  return path;
}

using test::sliding_on_rigid_flat;

std::vector<int> sorted(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  return v;
}

TEST(GmshHexReader, ReadsCorlabsOwnSphereBack) {
  if (!gmsh_available()) GTEST_SKIP() << "built without gmsh";
  const ImpactConfig c = sliding_on_rigid_flat();
  const HexMesh built = build_hex_impact_mesh(c);
  const HexMesh read = read_gmsh_hex_sphere(write_msh("sphere.msh", built), c.sphere.radius);
  EXPECT_EQ(read.x, built.x);
  EXPECT_EQ(read.y, built.y);
  EXPECT_EQ(read.z, built.z);
  EXPECT_EQ(read.hexes, built.hexes);
  EXPECT_EQ(read.sphere_surface_nodes, sorted(built.sphere_surface_nodes));
  EXPECT_EQ(read.symmetry_nodes, sorted(built.symmetry_nodes));
}

// mesh.file takes the sphere; the deformable flat's block is appended as for the built-in one.
TEST(GmshHexReader, GivesTheBuiltInRunAndBlock) {
  if (!gmsh_available()) GTEST_SKIP() << "built without gmsh";
  ImpactConfig c = sliding_on_rigid_flat();
  const ImpactResult built = simulate(c);
  c.mesh.file = write_msh("run.msh", build_hex_impact_mesh(c));
  validate(c);
  const ImpactResult read = simulate(c);
  ASSERT_EQ(read.status, RunStatus::kSeparated);
  EXPECT_EQ(read.e_n, built.e_n);
  EXPECT_EQ(read.e_t, built.e_t);
  EXPECT_EQ(read.omega, built.omega);
  EXPECT_EQ(read.steps, built.steps);
  c.substrate.shape = SubstrateShape::kFlat;  // E* and so the sphere's mesh change
  c.mesh.file.clear();
  const HexMesh generated = build_hex_impact_mesh(c);
  c.mesh.file = write_msh("block.msh", generated);
  const HexMesh with_block = build_hex_impact_mesh(c);
  EXPECT_EQ(with_block.x, generated.x);
  EXPECT_EQ(with_block.hexes, generated.hexes);
  EXPECT_EQ(with_block.top_faces, generated.top_faces);
  EXPECT_EQ(with_block.base_nodes, generated.base_nodes);
}

std::string refusal(const std::filesystem::path& file, double radius) {
  try {
    (void)read_gmsh_hex_sphere(file, radius);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(GmshHexReader, RefusesWhatIsNotTheHalfSphere) {
  if (!gmsh_available()) GTEST_SKIP() << "built without gmsh";
  const ImpactConfig c = sliding_on_rigid_flat();
  const double r = c.sphere.radius;
  const HexMesh built = build_hex_impact_mesh(c);
  const auto& hex = built.hexes.front();
  auto expect = [&](const std::filesystem::path& file, double radius, const std::string& what) {
    const std::string message = refusal(file, radius);
    EXPECT_NE(message.find(what), std::string::npos) << message;
    EXPECT_EQ(message.rfind("invalid mesh.file = " + file.string() + ": ", 0), 0u) << message;
  };
  const auto good = write_msh("good.msh", built);
  expect(good, 2.0 * r, "sphere.radius = 0.07 m asks for 0.14 m");
  const std::string inverted =
      fmt::format("5 2 1 1 {} {} {} {} {} {} {} {}", hex[4] + 1, hex[5] + 1, hex[6] + 1, hex[7] + 1,
                  hex[0] + 1, hex[1] + 1, hex[2] + 1, hex[3] + 1);
  expect(write_msh("inverted.msh", built, inverted), r, "hexahedron 1 of \"sphere\" is inverted");
  const std::string tetra =
      fmt::format("4 2 1 1 {} {} {} {}", hex[0] + 1, hex[1] + 1, hex[3] + 1, hex[4] + 1);
  expect(write_msh("tetra.msh", built, tetra), r, "only 8-node hexahedra are supported");
  HexMesh lifted = built;
  for (double& z : lifted.z) z += 1e-3;
  expect(write_msh("lifted.msh", lifted), r, "it must touch the flat at z = 0");
  HexMesh mirrored = built;
  for (double& y : mirrored.y) y = -y;
  expect(write_msh("mirrored.msh", mirrored), r, "the 3-D model is the half y >= 0");
  HexMesh no_symmetry = built;
  no_symmetry.symmetry_nodes.clear();
  expect(write_msh("no_symmetry.msh", no_symmetry), r, "physical group \"symmetry\"");
}

}  // namespace
}  // namespace corlab::fem
