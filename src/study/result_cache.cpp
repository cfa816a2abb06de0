// The on-disk result cache (result_cache.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/study/result_cache.hpp"

#include <dlfcn.h>
#include <fmt/format.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <system_error>

#include "corlab/core/atomic_file.hpp"
#include "corlab/core/hash.hpp"
#include "corlab/version.hpp"

namespace corlab::study {
namespace {

namespace fs = std::filesystem;

/// Tells an entry file from anything else a user keeps in the directory.
constexpr std::string_view kFormat = "corlab result cache 1";
constexpr std::string_view kRunsFolder = "runs";
/// A temporary older than this was left by a killed writer (a live one renames it within a
/// second): `clear` removes it [s].
constexpr auto kStaleTemporary = std::chrono::minutes(10);

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value == nullptr ? std::string() : std::string(value);
}

bool is_entry_name(const std::string& name) {
  return name.size() == 21 && name.ends_with(".json") &&
         std::all_of(name.begin(), name.begin() + 16,
                     [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

bool is_temporary_name(const std::string& name) {
  const auto at = name.find(".json.tmp.");
  return at != std::string::npos && is_entry_name(name.substr(0, at + 5));
}

std::optional<nlohmann::json> read_entry(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  nlohmann::json entry = nlohmann::json::parse(text.str(), nullptr, false);
  if (entry.is_discarded() || !entry.is_object() || entry.value("format", "") != kFormat ||
      !entry.contains("key") || !entry.contains("value") || !entry.contains("build") ||
      !entry["build"].is_string()) {
    return std::nullopt;
  }
  return entry;
}

}  // namespace

fs::path default_cache_directory() {
  if (const std::string dir = environment("CORLAB_CACHE_DIR"); !dir.empty()) return dir;
  if (const std::string xdg = environment("XDG_CACHE_HOME"); !xdg.empty()) {
    return fs::path(xdg) / "corlab";
  }
  if (const std::string home = environment("HOME"); !home.empty()) {
    return fs::path(home) / ".cache" / "corlab";
  }
  return {};
}

std::string cache_build_id() {
  std::string id(build_id());
  if (!id.ends_with("-dirty") && !id.ends_with("unknown")) return id;
  // The image (executable or shared library) that holds this function, hence the solver.
  Dl_info info{};
  if (::dladdr(reinterpret_cast<void*>(&cache_build_id), &info) == 0 || info.dli_fname == nullptr) {
    return id;
  }
  std::error_code ec;
  const fs::path image = fs::canonical("/proc/self/exe", ec);
  const fs::path holder = info.dli_fname[0] == '/' || ec ? fs::path(info.dli_fname) : image;
  struct stat status {};
  if (::stat(holder.c_str(), &status) != 0) return id;
  return fmt::format("{}+image.{}.{}.{:09}", id, status.st_size, status.st_mtim.tv_sec,
                     status.st_mtim.tv_nsec);
}

ResultCache::ResultCache(fs::path root,
                         std::string build,
                         std::function<void(const std::string&)> warn)
    : root_(std::move(root)), build_(std::move(build)), warn_(std::move(warn)) {}

fs::path ResultCache::entry_file(const nlohmann::json& key) const {
  return root_ / kRunsFolder / fmt::format("{:016x}.json", fnv1a64(key.dump()));
}

std::optional<nlohmann::json> ResultCache::load(const nlohmann::json& key) const {
  if (root_.empty()) return std::nullopt;
  auto entry = read_entry(entry_file(key));
  if (!entry || (*entry)["build"] != build_ || (*entry)["key"] != key) return std::nullopt;
  return std::move((*entry)["value"]);
}

void ResultCache::store(const nlohmann::json& key, const nlohmann::json& value) {
  if (!writable()) return;
  const nlohmann::json entry{
      {"format", kFormat}, {"build", build_}, {"key", key}, {"value", value}};
  const fs::path file = entry_file(key);
  std::string problem;
  try {
    std::error_code ec;
    fs::create_directories(file.parent_path(), ec);
    if (ec) {
      problem = fmt::format("cannot create {}: {}", file.parent_path().string(), ec.message());
    } else {
      write_file_atomically_shared(file, entry.dump(1) + "\n");
    }
  } catch (const std::exception& err) {
    problem = err.what();
  }
  if (problem.empty()) return;
  const std::lock_guard lock(mutex_);
  if (disabled_) return;
  disabled_ = true;
  if (warn_) {
    warn_(
        fmt::format("result cache {} not writable ({}): results are not cached "
                    "(set CORLAB_CACHE_DIR to a writable directory)",
                    root_.string(), problem));
  }
}

bool ResultCache::writable() const {
  const std::lock_guard lock(mutex_);
  return !root_.empty() && !disabled_;
}

std::vector<CacheEntry> list_cache(const fs::path& root) {
  std::vector<CacheEntry> out;
  std::error_code ec;
  for (const auto& item : fs::directory_iterator(root / kRunsFolder, ec)) {
    const std::string name = item.path().filename().string();
    if (!is_entry_name(name)) continue;
    CacheEntry entry;
    entry.file = item.path();
    entry.bytes = item.file_size(ec);
    if (ec) entry.bytes = 0;
    if (auto parsed = read_entry(item.path())) {
      entry.readable = true;
      entry.build = (*parsed)["build"].get<std::string>();
      entry.key = (*parsed)["key"].dump();
      entry.value = (*parsed)["value"].dump();
    }
    out.push_back(std::move(entry));
  }
  std::sort(out.begin(), out.end(),
            [](const CacheEntry& a, const CacheEntry& b) { return a.file < b.file; });
  return out;
}

std::size_t clear_cache(const fs::path& root, bool other_builds_only, const std::string& build) {
  std::size_t removed = 0;
  const auto remove = [&removed](const fs::path& file) {
    std::error_code ec;
    if (fs::remove(file, ec)) ++removed;
    if (ec && ec != std::errc::no_such_file_or_directory) {
      throw std::runtime_error(fmt::format("cannot remove {}: {}", file.string(), ec.message()));
    }
  };
  for (const CacheEntry& entry : list_cache(root)) {
    if (!other_builds_only || !entry.readable || entry.build != build) remove(entry.file);
  }
  std::error_code ec;
  const auto now = fs::file_time_type::clock::now();
  for (const auto& item : fs::directory_iterator(root / kRunsFolder, ec)) {
    if (!is_temporary_name(item.path().filename().string())) continue;
    std::error_code time_ec;
    const auto time = fs::last_write_time(item.path(), time_ec);
    if (!time_ec && now - time > kStaleTemporary) remove(item.path());
  }
  return removed;
}

}  // namespace corlab::study
