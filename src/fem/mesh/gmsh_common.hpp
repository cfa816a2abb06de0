// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the Gmsh readers share (gmsh_reader.cpp: the axisymmetric quads; gmsh_hex_reader.cpp: the
// 3-D model's half sphere): one Gmsh session at a time, the crash-safe opening of a file, and the
// physical groups, elements and nodes of the opened model. Private to src/fem/mesh; only built
// with CORLAB_WITH_GMSH.

#include <gmsh.h>

#include <cstddef>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "corlab/core/error.hpp"
#include "corlab/core/text.hpp"
#include "corlab/core/text_file.hpp"

namespace corlab::fem::gmsh_io {

/// Gmsh keeps global state and is not thread-safe: one reader at a time.
std::mutex& gmsh_mutex();

/// Initialises Gmsh on construction and finalises it on destruction (also on exceptions).
class GmshSession {
 public:
  GmshSession();
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

/// Opens `file` in a forked child first: InputError if gmsh crashes or overruns the time limit
/// (CORLAB_GMSH_TIMEOUT_S, default 60 s) on it.
void check_gmsh_survives_opening(const std::filesystem::path& file);

/// Physical group tags by name for one dimension.
std::map<std::string, int> physical_groups(int dim);

/// The tag of the physical group `name` of dimension `dim`; InputError naming it when missing.
int require_group(const std::map<std::string, int>& groups,
                  const std::string& name,
                  int dim,
                  const std::filesystem::path& file);

/// Node tags of the elements of `type` (all entities of a physical group), element by element;
/// InputError when another type occurs or the group is empty.
std::vector<std::size_t> group_elements(
    int dim, int tag, int type, const std::string& name, const std::filesystem::path& file);

/// Every node of the model: coordinates (x, y, z per node) and position of each gmsh tag.
struct NodeCoordinates {
  std::vector<double> coord;
  std::unordered_map<std::size_t, std::size_t> position;
};
NodeCoordinates node_coordinates();

/// Opens `file` (a regular file within kMaxMeshFileBytes, probed in a child first) in a fresh
/// session under the mutex and returns read(); Gmsh's own errors (std::string or
/// std::exception, from any call) become InputError naming mesh.file.
template <typename Read>
auto read_gmsh_file(const std::filesystem::path& file, Read read) {
  require_regular_file(file, "mesh.file", kMaxMeshFileBytes);
  const std::lock_guard<std::mutex> lock(gmsh_mutex());
  const GmshSession session;
  const auto unreadable = [&file](const std::string& why) {
    return InputError("invalid mesh.file = " + file.string() + ": gmsh could not read it (" +
                      one_line(why) + ")");
  };
  check_gmsh_survives_opening(file);
  try {
    gmsh::open(file.string());
    return read();
  } catch (const InputError&) {
    throw;
  } catch (const std::string& why) {
    throw unreadable(why);
  } catch (const std::exception& e) {
    throw unreadable(e.what());
  }
}

}  // namespace corlab::fem::gmsh_io
