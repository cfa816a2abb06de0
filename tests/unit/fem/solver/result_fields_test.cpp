// The result-field table (result_fields.hpp) drives summary.json and results.csv.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/result_fields.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "corlab/fem/output/impact_output.hpp"
#include "corlab/study/results_table.hpp"

namespace corlab::fem {
namespace {

TEST(ResultFields, NamesAreUniqueAndEveryFieldIsDocumented) {
  std::set<std::string_view> names;
  for (const ResultField& f : result_fields()) {
    EXPECT_TRUE(names.insert(f.name).second) << "duplicate field " << f.name;
    EXPECT_FALSE(f.unit.empty()) << f.name;
    EXPECT_FALSE(f.description.empty()) << f.name;
    EXPECT_NE(f.value, nullptr) << f.name;
    EXPECT_NE(f.outputs, 0) << f.name << " is written nowhere";
    EXPECT_EQ(find_result_field(f.name), &f);
  }
  EXPECT_EQ(find_result_field("no_such_field"), nullptr);
}

TEST(ResultFields, SummaryJsonHoldsExactlyTheSummaryFields) {
  ImpactResult r;
  r.e = 0.53;
  r.steps = 1234567890123LL;
  r.separated = true;
  const auto j = summary_to_json(r, ImpactConfig{});
  std::set<std::string> expected{"units", "config"};
  for (const ResultField& f : result_fields()) {
    if ((f.outputs & kSummary) != 0) expected.insert(std::string(f.name));
  }
  std::set<std::string> keys;
  for (const auto& [key, value] : j.items()) keys.insert(key);
  EXPECT_EQ(keys, expected);
  EXPECT_EQ(j["steps"].get<long long>(), 1234567890123LL);
  EXPECT_TRUE(j["separated"].get<bool>());
  EXPECT_EQ(j["units"]["F_max"], "N");
  EXPECT_EQ(j["units"]["energy_*"], "J");
  EXPECT_FALSE(j["units"].contains("e"));
}

TEST(ResultFields, CsvColumnsAndFailedRowsFollowTheTable) {
  std::vector<std::string> csv_fields;
  for (const ResultField& f : result_fields()) {
    if ((f.outputs & kCsv) != 0) csv_fields.emplace_back(f.name);
  }
  EXPECT_EQ(study::result_columns(), csv_fields);
  const auto header = study::results_header({"impact.velocity"});
  const ImpactConfig config;
  const auto failed = study::result_row("c1", {"5"}, config, nullptr, "boom", 3.5);
  ASSERT_EQ(failed.size(), header.size());
  const study::ResultsTable table(header, {failed});
  // A failed run: result members are empty, the case's own inputs and the wall time are written.
  EXPECT_EQ(table.cell(0, "e"), "");
  EXPECT_EQ(table.cell(0, "steps"), "");
  EXPECT_EQ(table.cell(0, "element_steps_per_s"), "");
  EXPECT_EQ(table.numbers("wall_s")[0], 3.5);
  EXPECT_EQ(table.numbers("velocity")[0], config.impact.velocity);
  EXPECT_TRUE(std::isfinite(table.numbers("k1")[0]));
}

TEST(ResultFields, CsvFieldsDoNotCollideWithTheStructuralColumns) {
  // results.csv has case_id, status (study::row_status), the swept keys and error around the
  // fields: a field written to the CSV must not reuse those names (the reader refuses a column
  // named twice).
  for (const ResultField& f : result_fields()) {
    if ((f.outputs & kCsv) == 0) continue;
    EXPECT_NE(f.name, "case_id");
    EXPECT_NE(f.name, "status") << "a run status goes to the summary; the CSV's is row_status()";
    EXPECT_NE(f.name, "error");
  }
}

TEST(ResultFields, TimingColumnsAreTheMachineDependentOnes) {
  for (const auto& name : study::timing_columns()) {
    const ResultField* f = find_result_field(name);
    ASSERT_NE(f, nullptr) << name;
    EXPECT_TRUE(f->machine_dependent) << name;
  }
  // Timings and the build that ran the case: they differ between two runs of one case.
  EXPECT_EQ(study::timing_columns(),
            (std::vector<std::string>{"wall_s", "element_steps_per_s", "corlab_build"}));
}

TEST(ResultFields, ValuesOfEveryKindBecomeCsvText) {
  EXPECT_EQ(field_text(FieldValue{}), "");
  EXPECT_EQ(field_text(FieldValue{0.1}), "0.1");
  EXPECT_EQ(field_text(FieldValue{std::nan("")}), "");  // no value: an empty cell
  EXPECT_EQ(field_text(FieldValue{-HUGE_VAL}), "-inf");
  EXPECT_EQ(field_text(FieldValue{12345678901LL}), "12345678901");
  EXPECT_EQ(field_text(FieldValue{true}), "true");
  // A text field (a run status or a reason) round-trips through the CSV, commas included.
  const std::string reason = "energy balance 2.1 %, above 1 %";
  EXPECT_EQ(field_text(FieldValue{reason}), reason);
  EXPECT_EQ(study::split_csv_line(study::csv_line({"c1", field_text(FieldValue{reason})}))[1],
            reason);
}

}  // namespace
}  // namespace corlab::fem
