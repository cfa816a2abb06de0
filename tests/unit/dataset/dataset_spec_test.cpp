// The dataset's sweep spec (dataset_spec.hpp): the committed studies/dataset/fe_restitution.toml
// is what the design writes.
#include "corlab/dataset/dataset_spec.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "corlab/study/sweep_spec.hpp"

namespace corlab::dataset {
namespace {

TEST(DatasetSpec, CommittedSpecIsWhatTheDesignWrites) {
  std::ifstream in(CORLAB_SOURCE_DIR "/studies/dataset/fe_restitution.toml", std::ios::binary);
  ASSERT_TRUE(in) << "studies/dataset/fe_restitution.toml missing";
  std::ostringstream text;
  text << in.rdbuf();
  const std::string expected = dataset_spec_toml(
      DatasetDesign{}, "corlab dataset design --out studies/dataset/fe_restitution.toml");
  EXPECT_TRUE(text.str() == expected)
      << "regenerate: corlab dataset design --out studies/dataset/fe_restitution.toml";
  const study::SweepSpec spec = study::parse_sweep_spec(expected, "fe_restitution.toml");
  EXPECT_EQ(spec.run_count(), DatasetDesign{}.points);
}

}  // namespace
}  // namespace corlab::dataset
