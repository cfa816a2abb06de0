// VTU output (vtu_writer.hpp): a well-formed file with the declared arrays.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/output/vtu_writer.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <sstream>
#include <string>

#include "corlab/core/error.hpp"
#include "corlab/fem/mesh/hex_mesh_generator.hpp"
#include "corlab/fem/mesh/mesh_generator.hpp"
#include "support/scratch_files.hpp"

namespace corlab::fem {
namespace {

std::filesystem::path out_dir() {
  const auto dir = std::filesystem::path(CORLAB_BINARY_DIR) / "test_output" / "vtu_writer";
  std::filesystem::create_directories(dir);
  return dir;
}

using test::slurp;

long count(const std::string& text, const std::string& what) {
  long n = 0;
  for (std::size_t pos = text.find(what); pos != std::string::npos;
       pos = text.find(what, pos + what.size()))
    ++n;
  return n;
}

/// Numbers between the opening tag of DataArray `name` and its closing tag.
std::vector<double> array_values(const std::string& text, const std::string& name) {
  const std::size_t start = text.find("Name=\"" + name + "\"");
  EXPECT_NE(start, std::string::npos) << name;
  const std::size_t open_end = text.find('>', start);
  const std::size_t close = text.find("</DataArray>", open_end);
  std::istringstream in(text.substr(open_end + 1, close - open_end - 1));
  std::vector<double> v;
  double x = 0.0;
  while (in >> x) v.push_back(x);
  return v;
}

Mesh small_mesh() {
  MeshOptions o;
  o.sphere_radius = 10e-3;
  o.substrate_radius = 20e-3;
  o.substrate_depth = 20e-3;
  o.h_contact = 0.5e-3;
  o.zone_radius = 2e-3;
  o.zone_depth = 2e-3;
  o.h_max = 3e-3;
  o.growth = 1.3;
  return generate_impact_mesh(o);
}

TEST(VtuWriter, WritesAWellFormedFileWithFields) {
  const Mesh m = small_mesh();
  const auto nn = static_cast<std::size_t>(m.num_nodes());
  const auto ne = static_cast<std::size_t>(m.num_elements());
  FieldSnapshot snap;
  snap.mesh = m;
  snap.displacement_r.assign(nn, 1e-6);
  snap.displacement_z.assign(nn, -2e-6);
  snap.von_mises.assign(ne, 3e8);
  snap.plastic_strain.assign(ne, 0.01);
  const auto path = out_dir() / "snapshot.vtu";
  write_vtu(path, snap);
  const std::string text = slurp(path);
  // XML well-formedness (balanced elements of this flat schema)
  EXPECT_EQ(text.rfind("<?xml", 0), 0u);
  EXPECT_EQ(count(text, "<DataArray"), count(text, "</DataArray>"));
  for (const char* tag :
       {"VTKFile", "UnstructuredGrid", "Piece", "Points", "Cells", "PointData", "CellData"})
    EXPECT_EQ(count(text, std::string("<") + tag + ">") + count(text, std::string("<") + tag + " "),
              count(text, std::string("</") + tag + ">"))
        << tag;
  EXPECT_NE(text.find("NumberOfPoints=\"" + std::to_string(nn) + "\""), std::string::npos);
  EXPECT_NE(text.find("NumberOfCells=\"" + std::to_string(ne) + "\""), std::string::npos);
  EXPECT_EQ(array_values(text, "connectivity").size(), 4 * ne);
  EXPECT_EQ(array_values(text, "offsets").back(), static_cast<double>(4 * ne));
  EXPECT_EQ(array_values(text, "types").size(), ne);
  const auto disp = array_values(text, "displacement");
  ASSERT_EQ(disp.size(), 3 * nn);
  EXPECT_DOUBLE_EQ(disp[0], 1e-6);
  EXPECT_DOUBLE_EQ(disp[1], -2e-6);
  EXPECT_DOUBLE_EQ(disp[2], 0.0);
  EXPECT_EQ(array_values(text, "von_mises").size(), ne);
  EXPECT_EQ(array_values(text, "plastic_strain").size(), ne);
  const auto body = array_values(text, "body");
  ASSERT_EQ(body.size(), ne);
  for (std::size_t e = 0; e < ne; ++e)
    EXPECT_EQ(body[e], m.element_body[e] == Body::kSphere ? 0.0 : 1.0);
  EXPECT_EQ(text.find("pressure"), std::string::npos);  // empty fields are skipped
}

TEST(VtuWriter, RejectsMisSizedFields) {
  const Mesh m = small_mesh();
  VtuField bad{"von_mises", 1, std::vector<double>(3, 0.0)};
  EXPECT_THROW(write_vtu(out_dir() / "bad.vtu", m, {}, {bad}), InputError);
  EXPECT_THROW(write_vtu(out_dir() / "no_such_dir" / "x.vtu", m), InputError);
}

HexMesh small_hex_mesh() {
  HexMeshOptions o;
  o.sphere_radius = 10e-3;
  o.h_contact = 0.5e-3;
  o.zone_radius = 1e-3;
  o.zone_depth = 1e-3;
  o.h_max = 3e-3;
  o.growth = 1.4;
  o.block = true;
  o.block_half_width = 10e-3;
  o.block_depth = 10e-3;
  return generate_hex_impact_mesh(o);
}

// The 3-D half model: hexahedra (VTK type 12), eight nodes each, 3-D points.
TEST(VtuWriter, WritesTheHexahedralMesh) {
  const HexMesh m = small_hex_mesh();
  const auto file = out_dir() / "hex.vtu";
  write_vtu(file, m);
  const std::string text = slurp(file);
  EXPECT_NE(text.find(fmt::format("NumberOfPoints=\"{}\" NumberOfCells=\"{}\"", m.num_nodes(),
                                  m.num_elements())),
            std::string::npos);
  const std::vector<double> types = array_values(text, "types");
  ASSERT_EQ(types.size(), static_cast<std::size_t>(m.num_elements()));
  for (const double t : types) EXPECT_EQ(t, 12.0);
  const std::vector<double> offsets = array_values(text, "offsets");
  EXPECT_EQ(offsets.back(), 8.0 * m.num_elements());
  const std::vector<double> body = array_values(text, "body");
  EXPECT_EQ(body.front(), 0.0);
  EXPECT_EQ(body.back(), 1.0);
}

// A 3-D snapshot: its vectors keep their three components in order; a mis-sized one is refused.
TEST(VtuWriter, WritesAHexSnapshot) {
  HexFieldSnapshot snap;
  snap.mesh = small_hex_mesh();
  const auto nn = static_cast<std::size_t>(snap.mesh.num_nodes());
  const auto ne = static_cast<std::size_t>(snap.mesh.num_elements());
  for (std::size_t n = 0; n < nn; ++n) snap.velocity.insert(snap.velocity.end(), {1.0, 2.0, -3.0});
  snap.von_mises.assign(ne, 2e8);
  snap.pressure.assign(ne, -1e8);
  const auto file = out_dir() / "hex_snapshot.vtu";
  write_vtu(file, snap);
  const std::string text = slurp(file);
  const std::vector<double> velocity = array_values(text, "velocity");
  ASSERT_EQ(velocity.size(), 3 * nn);
  EXPECT_EQ(velocity[3 * nn - 3], 1.0);
  EXPECT_EQ(velocity[3 * nn - 2], 2.0);
  EXPECT_EQ(velocity[3 * nn - 1], -3.0);
  EXPECT_EQ(array_values(text, "pressure").size(), ne);
  EXPECT_EQ(text.find("displacement"), std::string::npos);  // empty fields are skipped
  snap.displacement.assign(nn, 0.0);                        // one component per node: refused
  EXPECT_THROW(write_vtu(file, snap), InputError);
}

}  // namespace
}  // namespace corlab::fem
