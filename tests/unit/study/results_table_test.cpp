// results.csv: CSV quoting, number round trip, appender + reader, resume preparation.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/study/results_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <random>
#include <sstream>

#include "corlab/core/error.hpp"
#include "support/scratch_files.hpp"

namespace corlab::study {
namespace {

namespace fs = std::filesystem;

using test::fresh_dir;
using test::slurp;
using test::spit;

TEST(Csv, QuotesWhatNeedsQuotingAndSplitsBack) {
  const std::vector<std::string> fields{"plain",    "a,b",          "say \"hi\"", "",
                                        " padded ", "E=1e9,nu=0.3", "line\nbreak"};
  const std::string line = csv_line(fields);
  EXPECT_EQ(line.find('\n'), std::string::npos);
  EXPECT_EQ(line, "plain,\"a,b\",\"say \"\"hi\"\"\",,\" padded \",\"E=1e9,nu=0.3\",line break");
  auto back = split_csv_line(line);
  ASSERT_EQ(back.size(), fields.size());
  for (std::size_t i = 0; i + 1 < fields.size(); ++i) EXPECT_EQ(back[i], fields[i]);
  EXPECT_EQ(back.back(), "line break");
  EXPECT_THROW(split_csv_line("a,\"unterminated"), InputError);
}

TEST(Csv, NumbersRoundTripBitwise) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> exponent(-300.0, 300.0);
  for (int i = 0; i < 2000; ++i) {
    const double value = std::pow(10.0, exponent(rng)) * (i % 2 ? -1.0 : 1.0) / 3.0;
    const std::string text = format_number(value);
    double back = 0.0;
    std::istringstream(text) >> back;
    const ResultsTable table({"x"}, {{text}});
    const double parsed = table.numbers("x")[0];
    EXPECT_EQ(std::memcmp(&parsed, &value, sizeof value), 0) << text;
  }
  // No value is an empty cell, read back as NaN; "nan" written by earlier versions still reads.
  EXPECT_EQ(format_number(std::nan("")), "");
  EXPECT_TRUE(std::isnan(ResultsTable({"x"}, {{""}}).numbers("x")[0]));
  EXPECT_TRUE(std::isnan(ResultsTable({"x"}, {{"nan"}}).numbers("x")[0]));
}

TEST(ResultsTable, HeaderAndRowLayout) {
  const auto header = results_header({"sphere.material", "impact.velocity"});
  EXPECT_EQ(header.front(), "case_id");
  EXPECT_EQ(header[1], "status");
  EXPECT_EQ(header[2], "sphere.material");
  EXPECT_EQ(header.back(), "error");
  EXPECT_EQ(header.size(), 2 + 2 + result_columns().size() + 1);

  fem::ImpactConfig config;
  config.impact.velocity = 5.0;
  fem::ImpactResult result;
  result.e = 0.5;
  result.separated = true;
  result.status = fem::RunStatus::kSeparated;
  result.elements = 12;
  result.steps = 345;
  result.wall_s = 1.25;
  const auto row = result_row("c1", {"steel", "5"}, config, &result, "", 9.0);
  ASSERT_EQ(row.size(), header.size());
  const ResultsTable table(header, {row});
  EXPECT_EQ(table.cell(0, "status"), "ok");
  EXPECT_EQ(table.numbers("e")[0], 0.5);
  EXPECT_EQ(table.numbers("steps")[0], 345.0);
  EXPECT_EQ(table.numbers("wall_s")[0], 1.25);
  // Derived groups of Ma et al. 2023: E* (eq. 3), k1 = E*/(rho v^2) (eq. 5), k2 = sy/E* (eq. 6).
  const double e_star = 1.0 / (2.0 * (1.0 - 0.09) / 210e9);
  EXPECT_NEAR(table.numbers("E_star")[0], e_star, 1e-6 * e_star);
  EXPECT_NEAR(table.numbers("k1")[0], e_star / (7850.0 * 25.0), 1e-9 * e_star / 7850.0);
  EXPECT_NEAR(table.numbers("k2")[0], 500e6 / e_star, 1e-15);
  EXPECT_EQ(table.numbers("velocity")[0], 5.0);
  EXPECT_EQ(table.numbers("sigma_y")[0], 500e6);

  result.separated = false;
  result.status = fem::RunStatus::kNotSeparated;
  EXPECT_EQ(result_row("c1", {"s", "5"}, config, &result, "", 0)[1], "not_separated");
  result.status = fem::RunStatus::kElementInverted;
  result.status_detail = "element 3 inverted at t = 1e-05 s (step 7)";
  const auto inverted = result_row("c1", {"s", "5"}, config, &result, "", 0);
  EXPECT_EQ(inverted[1], "element_inverted");
  EXPECT_EQ(inverted.back(), result.status_detail);
  const auto failed = result_row("c2", {"steel", "5"}, config, nullptr, "boom, badly", 2.5);
  ASSERT_EQ(failed.size(), header.size());
  const ResultsTable failed_table(header, {failed});
  EXPECT_EQ(failed_table.cell(0, "status"), "failed");
  EXPECT_EQ(failed_table.cell(0, "error"), "boom, badly");
  EXPECT_EQ(failed_table.cell(0, "e"), "");
  EXPECT_EQ(failed_table.numbers("wall_s")[0], 2.5);
  EXPECT_TRUE(std::isnan(failed_table.numbers("e")[0]));
}

TEST(ResultsTable, AppendThenReadByColumnName) {
  const fs::path dir = fresh_dir("append");
  const fs::path csv = dir / "results.csv";
  const std::vector<std::string> header{"case_id", "status", "sphere.material", "e", "error"};
  {
    CsvAppender out(csv, header);
    out.append({"c1", "ok", "E=1e9,nu=0.3,rho=1000", "0.5", ""});
    out.append({"c2", "failed", "steel", "", "it broke, \"badly\""});
  }
  {
    CsvAppender again(csv, header);  // reopening does not repeat the header
    again.append({"c0", "ok", "steel", "0.25", ""});
  }
  const ResultsTable table = read_results(csv);
  EXPECT_EQ(table.columns(), header);
  ASSERT_EQ(table.size(), 3u);
  EXPECT_TRUE(table.is_numeric("e"));
  EXPECT_FALSE(table.is_numeric("sphere.material"));
  EXPECT_FALSE(table.is_numeric("error"));
  EXPECT_EQ(table.text("sphere.material")[0], "E=1e9,nu=0.3,rho=1000");
  EXPECT_EQ(table.text("error")[1], "it broke, \"badly\"");
  const auto e = table.numbers("e");
  EXPECT_EQ(e[0], 0.5);
  EXPECT_TRUE(std::isnan(e[1]));
  EXPECT_THROW(table.numbers("sphere.material"), InputError);
  EXPECT_THROW(table.text("nope"), InputError);
  const auto ok = table.where("status", "ok").sorted_by("case_id");
  ASSERT_EQ(ok.size(), 2u);
  EXPECT_EQ(ok.text("case_id"), (std::vector<std::string>{"c0", "c1"}));

  // A cut last line of a sweep's results.csv (killed writer) is dropped, with a note saying so.
  spit(csv, slurp(csv) + "c9,ok,steel,0.");
  const ResultsTable cut = read_results(csv);
  EXPECT_EQ(cut.size(), 3u);
  ASSERT_EQ(cut.notes().size(), 1u);
  EXPECT_NE(cut.notes()[0].find("line 5: dropped a partial last line"), std::string::npos)
      << cut.notes()[0];
  // A malformed complete line is an error naming the line.
  spit(csv, slurp(csv) + "\nc8,ok\n");
  try {
    read_results(csv);
    FAIL() << "no error";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("line 5"), std::string::npos) << err.what();
  }
}

