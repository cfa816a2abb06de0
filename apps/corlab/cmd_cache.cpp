// `corlab cache`: the FE result cache of `predict --model fe|auto` (study/result_cache.hpp).
//   corlab cache list | size | clear [--other-builds] | path
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/core.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "command.hpp"
#include "corlab/core/error.hpp"
#include "corlab/study/result_cache.hpp"
#include "corlab/study/results_table.hpp"

namespace corlab::cli {
namespace {

struct CacheOptions {
  std::string action;
  bool other_builds = false;
};

std::filesystem::path cache_root() {
  auto root = study::default_cache_directory();
  if (root.empty()) {
    throw InputError("no cache directory: none of CORLAB_CACHE_DIR, XDG_CACHE_HOME, HOME is set");
  }
  return root;
}

// The text at `path` in a JSON document, or "" (a foreign or partial entry).
std::string text_at(const nlohmann::json& doc, std::initializer_list<const char*> path) {
  const nlohmann::json* at = &doc;
  for (const char* key : path) {
    if (!at->is_object() || !at->contains(key)) return "";
    at = &(*at)[key];
  }
  if (at->is_string()) return at->get<std::string>();
  return at->is_null() ? "" : at->dump();
}

int list(const std::filesystem::path& root) {
  const std::string build = study::cache_build_id();
  fmt::print("{}\n", study::csv_line({"file", "bytes", "build", "this_build", "velocity", "sphere",
                                      "substrate", "shape", "status", "e", "e_error"}));
  for (const study::CacheEntry& entry : study::list_cache(root)) {
    const auto c = nlohmann::json::parse(entry.key, nullptr, false);
    const auto v = nlohmann::json::parse(entry.value, nullptr, false);
    fmt::print("{}\n", study::csv_line({entry.file.filename().string(), std::to_string(entry.bytes),
                                        entry.readable ? entry.build : "unreadable",
                                        entry.readable && entry.build == build ? "true" : "false",
                                        text_at(c, {"config", "impact", "velocity"}),
                                        text_at(c, {"config", "sphere", "material", "name"}),
                                        text_at(c, {"config", "substrate", "material", "name"}),
                                        text_at(c, {"config", "substrate", "shape"}),
                                        text_at(v, {"status"}), text_at(v, {"e"}),
                                        text_at(v, {"e_error"})}));
  }
  return 0;
}

int size(const std::filesystem::path& root) {
  const std::string build = study::cache_build_id();
  std::uintmax_t bytes = 0;
  std::size_t entries = 0;
  std::size_t current = 0;
  for (const study::CacheEntry& entry : study::list_cache(root)) {
    ++entries;
    bytes += entry.bytes;
    if (entry.readable && entry.build == build) ++current;
  }
  fmt::print("{} entries ({} of this build {}), {} bytes in {}\n", entries, current, build, bytes,
             root.string());
  return 0;
}

int run_cache(const CacheOptions& o) {
  const auto root = cache_root();
  if (o.other_builds && o.action != "clear") {
    throw_invalid("--other-builds", o.action, "used with clear");
  }
  if (o.action == "list") return list(root);
  if (o.action == "size") return size(root);
  if (o.action == "path") {
    fmt::print("{}\n", root.string());
    return 0;
  }
  const std::size_t removed = study::clear_cache(root, o.other_builds, study::cache_build_id());
  fmt::print("removed {} file(s) from {}\n", removed, root.string());
  return 0;
}

const CommandRegistration kRegistration{Command{
    "cache", "List, size or clear the FE result cache of `predict --model fe|auto`",
    [](CLI::App& sub) -> std::function<int()> {
      auto o = std::make_shared<CacheOptions>();
      sub.add_option("action", o->action,
                     "list (one CSV row per entry), size, clear, or path (the directory: "
                     "$CORLAB_CACHE_DIR, else $XDG_CACHE_HOME/corlab, else ~/.cache/corlab)")
          ->required()
          ->check(CLI::IsMember({"list", "size", "clear", "path"}));
      sub.add_flag("--other-builds", o->other_builds,
                   "clear: only entries of other corlab builds (and unreadable ones)");
      return [o] { return run_cache(*o); };
    },
    22}};

}  // namespace
}  // namespace corlab::cli
