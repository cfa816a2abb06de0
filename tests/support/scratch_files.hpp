// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Scratch directories and whole-file text for the tests (one copy instead of one per test file).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>

namespace corlab::test {

namespace detail {

// "Suite.Test" of the running test ("" outside one), with '/' of parametrised names and anything
// else a file name should not hold replaced by '_'.
inline std::string current_test_name() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  if (info == nullptr) return "";
  std::string name = std::string(info->test_suite_name()) + "." + info->name();
  for (char& c : name) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                       c == '.' || c == '-' || c == '_';
    if (!plain) c = '_';
  }
  return name;
}

}  // namespace detail

/// <tmp>/corlab_<pid>_<Suite.Test>_<name>, with nothing there (what an earlier process of the
/// same pid left is removed): for code under test that creates its own directory. The process id
/// keeps parallel ctest runs apart (ctest -j, and other build trees on the machine); the test's
/// name, the tests of one process.
inline std::filesystem::path fresh_path(std::string_view name) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("corlab_" + std::to_string(::getpid()) + "_" +
                                      detail::current_test_name() + "_" + std::string(name));
  std::filesystem::remove_all(path);
  return path;
}

/// fresh_path(name), created: an empty directory of this test's own.
inline std::filesystem::path fresh_dir(std::string_view name) {
  const std::filesystem::path dir = fresh_path(name);
  std::filesystem::create_directories(dir);
  return dir;
}

/// The whole file as it is on disk ("" if it cannot be read).
inline std::string slurp(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Replaces the file's content with `text`, byte for byte; a file it cannot write fails the test.
inline void spit(const std::filesystem::path& file, std::string_view text) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << text;
  if (!out) ADD_FAILURE() << "cannot write " << file;
}

}  // namespace corlab::test
