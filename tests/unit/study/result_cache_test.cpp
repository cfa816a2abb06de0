// The result cache (result_cache.hpp): keying, builds, corrupted entries, concurrent writers.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/study/result_cache.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "corlab/version.hpp"
#include "support/scratch_files.hpp"

namespace corlab::study {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json run_key(double velocity) {
  return {{"config", {{"impact", {{"velocity", velocity}}}, {"sphere", {{"E", 210e9}}}}}};
}

TEST(ResultCache, TheSameKeyHitsAChangedKeyMisses) {
  const fs::path root = test::fresh_path("cache");
  ResultCache cache(root, "build-a");
  EXPECT_FALSE(cache.load(run_key(1.0)));
  cache.store(run_key(1.0), {{"e", 0.8}});
  ASSERT_TRUE(cache.load(run_key(1.0)));
  EXPECT_EQ((*cache.load(run_key(1.0)))["e"], 0.8);
  EXPECT_FALSE(cache.load(run_key(1.0 + 1e-15)));  // one bit of one key
  json other = run_key(1.0);
  other["config"]["sphere"]["E"] = 211e9;
  EXPECT_FALSE(cache.load(other));
  EXPECT_NE(cache.entry_file(other), cache.entry_file(run_key(1.0)));
  fs::remove_all(root);
}

TEST(ResultCache, AnEntryOfAnotherBuildIsAMissAndIsReplaced) {
  const fs::path root = test::fresh_path("cache");
  ResultCache old_build(root, "0.5.0+git.aaaa");
  old_build.store(run_key(2.0), {{"e", 0.5}});
  ResultCache new_build(root, "0.5.0+git.bbbb");
  EXPECT_FALSE(new_build.load(run_key(2.0)));
  new_build.store(run_key(2.0), {{"e", 0.6}});
  EXPECT_EQ((*new_build.load(run_key(2.0)))["e"], 0.6);
  EXPECT_FALSE(old_build.load(run_key(2.0)));
  fs::remove_all(root);
}

TEST(ResultCache, ACorruptedOrForeignEntryIsAMissThenRecomputed) {
  const fs::path root = test::fresh_path("cache");
  ResultCache cache(root, "b");
  cache.store(run_key(3.0), {{"e", 0.7}});
  const fs::path file = cache.entry_file(run_key(3.0));
  const std::string whole = test::slurp(file);
  for (const std::string& bad :
       {whole.substr(0, whole.size() / 2), std::string("\0\0\0", 3), std::string("[]"),
        json{{"format", "corlab result cache 1"},
             {"build", "b"},
             {"key", run_key(4.0)},
             {"value", {{"e", 0.1}}}}
            .dump()}) {
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bad;
    EXPECT_FALSE(cache.load(run_key(3.0))) << bad;
    EXPECT_EQ(list_cache(root).size(), 1U);
  }
  cache.store(run_key(3.0), {{"e", 0.7}});
  EXPECT_EQ((*cache.load(run_key(3.0)))["e"], 0.7);
  fs::remove_all(root);
}

TEST(ResultCache, ConcurrentWritersOfTheSameAndOtherEntries) {
  const fs::path root = test::fresh_path("cache");
  constexpr int kWriters = 2;
  constexpr int kRounds = 100;
  std::vector<pid_t> children;
  for (int w = 0; w < kWriters; ++w) {
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      ResultCache cache(root, "b");
      for (int i = 0; i < kRounds; ++i) {
        cache.store(run_key(10.0), {{"writer", w}, {"round", i}});   // the same entry
        cache.store(run_key(100.0 * (w + 1) + i), {{"writer", w}});  // entries of its own
      }
      ::_exit(cache.writable() ? 0 : 1);
    }
    children.push_back(pid);
  }
  // Meanwhile every read of the shared entry is a whole entry of one writer, or a miss.
  ResultCache reader(root, "b");
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    if (const auto value = reader.load(run_key(10.0))) {
      ++hits;
      EXPECT_TRUE((*value)["writer"] == 0 || (*value)["writer"] == 1);
    }
  }
  for (const pid_t pid : children) {
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  }
  EXPECT_TRUE(reader.load(run_key(10.0)));
  for (int w = 0; w < kWriters; ++w) {
    for (int i = 0; i < kRounds; ++i) {
      ASSERT_TRUE(reader.load(run_key(100.0 * (w + 1) + i))) << w << " " << i;
    }
  }
  // One entry per key and no temporary left behind.
  EXPECT_EQ(list_cache(root).size(), 1U + kWriters * kRounds);
  for (const auto& item : fs::directory_iterator(root / "runs")) {
    EXPECT_EQ(item.path().extension(), ".json") << item.path();
  }
  fs::remove_all(root);
}