// issue 12 item 3: a reader never drops or doubles data silently.
TEST(ResultsTable, ALastRowWithoutLineBreakIsData) {
  const fs::path csv = fresh_dir("no_newline") / "r.csv";
  spit(csv, "case_id,status,e,error\nc1,ok,0.5,\nc2,ok,0.25,");
  const ResultsTable table = read_results(csv);
  ASSERT_EQ(table.size(), 2u);
  EXPECT_EQ(table.numbers("e")[1], 0.25);
  EXPECT_TRUE(table.notes().empty());
  spit(csv, "x,y\n1,2\n3,4");  // any CSV, not only a sweep's
  EXPECT_EQ(read_results(csv).numbers("y"), (std::vector<double>{2.0, 4.0}));
}

TEST(ResultsTable, ACutLastLineOfAnyOtherCsvIsAnError) {
  const fs::path csv = fresh_dir("cut") / "r.csv";
  spit(csv, "x,y\n1,2\n3");
  try {
    read_results(csv);
    FAIL() << "no error";
  } catch (const InputError& err) {
    const std::string message = err.what();
    EXPECT_NE(message.find("line 3: must be a complete row of 2 fields"), std::string::npos)
        << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
  spit(csv, "x,y\n1,2\n3,\"cut in a quote");
  EXPECT_THROW(read_results(csv), InputError);
}

TEST(ResultsTable, ARepeatedCaseIsCountedOnceWithANoteOrRefused) {
  const fs::path csv = fresh_dir("dup") / "r.csv";
  // The same case twice (only the timing differs): counted once, and the note says so.
  spit(csv, "case_id,status,e,wall_s,error\nc1,ok,0.5,1.0,\nc2,ok,0.25,1.0,\nc1,ok,0.5,2.0,\n");
  const ResultsTable table = read_results(csv);
  EXPECT_EQ(table.text("case_id"), (std::vector<std::string>{"c1", "c2"}));
  ASSERT_EQ(table.notes().size(), 1u);
  EXPECT_NE(table.notes()[0].find("line 4: case_id 'c1' repeats line 2"), std::string::npos)
      << table.notes()[0];
  // The same case with another e: two studies mixed, refused.
  spit(csv, "case_id,status,e,wall_s,error\nc1,ok,0.5,1.0,\nc1,ok,0.6,1.0,\n");
  try {
    read_results(csv);
    FAIL() << "no error";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("line 3: case_id 'c1' must appear once"),
              std::string::npos)
        << err.what();
  }
}

