// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/mesh/gmsh_reader.hpp"

#include "corlab/core/error.hpp"

#ifdef CORLAB_WITH_GMSH
#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <unordered_map>
#include <vector>

#include "fem/mesh/gmsh_common.hpp"
#endif

namespace corlab::fem {

#ifndef CORLAB_WITH_GMSH

bool gmsh_available() { return false; }

Mesh read_gmsh(const std::filesystem::path& /*file*/) {
  throw InputError("gmsh support not built");
}

#else

namespace {

using gmsh_io::group_elements;
using gmsh_io::node_coordinates;
using gmsh_io::NodeCoordinates;
using gmsh_io::physical_groups;
using gmsh_io::require_group;

constexpr int kLine2 = 1;
constexpr int kQuad4 = 3;

/// Orders the nodes of a chain of 2-node segments, starting from the end that minimises `key`.
template <typename Key>
std::vector<int> chain(const std::vector<std::size_t>& segments,
                       const std::unordered_map<std::size_t, int>& index,
                       Key key,
                       const std::string& name,
                       const std::filesystem::path& file) {
  std::unordered_map<int, std::vector<int> > adjacent;
  for (std::size_t k = 0; k + 1 < segments.size(); k += 2) {
    const auto a = index.find(segments[k]);
    const auto b = index.find(segments[k + 1]);
    if (a == index.end() || b == index.end())
      throw InputError("invalid mesh.file = " + file.string() + ": physical group \"" + name +
                       "\" has nodes outside its body");
    adjacent[a->second].push_back(b->second);
    adjacent[b->second].push_back(a->second);
  }
  int start = -1;
  for (const auto& [node, next] : adjacent) {
    if (next.size() > 2)
      throw InputError("invalid mesh.file = " + file.string() + ": physical group \"" + name +
                       "\" is not a simple curve");
    if (next.size() == 1 && (start < 0 || key(node) < key(start))) start = node;
  }
  if (start < 0)
    throw InputError("invalid mesh.file = " + file.string() + ": physical group \"" + name +
                     "\" is a closed curve");
  std::vector<int> order{start};
  int prev = -1;
  int cur = start;
  while (true) {
    const auto& next = adjacent.at(cur);
    int step = -1;
    for (const int n : next)
      if (n != prev) step = n;
    if (step < 0 || (next.size() == 1 && prev >= 0)) break;
    prev = cur;
    cur = step;
    order.push_back(cur);
  }
  if (order.size() != adjacent.size())
    throw InputError("invalid mesh.file = " + file.string() + ": physical group \"" + name +
                     "\" is not one connected curve");
  return order;
}

/// Appends the quadrilaterals `connectivity` (4 gmsh node tags each) of one body to `mesh`,
/// counter-clockwise in (r, z); `index` maps gmsh tags to mesh nodes of this body, `other` those
/// of the other body (the bodies must not share nodes).
void add_body(Mesh& mesh,
              const std::vector<std::size_t>& connectivity,
              const NodeCoordinates& nodes,
              Body body,
              std::unordered_map<std::size_t, int>& index,
              const std::unordered_map<std::size_t, int>& other,
              const std::filesystem::path& file) {
  for (std::size_t k = 0; k < connectivity.size(); k += 4) {
    std::array<int, 4> quad{};
    for (std::size_t c = 0; c < 4; ++c) {
      const std::size_t gtag = connectivity[k + c];
      if (other.count(gtag) != 0)
        throw InputError("invalid mesh.file = " + file.string() +
                         R"(: the bodies "sphere" and "substrate" share nodes)");
      auto [it, inserted] = index.try_emplace(gtag, mesh.num_nodes());
      if (inserted) {
        const std::size_t p = nodes.position.at(gtag);
        mesh.r.push_back(nodes.coord[3 * p]);
        mesh.z.push_back(nodes.coord[3 * p + 1]);
        mesh.node_body.push_back(body);
      }
      quad[c] = it->second;
    }
    mesh.quads.push_back(counter_clockwise(mesh, quad));
    mesh.element_body.push_back(body);
  }
}

std::vector<std::size_t> physical_group_nodes(int tag) {
  std::vector<std::size_t> tags;
  std::vector<double> xyz;
  gmsh::model::mesh::getNodesForPhysicalGroup(1, tag, tags, xyz);
  return tags;
}

/// The axis nodes (of either body) and the base nodes (of the substrate), sorted.
void add_boundary_nodes(Mesh& mesh,
                        int axis_tag,
                        int base_tag,
                        const std::unordered_map<std::size_t, int>& sphere_index,
                        const std::unordered_map<std::size_t, int>& substrate_index,
                        const std::filesystem::path& file) {
  for (const std::size_t t : physical_group_nodes(axis_tag)) {
    if (const auto it = sphere_index.find(t); it != sphere_index.end())
      mesh.axis_nodes.push_back(it->second);
    else if (const auto jt = substrate_index.find(t); jt != substrate_index.end())
      mesh.axis_nodes.push_back(jt->second);
  }
  std::sort(mesh.axis_nodes.begin(), mesh.axis_nodes.end());
  for (const std::size_t t : physical_group_nodes(base_tag)) {
    const auto it = substrate_index.find(t);
    if (it == substrate_index.end())
      throw InputError("invalid mesh.file = " + file.string() +
                       R"(: physical group "base" has nodes outside "substrate")");
    mesh.base_nodes.push_back(it->second);
  }
  std::sort(mesh.base_nodes.begin(), mesh.base_nodes.end());
}

}  // namespace

bool gmsh_available() { return true; }

namespace {

Mesh read_opened_gmsh(const std::filesystem::path& file);

}  // namespace

// Gmsh opens the file itself: only a regular file within the cap reaches it, and the gmsh API
// throws std::string (not std::exception) on a damaged file, from any call; found by fuzzing
// (tests/fuzz, regression: gmsh_reader_test DamagedFileIsAnInputError).
Mesh read_gmsh(const std::filesystem::path& file) {
  return gmsh_io::read_gmsh_file(file, [&file] { return read_opened_gmsh(file); });
}

namespace {

Mesh read_opened_gmsh(const std::filesystem::path& file) {
  {
    std::vector<int> types;
    std::vector<std::vector<std::size_t> > tags;
    std::vector<std::vector<std::size_t> > nodes;
    gmsh::model::mesh::getElements(types, tags, nodes, 2);
    if (types.empty()) gmsh::model::mesh::generate(2);  // a .geo without a stored mesh
  }

  const auto groups2 = physical_groups(2);
  const auto groups1 = physical_groups(1);
  const int sphere_tag = require_group(groups2, "sphere", 2, file);
  const int substrate_tag = require_group(groups2, "substrate", 2, file);
  const int axis_tag = require_group(groups1, "axis", 1, file);
  const int base_tag = require_group(groups1, "base", 1, file);
  const int sphere_contact_tag = require_group(groups1, "sphere_contact", 1, file);
  const int substrate_contact_tag = require_group(groups1, "substrate_contact", 1, file);

  Mesh mesh;
  std::unordered_map<std::size_t, int> sphere_index;
  std::unordered_map<std::size_t, int> substrate_index;
  const NodeCoordinates nodes = node_coordinates();
  add_body(mesh, group_elements(2, sphere_tag, kQuad4, "sphere", file), nodes, Body::kSphere,
           sphere_index, {}, file);
  add_body(mesh, group_elements(2, substrate_tag, kQuad4, "substrate", file), nodes,
           Body::kSubstrate, substrate_index, sphere_index, file);
  add_boundary_nodes(mesh, axis_tag, base_tag, sphere_index, substrate_index, file);

  const auto sphere_segments =
      group_elements(1, sphere_contact_tag, kLine2, "sphere_contact", file);
  mesh.sphere_surface_nodes = chain(
      sphere_segments, sphere_index, [&](int n) { return mesh.z[static_cast<std::size_t>(n)]; },
      "sphere_contact", file);
  const auto substrate_segments =
      group_elements(1, substrate_contact_tag, kLine2, "substrate_contact", file);
  mesh.substrate_surface_nodes = chain(
      substrate_segments, substrate_index,
      [&](int n) { return mesh.r[static_cast<std::size_t>(n)]; }, "substrate_contact", file);
  return mesh;
}

}  // namespace

#endif

}  // namespace corlab::fem
