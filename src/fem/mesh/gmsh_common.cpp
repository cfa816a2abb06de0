// What the Gmsh readers share (gmsh_common.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#ifdef CORLAB_WITH_GMSH
#include "fem/mesh/gmsh_common.hpp"

#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <optional>
#include <thread>

#include "corlab/core/number.hpp"

namespace corlab::fem::gmsh_io {
namespace {

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

}  // namespace

std::mutex& gmsh_mutex() {
  static std::mutex mutex;
  return mutex;
}

GmshSession::GmshSession() {
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("General.Verbosity", 1);
}

GmshSession::~GmshSession() { gmsh::finalize(); }

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
            dim == 3   ? "8-node hexahedra"
            : dim == 2 ? "4-node quadrilaterals (recombine the mesh)"
                       : "2-node lines"));
      }
      nodes.insert(nodes.end(), node_tags[k].begin(), node_tags[k].end());
    }
  }
  if (nodes.empty())
    throw InputError("invalid mesh.file = " + file.string() + ": physical group \"" + name +
                     "\" has no elements");
  return nodes;
}

NodeCoordinates node_coordinates() {
  NodeCoordinates nodes;
  std::vector<std::size_t> all_tags;
  std::vector<double> parametric;
  gmsh::model::mesh::getNodes(all_tags, nodes.coord, parametric, -1, -1, false, false);
  for (std::size_t k = 0; k < all_tags.size(); ++k) nodes.position[all_tags[k]] = k;
  return nodes;
}

}  // namespace corlab::fem::gmsh_io
#endif
