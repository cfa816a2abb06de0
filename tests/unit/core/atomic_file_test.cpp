// File replacement (atomic_file.hpp): new content in one step, no temporary left behind.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/core/atomic_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

#include "support/scratch_files.hpp"

namespace corlab {
namespace {

namespace fs = std::filesystem;

TEST(AtomicFile, ReplacesTheContentAndLeavesNoTemporary) {
  const fs::path dir = test::fresh_dir("atomic");
  const fs::path file = dir / "a.json";
  write_file_atomically(file, "first");
  write_file_atomically(file, "second\n");
  EXPECT_EQ(test::slurp(file), "second\n");
  EXPECT_FALSE(fs::exists(dir / "a.json.tmp"));
  EXPECT_THROW(write_file_atomically(dir / "no" / "such" / "dir.json", "x"), std::runtime_error);
  fs::remove_all(dir);
}

TEST(AtomicFile, TheSharedVariantLeavesNoTemporaryEvenWhenItFails) {
  const fs::path dir = test::fresh_dir("atomic");
  const fs::path file = dir / "a.json";
  write_file_atomically_shared(file, "first");
  write_file_atomically_shared(file, "second\n");
  EXPECT_EQ(test::slurp(file), "second\n");
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& item : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1U);
  EXPECT_THROW(write_file_atomically_shared(dir / "no" / "dir.json", "x"), std::runtime_error);
  // A directory in the file's place: the rename fails and the temporary goes.
  fs::create_directories(dir / "d.json" / "x");
  EXPECT_THROW(write_file_atomically_shared(dir / "d.json", "x"), std::runtime_error);
  files = 0;
  for ([[maybe_unused]] const auto& item : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 2U);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace corlab
