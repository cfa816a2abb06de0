// Sweep progress (progress.hpp): the ETA, the duration and progress texts, plain lines when the
// output is not a terminal; the whole job's time left from its runs' estimated costs.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/study/progress.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace corlab::study {
namespace {

TEST(Progress, EtaAndText) {
  EXPECT_LT(eta_seconds(-1.0, 10, 2), 0.0);
  EXPECT_EQ(eta_seconds(3.0, 10, 2), 15.0);
  EXPECT_EQ(eta_seconds(3.0, 3, 2), 6.0);
  EXPECT_EQ(eta_seconds(3.0, 0, 2), 0.0);
  EXPECT_EQ(format_duration(-1), "--");
  EXPECT_EQ(format_duration(12.4), "12s");
  EXPECT_EQ(format_duration(185), "3m05s");
  EXPECT_EQ(format_duration(3720), "1h02m");
  const std::string text = progress_text(6, 12, 185, 185, 1);
  EXPECT_NE(text.find("6/12"), std::string::npos) << text;
  EXPECT_NE(text.find(" 50%"), std::string::npos) << text;
  EXPECT_NE(text.find("elapsed 3m05s"), std::string::npos) << text;
  EXPECT_NE(text.find("ETA 3m05s"), std::string::npos) << text;
  EXPECT_NE(text.find("(1 failed)"), std::string::npos) << text;
}

TEST(Progress, PlainLinesWhenNotATerminal) {
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  ProgressBar bar(file, 4, 2, /*terminal=*/0);
  bar.update(0, 0, -1.0, true);
  bar.update(1, 0, 1.0);  // throttled: not drawn
  bar.update(2, 0, 1.0);  // throttled
  bar.finish();
  std::rewind(file);
  std::string text;
  for (int c; (c = std::fgetc(file)) != EOF;) text += static_cast<char>(c);
  std::fclose(file);
  EXPECT_EQ(text.find('\r'), std::string::npos);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 2) << text;
  EXPECT_NE(text.find("2/4"), std::string::npos) << text;
}

std::string read_all(std::FILE* file) {
  std::rewind(file);
  std::string text;
  for (int c; (c = std::fgetc(file)) != EOF;) text += static_cast<char>(c);
  return text;
}

TEST(WorkProgress, RemainingSecondsIsTheCostLeftAtTheMeasuredRate) {
  // 30 of 120 cost units done here in 60 s: 2 s per unit, 90 units left.
  EXPECT_DOUBLE_EQ(remaining_seconds(90.0, 30.0, 60.0), 180.0);
  // Units found done on disk shorten what is left but are not part of the rate.
  EXPECT_DOUBLE_EQ(remaining_seconds(120.0 - 30.0 - 50.0, 30.0, 60.0), 80.0);
  EXPECT_LT(remaining_seconds(90.0, 0.0, 60.0), 0.0);  // nothing done yet: unknown
  EXPECT_LT(remaining_seconds(90.0, 30.0, 0.0), 0.0);
  EXPECT_EQ(remaining_seconds(0.0, 0.0, 0.0), 0.0);  // nothing left
  EXPECT_EQ(remaining_seconds(-1e-9, 30.0, 60.0), 0.0);
}

TEST(WorkProgress, TextShowsTheWholeJobAndTheStage) {
  const std::string text = work_progress_text(0.34, "table2", 60, 165, 130, 245);
  EXPECT_NE(text.find(" 34%"), std::string::npos) << text;
  EXPECT_NE(text.find("table2 60/165"), std::string::npos) << text;
  EXPECT_NE(text.find("elapsed 2m10s"), std::string::npos) << text;
  EXPECT_NE(text.find("left 4m05s"), std::string::npos) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '#'), 8) << text;  // 0.34 x 24
  EXPECT_NE(work_progress_text(0.0, "a", 0, 1, 0, -1).find("left --"), std::string::npos);
  EXPECT_NE(work_progress_text(1.7, "a", 1, 1, 0, 0).find("100%"), std::string::npos);
}

TEST(WorkProgress, PlainLinesCountTheCostDoneOnDiskAndHere) {
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  {
    WorkProgress progress(file, 100.0, /*terminal=*/0);
    progress.stage("first", 5, 1, 40.0);  // 1 run, 40 of 100, on disk already: drawn at once
    progress.log("a line");
    progress.done(10.0);  // throttled: no line
    progress.done(10.0);
    progress.finish();  // 60 of 100
  }
  const std::string text = read_all(file);
  std::fclose(file);
  EXPECT_EQ(text.find('\r'), std::string::npos) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 3) << text;
  EXPECT_NE(text.find(" 40%  first 1/5"), std::string::npos) << text;
  EXPECT_NE(text.find("a line\n"), std::string::npos) << text;
  EXPECT_NE(text.find(" 60%  first 3/5"), std::string::npos) << text;
}

TEST(WorkProgress, NothingStartedPrintsNothing) {
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  {
    WorkProgress progress(file, 100.0, /*terminal=*/1);
    progress.finish();
  }
  EXPECT_EQ(read_all(file), "");
  std::fclose(file);
}

}  // namespace
}  // namespace corlab::study
