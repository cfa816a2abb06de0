// Dataset export from a sweep directory written with synthetic results: rows in design order,
// dimensionless inputs, inclusion rule, columns.json matching the header, provenance lines.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dataset/dataset_export.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "corlab/core/error.hpp"
#include "corlab/dataset/dataset_spec.hpp"
#include "corlab/study/results_table.hpp"
#include "support/scratch_files.hpp"

namespace corlab::dataset {
namespace {

namespace fs = std::filesystem;

using test::fresh_dir;

// A sweep directory of the 8-point design whose points 1, 2, 4, 5, 6 finished (out of order):
// 2 clean, 4 with a 1 % energy balance, 5 not separated, 6 with a hourglass flag.
fs::path synthetic_sweep() {
  const fs::path dir = fresh_dir("sweep");
  const std::string text =
      dataset_spec_toml(DatasetDesign{.name = "t", .points = 8, .box = {}}, "test");
  test::spit(dir / "spec.toml", text);
  const study::SweepSpec spec = study::parse_sweep_spec(text, "spec.toml");
  const auto runs = spec.expand();
  const auto keys = spec.swept_keys();
  study::CsvAppender csv(dir / "results.csv", study::results_header(keys));
  for (const std::size_t i : {6U, 2U, 1U, 5U, 4U}) {
    fem::ImpactResult r;
    r.e = 0.5 + 0.01 * static_cast<double>(i);
    r.e_error = 0.001;
    r.status = i == 5 ? fem::RunStatus::kNotSeparated : fem::RunStatus::kSeparated;
    r.energy_balance_error = i == 4 ? 0.01 : 1e-4;
    r.energy_initial = 1.0;
    if (i == 6) r.suspect = "hourglass energy 0.8 % of the initial energy (limit 0.5 %)";
    r.wall_s = 2.0;
    std::vector<std::string> values;
    for (const auto& key : keys) {
      for (const auto& [k, v] : runs[i].settings) {
        if (k == key) values.push_back(v);
      }
    }
    csv.append(study::result_row(runs[i].id, values, runs[i].config, &r, "", r.wall_s));
  }
  return dir;
}

TEST(DatasetExport, RowsInDesignOrderWithInputsAndTheInclusionRule) {
  const fs::path out = fresh_dir("out");
  const ExportSummary s = export_dataset(synthetic_sweep(), out);
  EXPECT_EQ(s.design_points, 8U);
  EXPECT_EQ(s.rows, 5U);
  EXPECT_EQ(s.included, 2U);
  EXPECT_EQ(s.excluded.at("status not_separated"), 1U);
  EXPECT_EQ(s.excluded.at("energy balance error"), 1U);
  EXPECT_EQ(s.excluded.at("hourglass energy"), 1U);
  EXPECT_DOUBLE_EQ(s.cpu_s, 10.0);
  EXPECT_NEAR(s.e_error_max, 0.001 / 0.51, 1e-15);  // included: points 1 (e 0.51) and 2 (0.52)

  const study::ResultsTable t = study::read_results(out / "dataset.csv");
  EXPECT_EQ(t.numbers("design_index"), (std::vector<double>{1, 2, 4, 5, 6}));
  EXPECT_EQ(t.text("included"),
            (std::vector<std::string>{"true", "true", "false", "false", "false"}));
  const auto design = design_points(DatasetDesign{.name = "t", .points = 8, .box = {}});
  const auto k2 = t.numbers("k2");
  const auto ratio = t.numbers("velocity_ratio");
  for (std::size_t r = 0; r < t.size(); ++r) {
    const auto& p = design[static_cast<std::size_t>(t.numbers("design_index")[r])].point;
    EXPECT_NEAR(k2[r] / p.k2, 1.0, 1e-12);
    EXPECT_NEAR(ratio[r] / p.velocity_ratio, 1.0, 1e-12);
  }
  // columns.json describes exactly the header, each with a unit and a description.
  const auto columns = nlohmann::json::parse(std::ifstream(out / "columns.json"));
  ASSERT_EQ(columns.size(), t.columns().size());
  for (std::size_t c = 0; c < columns.size(); ++c) {
    EXPECT_EQ(columns[c]["name"], t.columns()[c]);
    EXPECT_FALSE(columns[c]["unit"].get<std::string>().empty()) << t.columns()[c];
    EXPECT_FALSE(columns[c]["description"].get<std::string>().empty()) << t.columns()[c];
  }
  // One provenance line per row, with the full config.
  std::ifstream configs(out / "configs.jsonl");
  std::string line;
  std::size_t lines = 0;
  while (std::getline(configs, line)) {
    const auto j = nlohmann::json::parse(line);
    EXPECT_EQ(j["case_id"], t.text("case_id")[lines]);
    EXPECT_TRUE(j["config"].contains("solver"));
    ++lines;
  }
  EXPECT_EQ(lines, t.size());
}

TEST(DatasetExport, RefusesResultsOfAnotherSpec) {
  const fs::path sweep = synthetic_sweep();
  test::spit(sweep / "spec.toml",
             dataset_spec_toml(DatasetDesign{.name = "t", .points = 2, .box = {}}, "test"));
  try {
    (void)export_dataset(sweep, fresh_dir("foreign"));
    FAIL() << "exported results of another spec";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("case_id"), std::string::npos) << err.what();
  }
}

}  // namespace
}  // namespace corlab::dataset
