// Where the shipped data (materials.toml, fe_restitution/, studies/) are: the one rule of
// data_directory(), installed_data_directory() and studies_directory().
// SPDX-License-Identifier: BSD-3-Clause
#if !defined(__EMSCRIPTEN__)
#include <dlfcn.h>
#include <link.h>
#endif

#include <cstdlib>
#include <filesystem>
#include <string_view>
#include <system_error>

#include "corlab/materials/material_database.hpp"

// The installed data directory relative to each directory corlab's code is installed to (bin/,
// lib/, the Python package), ':'-separated; CMake computes it from the install layout
// (cmake/CorlabInstall.cmake).
#ifndef CORLAB_INSTALL_DATA_FROM_CODE
#define CORLAB_INSTALL_DATA_FROM_CODE ""
#endif

namespace corlab {

namespace {

namespace fs = std::filesystem;

/// The executable or shared object this function was loaded from; empty when unknown (always in
/// the browser explorer's WebAssembly build: it has no installed data).
fs::path own_object_file() {
#if defined(__EMSCRIPTEN__)
  return {};
#else
  Dl_info info{};
  link_map* map = nullptr;
  if (dladdr1(reinterpret_cast<void*>(&own_object_file), &info, reinterpret_cast<void**>(&map),
              RTLD_DL_LINKMAP) == 0) {
    return {};
  }
  std::error_code ec;
  // The main program's link map has no name (and dli_fname is then argv[0], not a path).
  if (map == nullptr || map->l_name == nullptr || *map->l_name == '\0') {
    fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    return ec ? fs::path() : exe;
  }
  fs::path file = fs::canonical(map->l_name, ec);
  return ec ? fs::path() : file;
#endif
}

}  // namespace

fs::path installed_data_directory() {
  static const fs::path dir = [] {
    const fs::path code_dir = own_object_file().parent_path();
    if (code_dir.empty()) return fs::path();
    std::string_view candidates = CORLAB_INSTALL_DATA_FROM_CODE;
    while (!candidates.empty()) {
      const auto colon = candidates.find(':');
      fs::path candidate = (code_dir / candidates.substr(0, colon)).lexically_normal();
      candidates = colon == std::string_view::npos ? "" : candidates.substr(colon + 1);
      std::error_code ec;  // an unreadable copy counts as none
      if (fs::is_regular_file(candidate / "materials.toml", ec)) return candidate;
    }
    return fs::path();
  }();
  return dir;
}

fs::path data_directory(const fs::path& installed) {
  if (const char* env = std::getenv("CORLAB_DATA_DIR"); env != nullptr && *env != '\0') {
    return env;
  }
  std::error_code ec;  // an unreadable installed copy counts as none
  if (!installed.empty() && fs::is_regular_file(installed / "materials.toml", ec)) {
    return installed;
  }
  return CORLAB_DATA_DIR;
}

fs::path studies_directory() {
  const fs::path installed = installed_data_directory();
  return installed.empty() ? fs::path(CORLAB_STUDIES_DIR) : installed / "studies";
}

}  // namespace corlab
