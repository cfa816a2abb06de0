// The data-directory rule (data_directory.cpp): $CORLAB_DATA_DIR, else the installed copy, else
// the source tree; the study specs' folder. Where an installed corlab finds its data from any
// prefix is checked by installing it (tests/regression/install_test.sh).
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "corlab/materials/material_database.hpp"
#include "support/scratch_files.hpp"

namespace corlab {
namespace {

// Sets CORLAB_DATA_DIR (nullptr: unsets it) for one scope, then puts back what was there.
class DataDirEnvironment {
 public:
  explicit DataDirEnvironment(const char* value) {
    if (const char* old = std::getenv("CORLAB_DATA_DIR")) saved_ = old;
    if (value != nullptr) {
      ::setenv("CORLAB_DATA_DIR", value, 1);
    } else {
      ::unsetenv("CORLAB_DATA_DIR");
    }
  }
  ~DataDirEnvironment() {
    if (saved_) {
      ::setenv("CORLAB_DATA_DIR", saved_->c_str(), 1);
    } else {
      ::unsetenv("CORLAB_DATA_DIR");
    }
  }
  DataDirEnvironment(const DataDirEnvironment&) = delete;
  DataDirEnvironment& operator=(const DataDirEnvironment&) = delete;

 private:
  std::optional<std::string> saved_;
};

TEST(DataDirectory, TheEnvironmentComesFirst) {
  const auto installed = test::fresh_dir("installed");
  test::spit(installed / "materials.toml", "");
  const DataDirEnvironment env("/tmp/corlab-data-test");
  EXPECT_EQ(data_directory(), std::filesystem::path("/tmp/corlab-data-test"));
  EXPECT_EQ(data_directory(installed), std::filesystem::path("/tmp/corlab-data-test"));
}

TEST(DataDirectory, UnsetOrEmptyTakesTheInstalledCopyElseTheSourceTree) {
  const auto installed = test::fresh_dir("installed");
  for (const char* value : {static_cast<const char*>(nullptr), ""}) {
    SCOPED_TRACE(value == nullptr ? "unset" : "empty");
    const DataDirEnvironment env(value);
    EXPECT_EQ(data_directory(), std::filesystem::path(CORLAB_DATA_DIR));
    // an installed directory without materials.toml is no copy
    EXPECT_EQ(data_directory(installed), std::filesystem::path(CORLAB_DATA_DIR));
    EXPECT_EQ(data_directory(installed / "missing"), std::filesystem::path(CORLAB_DATA_DIR));
    test::spit(installed / "materials.toml", "");
    EXPECT_EQ(data_directory(installed), installed);
    std::filesystem::remove(installed / "materials.toml");
  }
}

TEST(DataDirectory, ABuildTreeHasNoInstalledCopy) {
  // This test program runs from build/tests/, where no share/corlab lies next to the code.
  EXPECT_TRUE(installed_data_directory().empty()) << installed_data_directory();
  const DataDirEnvironment env(nullptr);
  EXPECT_EQ(data_directory(), std::filesystem::path(CORLAB_DATA_DIR));
  EXPECT_EQ(studies_directory(), std::filesystem::path(CORLAB_STUDIES_DIR));
  EXPECT_TRUE(std::filesystem::is_regular_file(studies_directory() / "paper" / "table2.toml"));
}

}  // namespace
}  // namespace corlab
