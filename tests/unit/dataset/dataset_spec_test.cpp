// The dataset's sweep spec (dataset_spec.hpp): the committed studies/dataset/fe_restitution.toml
// is what the design writes.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dataset/dataset_spec.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "corlab/study/sweep_spec.hpp"

namespace corlab::dataset {
namespace {

// Checks that studies/dataset/<name>.toml is what `command` writes, and that it parses.
void expect_committed_spec(const DatasetDesign& design, const std::string& command) {
  const std::string path = "studies/dataset/" + design.name + ".toml";
  std::ifstream in(std::string(CORLAB_SOURCE_DIR) + "/" + path, std::ios::binary);
  ASSERT_TRUE(in) << path << " missing";
  std::ostringstream text;
  text << in.rdbuf();
  const std::string expected = dataset_spec_toml(design, command);
  EXPECT_TRUE(text.str() == expected) << "regenerate: " << command;
  const study::SweepSpec spec = study::parse_sweep_spec(expected, path);
  EXPECT_EQ(spec.run_count(), design.points);
}

TEST(DatasetSpec, CommittedSpecIsWhatTheDesignWrites) {
  expect_committed_spec(DatasetDesign{},
                        "corlab dataset design --out studies/dataset/fe_restitution.toml");
}

TEST(DatasetSpec, CommittedPairSpecIsWhatTheDesignWrites) {
  expect_committed_spec(
      pair_design(),
      "corlab dataset design --box pairs --out studies/dataset/fe_restitution_pairs.toml");
}

}  // namespace
}  // namespace corlab::dataset
