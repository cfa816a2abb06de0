// Gmsh mesh input (gmsh_reader.hpp) on data/meshes/example_impact.{geo,msh}.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/mesh/gmsh_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <regex>
#include <string>

#include "corlab/core/error.hpp"
#include "corlab/fem/mesh/mesh_quality.hpp"
#include "support/scratch_files.hpp"

namespace corlab::fem {
namespace {

const std::filesystem::path kMeshDir = std::filesystem::path(CORLAB_DATA_DIR) / "meshes";

using test::slurp;

/// Writes a variant of the example .geo into the build tree and returns its path.
std::filesystem::path geo_variant(const std::string& name,
                                  const std::string& from,
                                  const std::string& to) {
  std::string text = slurp(kMeshDir / "example_impact.geo");
  text = std::regex_replace(text, std::regex(from), to);
  const auto dir = std::filesystem::path(CORLAB_BINARY_DIR) / "test_output" / "gmsh_reader";
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  test::spit(path, text);
  return path;
}

void check_example(const Mesh& m) {
  // 4 sphere blocks of 12 x 6 and 12 x 12 quads, substrate 16 x 16
  const MeshQuality s = mesh_quality(m, Body::kSphere);
  const MeshQuality w = mesh_quality(m, Body::kSubstrate);
  EXPECT_EQ(s.elements, 3 * 12 * 6 + 12 * 12);
  EXPECT_EQ(w.elements, 16 * 16);
  EXPECT_GT(s.min_jacobian, 0.0);  // counter-clockwise after reading
  EXPECT_GT(w.min_jacobian, 0.0);
  EXPECT_NEAR(w.area, 0.02 * 0.02, 1e-15);
  EXPECT_NEAR(s.area, 0.5 * std::numbers::pi * 1e-4, 0.01 * 0.5 * std::numbers::pi * 1e-4);
  for (std::size_t e = 0; e < m.quads.size(); ++e)
    for (const int n : m.quads[e])
      EXPECT_EQ(m.node_body[static_cast<std::size_t>(n)], m.element_body[e]);
  // node sets
  for (const int n : m.axis_nodes) EXPECT_NEAR(m.r[static_cast<std::size_t>(n)], 0.0, 1e-15);
  EXPECT_EQ(m.axis_nodes.size(), 17u + 6u + 12u + 6u + 1u);  // substrate + sphere axis edges
  EXPECT_EQ(m.base_nodes.size(), 17u);
  for (const int n : m.base_nodes) EXPECT_NEAR(m.z[static_cast<std::size_t>(n)], -0.02, 1e-15);
  const auto& top = m.substrate_surface_nodes;
  ASSERT_EQ(top.size(), 17u);
  for (std::size_t k = 1; k < top.size(); ++k)
    EXPECT_GT(m.r[static_cast<std::size_t>(top[k])], m.r[static_cast<std::size_t>(top[k - 1])]);
  const auto& surf = m.sphere_surface_nodes;
  ASSERT_EQ(surf.size(), 25u);  // two arcs of 12 segments
  EXPECT_NEAR(m.r[static_cast<std::size_t>(surf.front())], 0.0, 1e-15);
  EXPECT_NEAR(m.z[static_cast<std::size_t>(surf.front())], 1e-4, 1e-15);
  double last = -1.0;
  for (const int n : surf) {
    const double r = m.r[static_cast<std::size_t>(n)];
    const double z = m.z[static_cast<std::size_t>(n)] - 0.0101;
    EXPECT_NEAR(std::hypot(r, z), 0.01, 1e-9);
    const double phi = std::atan2(r, -z);
    EXPECT_GT(phi, last);
    last = phi;
  }
}

TEST(GmshReader, ReadsTheShippedExampleMesh) {
  if (!gmsh_available()) GTEST_SKIP() << "built without gmsh";
  check_example(read_gmsh(kMeshDir / "example_impact.msh"));
}

TEST(GmshReader, MeshesAGeoFileOnTheFly) {
  if (!gmsh_available()) GTEST_SKIP() << "built without gmsh";
  const Mesh from_geo = read_gmsh(kMeshDir / "example_impact.geo");
  check_example(from_geo);
  const Mesh from_msh = read_gmsh(kMeshDir / "example_impact.msh");
  EXPECT_EQ(from_geo.num_nodes(), from_msh.num_nodes());
}

TEST(GmshReader, MissingPhysicalGroupIsNamed) {
  if (!gmsh_available()) GTEST_SKIP() << "built without gmsh";
  const auto path = geo_variant("no_base.geo", "Physical Curve\\(\"base\"\\) = \\{1\\};", "");
  try {
    read_gmsh(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("\"base\""), std::string::npos) << e.what();
  }
}

TEST(GmshReader, RejectsTriangles) {
  if (!gmsh_available()) GTEST_SKIP() << "built without gmsh";
  const auto path = geo_variant("triangles.geo", "Recombine Surface\\{1\\};", "");
  try {
    read_gmsh(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("\"substrate\""), std::string::npos) << what;
    EXPECT_NE(what.find("quadrilaterals"), std::string::npos) << what;
  }
}

TEST(GmshReader, MissingFile) {
  EXPECT_THROW(read_gmsh(kMeshDir / "does_not_exist.msh"), InputError);
}

}  // namespace
}  // namespace corlab::fem