TEST(ResultsTable, ADuplicateColumnIsAnError) {
  const fs::path csv = fresh_dir("dupcol") / "r.csv";
  spit(csv, "case_id,e,status,e\nc1,0.5,ok,0.6\n");
  try {
    read_results(csv);
    FAIL() << "no error";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what())
                  .find("column 'e': must appear once in the header (columns 2 "
                        "and 4)"),
              std::string::npos)
        << err.what();
  }
}

TEST(ResultsTable, PrepareResumeKeepsACompleteLastRowAndDropsRepeats) {
  const fs::path csv = fresh_dir("resume2") / "results.csv";
  const std::vector<std::string> header{"case_id", "status", "e", "error"};
  spit(csv, "case_id,status,e,error\nc1,ok,0.5,\nc1,ok,0.5,\nc2,ok,0.25,");
  const ExistingResults existing = prepare_resume(csv, header, {"ok"});
  EXPECT_FALSE(existing.dropped_partial_line);
  EXPECT_EQ(existing.rows, 2u);
  EXPECT_EQ(existing.duplicates_dropped, 1u);
  EXPECT_EQ(slurp(csv), "case_id,status,e,error\nc1,ok,0.5,\nc2,ok,0.25,\n");
}

TEST(ResultsTable, PrepareResumeDropsPartialLineAndUnfinishedRows) {
  const fs::path dir = fresh_dir("resume");
  const fs::path csv = dir / "results.csv";
  const std::vector<std::string> header{"case_id", "status", "e", "error"};
  const std::vector<std::string> keep{"ok", "not_separated"};
  EXPECT_TRUE(prepare_resume(csv, header, keep).status.empty());  // no file yet

  spit(csv,
       "case_id,status,e,error\n"
       "c1,ok,0.5,\n"
       "c2,failed,,boom\n"
       "c3,not_separated,0.1,\n"
       "c4,ok,0.");
  const ExistingResults existing = prepare_resume(csv, header, keep);
  EXPECT_TRUE(existing.dropped_partial_line);
  EXPECT_EQ(existing.rows, 2u);
  EXPECT_EQ(existing.status.count("c1"), 1u);
  EXPECT_EQ(existing.status.count("c2"), 0u);  // failed: rerun
  EXPECT_EQ(existing.status.at("c3"), "not_separated");
  EXPECT_EQ(existing.status.count("c4"), 0u);  // partial: rerun
  EXPECT_EQ(slurp(csv), "case_id,status,e,error\nc1,ok,0.5,\nc3,not_separated,0.1,\n");
  {
    CsvAppender out(csv, header);
    out.append({"c4", "ok", "0.75", ""});
  }
  EXPECT_EQ(read_results(csv).size(), 3u);

  // Another spec's table is refused with one line.
  try {
    prepare_resume(csv, {"case_id", "status", "impact.velocity", "e", "error"}, keep);
    FAIL() << "no error";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("columns differ"), std::string::npos);
  }
}

}  // namespace
}  // namespace corlab::study
