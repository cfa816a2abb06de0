// The dataset's sweep spec (dataset_spec.hpp): the committed studies/dataset/fe_restitution.toml
// is what the design writes.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dataset/dataset_spec.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "corlab/core/error.hpp"
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

// Issue 42: a path given to --out holding a line break and a [grid] stays in the header comment,
// escaped; the spec still holds the design's cases only.
TEST(DatasetSpec, TheCommandIsOneCommentLine) {
  DatasetDesign design;
  design.points = 2;
  const std::string text = dataset_spec_toml(
      design,
      "corlab dataset design --out x\n[grid]\n\"impact.velocity\" = [1.0, 2.0, 3.0]\r\x7f\xff#");
  EXPECT_NE(
      text.find("#   corlab dataset design --out x\\n[grid]\\n\"impact.velocity\" = [1.0, 2.0, "
                "3.0]\\r\\x7f\\xff#\n"),
      std::string::npos)
      << text;
  const study::SweepSpec spec = study::parse_sweep_spec(text, "design.toml");
  EXPECT_EQ(spec.run_count(), 2u);
  EXPECT_TRUE(spec.grid.empty());
}

TEST(DatasetSpec, PointsWithinTheSweepsCap) {
  for (const std::size_t n : {std::size_t{0}, study::kMaxRunsLimit + 1, ~std::size_t{0}}) {
    EXPECT_THROW(validate_design_points(n, "--points"), InputError) << n;
  }
  EXPECT_NO_THROW(validate_design_points(study::kMaxRunsLimit, "--points"));
}

}  // namespace
}  // namespace corlab::dataset