namespace corlab::fem {
namespace {

// Found by fuzzing (tests/fuzz): on this damaged file the gmsh API throws a std::string, which
// escaped read_gmsh and terminated the process.
TEST(GmshReader, DamagedFileFoundByFuzzingIsAnInputError) {
  if (!gmsh_available()) GTEST_SKIP() << "built without gmsh";
  try {
    (void)read_gmsh(CORLAB_SOURCE_DIR "/tests/fuzz/regressions/gmsh_string_exception.msh");
    ADD_FAILURE() << "the damaged mesh was accepted";
  } catch (const InputError& err) {
    const std::string message = err.what();
    EXPECT_NE(message.find("gmsh could not read it"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

// Found by fuzzing: gmsh 4.8's own reader segfaults on this file; read_gmsh probes it in a child
// process and refuses it.
TEST(GmshReader, FileThatCrashesGmshIsAnInputError) {
  if (!gmsh_available()) GTEST_SKIP() << "built without gmsh";
  try {
    (void)read_gmsh(CORLAB_SOURCE_DIR "/tests/fuzz/regressions/gmsh_reader_segfault.msh");
    ADD_FAILURE() << "the damaged mesh was accepted";
  } catch (const InputError& err) {
    const std::string message = err.what();
    EXPECT_NE(message.find("gmsh could not read it"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

// Found by fuzzing: a damaged node count (999999432) keeps gmsh 4.8 reading for ~40 s; the
// probe's time limit (here 2 s) turns it into an InputError.
TEST(GmshReader, FileThatHangsGmshIsAnInputError) {
  if (!gmsh_available()) GTEST_SKIP() << "built without gmsh";
  ::setenv("CORLAB_GMSH_TIMEOUT_S", "2", 1);
  try {
    (void)read_gmsh(CORLAB_SOURCE_DIR "/tests/fuzz/regressions/gmsh_reader_hang.msh");
    ADD_FAILURE() << "the damaged mesh was accepted";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("could not read it within 2 s"), std::string::npos)
        << err.what();
  }
  ::unsetenv("CORLAB_GMSH_TIMEOUT_S");
  EXPECT_NO_THROW((void)read_gmsh(kMeshDir / "example_impact.msh"));
}

TEST(GmshReader, TimeLimitThatIsNotAPositiveNumberIsAnInputError) {
  if (!gmsh_available()) GTEST_SKIP() << "built without gmsh";
  for (const char* bad : {"abc", "0", "-5", "2s", ""}) {
    ::setenv("CORLAB_GMSH_TIMEOUT_S", bad, 1);
    try {
      (void)read_gmsh(kMeshDir / "example_impact.msh");
      ADD_FAILURE() << "CORLAB_GMSH_TIMEOUT_S=" << bad << " was accepted";
    } catch (const InputError& err) {
      EXPECT_EQ(err.field(), "CORLAB_GMSH_TIMEOUT_S") << err.what();
      EXPECT_EQ(err.value(), bad) << err.what();
    }
  }
  ::setenv("CORLAB_GMSH_TIMEOUT_S", " 30 ", 1);
  EXPECT_NO_THROW((void)read_gmsh(kMeshDir / "example_impact.msh"));
  ::unsetenv("CORLAB_GMSH_TIMEOUT_S");
}

}  // namespace
}  // namespace corlab::fem
