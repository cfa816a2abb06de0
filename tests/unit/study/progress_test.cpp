// Sweep progress (progress.hpp): the ETA, the duration and progress texts, plain lines when the
// output is not a terminal.
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

}  // namespace
}  // namespace corlab::study
