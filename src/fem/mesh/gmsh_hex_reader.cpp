// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/mesh/gmsh_hex_reader.hpp"

#include "corlab/core/error.hpp"

#ifdef CORLAB_WITH_GMSH
#include <fmt/format.h>
#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <unordered_map>
#include <vector>

#include "corlab/fem/kernels/hex8.hpp"
#include "fem/mesh/gmsh_common.hpp"
#endif

namespace corlab::fem {

#ifndef CORLAB_WITH_GMSH

HexMesh read_gmsh_hex_sphere(const std::filesystem::path& /*file*/, double /*radius*/) {
  throw InputError("gmsh support not built");
}

#else

namespace {

constexpr int kHex8 = 5;
/// Coordinates within this fraction of the radius count as on a plane [-].
constexpr double kPlaneTolerance = 1e-6;
/// The body's height may differ from the sphere's diameter by this fraction [-].
constexpr double kHeightTolerance = 0.01;

[[noreturn]] void refuse(const std::filesystem::path& file, const std::string& why) {
  throw InputError("invalid mesh.file = " + file.string() + ": " + why);
}

// The nodes of a 2D physical group, as mesh indices; every one must be a node of "sphere".
std::vector<int> group_nodes(int tag,
                             const std::string& name,
                             const std::unordered_map<std::size_t, int>& index,
                             const std::filesystem::path& file) {
  std::vector<std::size_t> tags;
  std::vector<double> xyz;
  gmsh::model::mesh::getNodesForPhysicalGroup(2, tag, tags, xyz);
  std::vector<int> nodes;
  for (const std::size_t t : tags) {
    const auto it = index.find(t);
    if (it == index.end())
      refuse(file, "physical group \"" + name + R"(" has nodes outside "sphere")");
    nodes.push_back(it->second);
  }
  if (nodes.empty()) refuse(file, "physical group \"" + name + "\" has no nodes");
  std::sort(nodes.begin(), nodes.end());
  return nodes;
}

// The hexahedra, their nodes numbered by increasing Gmsh tag.
HexMesh sphere_body(const std::vector<std::size_t>& connectivity,
                    const gmsh_io::NodeCoordinates& nodes,
                    std::unordered_map<std::size_t, int>& index) {
  std::vector<std::size_t> tags(connectivity);
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  HexMesh mesh;
  for (const std::size_t t : tags) {
    index[t] = mesh.num_nodes();
    const std::size_t p = nodes.position.at(t);
    mesh.x.push_back(nodes.coord[3 * p]);
    mesh.y.push_back(nodes.coord[3 * p + 1]);
    mesh.z.push_back(nodes.coord[3 * p + 2]);
    mesh.node_body.push_back(Body::kSphere);
  }
  for (std::size_t k = 0; k < connectivity.size(); k += 8) {
    std::array<int, 8> hex{};
    for (std::size_t c = 0; c < 8; ++c) hex[c] = index.at(connectivity[k + c]);
    mesh.hexes.push_back(hex);
    mesh.element_body.push_back(Body::kSphere);
  }
  return mesh;
}

// Refuses a body that is not the half sphere of `radius`, or an inverted element.
void check_half_sphere(const HexMesh& mesh, double radius, const std::filesystem::path& file) {
  const double tolerance = kPlaneTolerance * radius;
  const auto y_min = std::min_element(mesh.y.begin(), mesh.y.end());
  if (*y_min < -tolerance)
    refuse(file, fmt::format("\"sphere\" reaches y = {:.6g} m: the 3-D model is the half y >= 0",
                             *y_min));
  for (const int n : mesh.symmetry_nodes)
    if (std::abs(mesh.y[static_cast<std::size_t>(n)]) > tolerance)
      refuse(file, fmt::format("a \"symmetry\" node lies at y = {:.6g} m, off the plane y = 0",
                               mesh.y[static_cast<std::size_t>(n)]));
  const auto [z_min, z_max] = std::minmax_element(mesh.z.begin(), mesh.z.end());
  if (std::abs(*z_min) > tolerance)
    refuse(file, fmt::format("the lowest node of \"sphere\" lies at z = {:.6g} m; it must touch "
                             "the flat at z = 0",
                             *z_min));
  const double height = *z_max - *z_min;
  if (std::abs(height - 2.0 * radius) > kHeightTolerance * 2.0 * radius)
    refuse(file, fmt::format("\"sphere\" is {:.6g} m tall; sphere.radius = {:.6g} m asks for "
                             "{:.6g} m (within 1 %)",
                             height, radius, 2.0 * radius));
  for (std::size_t e = 0; e < mesh.hexes.size(); ++e) {
    double x[8], y[8], z[8];
    for (std::size_t i = 0; i < 8; ++i) {
      const auto n = static_cast<std::size_t>(mesh.hexes[e][i]);
      x[i] = mesh.x[n];
      y[i] = mesh.y[n];
      z[i] = mesh.z[n];
    }
    if (!(hex8_geometry(x, y, z).volume > 0.0))
      refuse(file, fmt::format("hexahedron {} of \"sphere\" is inverted or flat (Gmsh's node "
                               "order: the bottom face counter-clockwise seen from above, then "
                               "the top)",
                               e + 1));
  }
}

HexMesh read_opened_hex_sphere(const std::filesystem::path& file, double radius) {
  {
    std::vector<int> types;
    std::vector<std::vector<std::size_t> > tags;
    std::vector<std::vector<std::size_t> > nodes;
    gmsh::model::mesh::getElements(types, tags, nodes, 3);
    if (types.empty()) gmsh::model::mesh::generate(3);  // a .geo without a stored mesh
  }
  const auto groups3 = gmsh_io::physical_groups(3);
  const auto groups2 = gmsh_io::physical_groups(2);
  const int sphere_tag = gmsh_io::require_group(groups3, "sphere", 3, file);
  const int contact_tag = gmsh_io::require_group(groups2, "sphere_contact", 2, file);
  const int symmetry_tag = gmsh_io::require_group(groups2, "symmetry", 2, file);
  std::unordered_map<std::size_t, int> index;
  HexMesh mesh = sphere_body(gmsh_io::group_elements(3, sphere_tag, kHex8, "sphere", file),
                             gmsh_io::node_coordinates(), index);
  mesh.sphere_surface_nodes = group_nodes(contact_tag, "sphere_contact", index, file);
  mesh.symmetry_nodes = group_nodes(symmetry_tag, "symmetry", index, file);
  check_half_sphere(mesh, radius, file);
  return mesh;
}

}  // namespace

HexMesh read_gmsh_hex_sphere(const std::filesystem::path& file, double radius) {
  return gmsh_io::read_gmsh_file(file,
                                 [&file, radius] { return read_opened_hex_sphere(file, radius); });
}

#endif

}  // namespace corlab::fem
