#include "corlab/fem/mesh/gmsh_reader.hpp"

#include "corlab/core/error.hpp"

#ifdef CORLAB_WITH_GMSH
#include <fmt/format.h>
#include <gmsh.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstddef>
#include <cstdlib>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <unordered_map>
#include <vector>

#include "corlab/core/number.hpp"
#include "corlab/core/text.hpp"
#include "corlab/core/text_file.hpp"
#endif

namespace corlab::fem {

#ifndef CORLAB_WITH_GMSH

bool gmsh_available() { return false; }

Mesh read_gmsh(const std::filesystem::path& /*file*/) {
  throw InputError("gmsh support not built");
}

#else

namespace {

/// Gmsh keeps global state and is not thread-safe: one reader at a time.
std::mutex& gmsh_mutex() {
  static std::mutex mutex;
  return mutex;
}

/// Initialises Gmsh on construction and finalises it on destruction (also on exceptions).
class GmshSession {
 public:
  GmshSession() {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 1);
  }
  ~GmshSession() { gmsh::finalize(); }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

constexpr int kLine2 = 1;
constexpr int kQuad4 = 3;

/// Physical group tags by name for one dimension.
std::map<std::string, int> physical_groups(int dim) {
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, dim);
  std::map<std::string, int> out;
  for (const auto& [d, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(d, tag, name);
    out[name] = tag;
  }
  return out;
}

int require_group(const std::map<std::string, int>& groups,
                  const std::string& name,
                  int dim,
                  const std::filesystem::path& file) {
  const auto it = groups.find(name);
  if (it == groups.end())
    throw InputError("invalid mesh.file = " + file.string() + ": missing " + std::to_string(dim) +
                     "D physical group \"" + name + "\"");
  return it->second;
}

/// Elements of `type` (all entities of a physical group); throws when another type occurs.
std::vector<std::size_t> group_elements(
    int dim, int tag, int type, const std::string& name, const std::filesystem::path& file) {
  std::vector<int> entities;
  gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
  std::vector<std::size_t> nodes;
  for (const int entity : entities) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t> > element_tags;
    std::vector<std::vector<std::size_t> > node_tags;
    gmsh::model::mesh::getElements(types, element_tags, node_tags, dim, entity);
    for (std::size_t k = 0; k < types.size(); ++k) {
      if (types[k] != type) {
        std::string type_name;
        int edim = 0;
        int order = 0;
        int num_nodes = 0;
        int num_primary = 0;
        std::vector<double> local;
        gmsh::model::mesh::getElementProperties(types[k], type_name, edim, order, num_nodes, local,
                                                num_primary);
        throw InputError(fmt::format(
            "invalid mesh.file = {}: physical group \"{}\" contains {} elements; only {} are "
            "supported",
            file.string(), name, type_name,
            dim == 2 ? "4-node quadrilaterals (recombine the mesh)" : "2-node lines"));
      }
      nodes.insert(nodes.end(), node_tags[k].begin(), node_tags[k].end());
    }
  }
  if (nodes.empty())
    throw InputError("invalid mesh.file = " + file.string() + ": physical group \"" + name +
                     "\" has no elements");
  return nodes;
}

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

/// Every node of the model: coordinates (x, y, z per node) and position of each gmsh tag.
struct NodeCoordinates {
  std::vector<double> coord;
  std::unordered_map<std::size_t, std::size_t> position;
};

NodeCoordinates node_coordinates() {
  NodeCoordinates nodes;
  std::vector<std::size_t> all_tags;
  std::vector<double> parametric;
  gmsh::model::mesh::getNodes(all_tags, nodes.coord, parametric, -1, -1, false, false);
  for (std::size_t k = 0; k < all_tags.size(); ++k) nodes.position[all_tags[k]] = k;
  return nodes;
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

// Longest time gmsh may take to open a file [s]; CORLAB_GMSH_TIMEOUT_S overrides it.
double gmsh_open_timeout_s() {
  constexpr const char* kVariable = "CORLAB_GMSH_TIMEOUT_S";
  const char* env = std::getenv(kVariable);
  if (env == nullptr) return 60.0;
  const std::optional<double> value = parse_double(trim(env));
  if (!value || !std::isfinite(*value) || *value <= 0.0) {
    throw_invalid(kVariable, env, "a time limit > 0 [s] (or unset for 60 s)");
  }
  return *value;
}

// Debian's gmsh 4.8 reader segfaults on some damaged .msh files (GModel::getMeshVertexByTag) and
// loops for minutes on a damaged node count (found by fuzzing; regressions in gmsh_reader_test).
// Open the file in a forked child first: if the child dies or overruns the time limit, the file is
// refused as an InputError instead of taking corlab down or hanging it.
void check_gmsh_survives_opening(const std::filesystem::path& file) {
  const double limit = gmsh_open_timeout_s();
  const pid_t pid = ::fork();
  if (pid < 0) return;  // cannot probe: read directly
  if (pid == 0) {
    for (const int s : {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL}) std::signal(s, SIG_DFL);
    try {
      gmsh::open(file.string());
    } catch (...) {
      // a clean error: the parent reports it
    }
    ::_exit(0);
  }
  const auto start = std::chrono::steady_clock::now();
  int status = 0;
  while (true) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) return;
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > limit) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      throw InputError("invalid mesh.file = " + file.string() + ": gmsh could not read it within " +
                       std::to_string(static_cast<int>(limit)) +
                       " s (a damaged count?; CORLAB_GMSH_TIMEOUT_S raises the limit)");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
  throw InputError(
      "invalid mesh.file = " + file.string() + ": gmsh could not read it (its reader " +
      (WIFSIGNALED(status) ? "crashed with signal " + std::to_string(WTERMSIG(status)) : "failed") +
      " on this file)");
}

}  // namespace

Mesh read_gmsh(const std::filesystem::path& file) {
  // Gmsh opens the file itself: only a regular file within the cap reaches it.
  require_regular_file(file, "mesh.file", kMaxMeshFileBytes);
  const std::lock_guard<std::mutex> lock(gmsh_mutex());
  const GmshSession session;
  // The gmsh API throws std::string (not std::exception) on a damaged file, from any call; found
  // by fuzzing (tests/fuzz, regression: gmsh_reader_test DamagedFileIsAnInputError).
  const auto unreadable = [&file](const std::string& why) {
    return InputError("invalid mesh.file = " + file.string() + ": gmsh could not read it (" +
                      one_line(why) + ")");
  };
  check_gmsh_survives_opening(file);
  try {
    gmsh::open(file.string());
    return read_opened_gmsh(file);
  } catch (const InputError&) {
    throw;
  } catch (const std::string& why) {
    throw unreadable(why);
  } catch (const std::exception& e) {
    throw unreadable(e.what());
  }
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
