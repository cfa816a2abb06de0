// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file result_cache.hpp
/// A cache of computed results on disk, one JSON file per entry, keyed by a JSON document (for an
/// impact run: its whole resolved config, fe_curve.hpp) and by the solver build that computed it.
/// Every entry holds its key and build: a read checks both, so a corrupted file, a hash collision
/// or an entry of another build is a miss (recomputed and replaced), never a wrong answer.
/// Writers replace a file atomically through a unique temporary in the same directory
/// (write_file_atomically_shared), so processes may fill one cache at the same time.
///
/// Layout: <root>/runs/<16 hex digits>.json, the digits FNV-1a of the key's compact JSON text.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace corlab::study {

/// The user's cache directory: $CORLAB_CACHE_DIR if set, else $XDG_CACHE_HOME/corlab, else
/// $HOME/.cache/corlab; empty when none of them is set.
std::filesystem::path default_cache_directory();

/// The build an entry is valid for: corlab::build_id(); for a build of a modified tree
/// ("-dirty") or one outside git ("unknown"), which names no one source, the size and
/// modification time of the program or library holding the solver are appended, so that a
/// rebuild invalidates the entries.
std::string cache_build_id();

/// One entry as `corlab cache list` shows it.
struct CacheEntry {
  std::filesystem::path file;
  std::uintmax_t bytes = 0;
  bool readable = false;  ///< parsed as an entry (key, build and value present)
  std::string build;      ///< the build that wrote it
  std::string key;        ///< its key as compact JSON text ("" when not readable)
  std::string value;      ///< its value as compact JSON text ("" when not readable)
};

class ResultCache {
 public:
  /// A cache in `root` for results of `build`; `warn` receives the one warning of a cache that
  /// cannot be written (null: none). An empty root is a cache that stores nothing.
  ResultCache(std::filesystem::path root,
              std::string build,
              std::function<void(const std::string&)> warn = {});

  /// The value stored for `key` by this build, or nullopt (none, unreadable, another key or build).
  std::optional<nlohmann::json> load(const nlohmann::json& key) const;
  /// Stores `value` under `key`. A directory or file that cannot be written turns the cache off
  /// for this object's life, with one warning; it never throws. Thread-safe.
  void store(const nlohmann::json& key, const nlohmann::json& value);

  /// Whether store() still writes.
  bool writable() const;
  const std::filesystem::path& root() const { return root_; }
  const std::string& build() const { return build_; }
  /// The file of `key`.
  std::filesystem::path entry_file(const nlohmann::json& key) const;

 private:
  std::filesystem::path root_;
  std::string build_;
  std::function<void(const std::string&)> warn_;
  mutable std::mutex mutex_;
  bool disabled_ = false;
};

/// Every entry file under `root` (readable or not), by file name.
std::vector<CacheEntry> list_cache(const std::filesystem::path& root);

/// Removes the entries under `root` (and temporaries left by killed writers); with
/// `other_builds_only`, only those not written by `build` (and unreadable ones). Returns the
/// files removed. Throws std::runtime_error naming a file it cannot remove.
std::size_t clear_cache(const std::filesystem::path& root,
                        bool other_builds_only,
                        const std::string& build);

}  // namespace corlab::study