TEST(ResultCache, AnUnwritableDirectoryWarnsOnceAndStoresNothing) {
  const fs::path dir = test::fresh_dir("cache");
  const fs::path root = dir / "a_file";
  std::ofstream(root) << "not a directory";
  std::vector<std::string> warnings;
  ResultCache cache(root, "b", [&warnings](const std::string& w) { warnings.push_back(w); });
  cache.store(run_key(1.0), {{"e", 0.8}});
  cache.store(run_key(2.0), {{"e", 0.8}});
  ASSERT_EQ(warnings.size(), 1U);
  EXPECT_NE(warnings[0].find("not writable"), std::string::npos) << warnings[0];
  EXPECT_FALSE(cache.writable());
  EXPECT_FALSE(cache.load(run_key(1.0)));
  ResultCache none({}, "b");
  none.store(run_key(1.0), {{"e", 0.8}});
  EXPECT_FALSE(none.writable());
  fs::remove_all(dir);
}

TEST(ResultCache, ListAndClearByBuild) {
  const fs::path root = test::fresh_path("cache");
  ResultCache a(root, "a");
  ResultCache b(root, "b");
  a.store(run_key(1.0), {{"e", 0.8}});
  b.store(run_key(2.0), {{"e", 0.7}});
  fs::create_directories(root / "runs" / "keep");  // not an entry: never listed nor removed
  std::ofstream(root / "runs" / "notes.txt") << "mine";
  const auto entries = list_cache(root);
  ASSERT_EQ(entries.size(), 2U);
  EXPECT_TRUE(entries[0].readable && entries[0].bytes > 0);
  EXPECT_EQ(clear_cache(root, true, "b"), 1U);
  EXPECT_FALSE(a.load(run_key(1.0)));
  EXPECT_TRUE(b.load(run_key(2.0)));
  EXPECT_EQ(clear_cache(root, false, "b"), 1U);
  EXPECT_TRUE(list_cache(root).empty());
  EXPECT_TRUE(fs::exists(root / "runs" / "notes.txt"));
  EXPECT_EQ(clear_cache(test::fresh_path("none"), false, "b"), 0U);
  fs::remove_all(root);
}

TEST(ResultCache, TheDirectoryFollowsTheEnvironment) {
  const auto saved = [](const char* name) {
    const char* v = std::getenv(name);
    return v == nullptr ? std::optional<std::string>() : std::optional<std::string>(v);
  };
  const auto dir = saved("CORLAB_CACHE_DIR");
  const auto xdg = saved("XDG_CACHE_HOME");
  const auto home = saved("HOME");
  ::setenv("CORLAB_CACHE_DIR", "/c", 1);
  ::setenv("XDG_CACHE_HOME", "/x", 1);
  ::setenv("HOME", "/h", 1);
  EXPECT_EQ(default_cache_directory(), fs::path("/c"));
  ::unsetenv("CORLAB_CACHE_DIR");
  EXPECT_EQ(default_cache_directory(), fs::path("/x/corlab"));
  ::setenv("XDG_CACHE_HOME", "", 1);
  EXPECT_EQ(default_cache_directory(), fs::path("/h/.cache/corlab"));
  ::unsetenv("HOME");
  EXPECT_TRUE(default_cache_directory().empty());
  const auto restore = [](const char* name, const std::optional<std::string>& v) {
    if (v) {
      ::setenv(name, v->c_str(), 1);
    } else {
      ::unsetenv(name);
    }
  };
  restore("CORLAB_CACHE_DIR", dir);
  restore("XDG_CACHE_HOME", xdg);
  restore("HOME", home);
}

TEST(ResultCache, TheBuildIdNamesTheBuild) {
  EXPECT_TRUE(cache_build_id().starts_with(std::string(build_id())));
}

}  // namespace
}  // namespace corlab::study
