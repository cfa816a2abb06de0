// Text helpers (text.hpp, header-only): trim and one_line.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/core/text.hpp"

#include <gtest/gtest.h>

namespace corlab {
namespace {

TEST(Trim, RemovesBlanksAtBothEndsOnly) {
  EXPECT_EQ(trim("  a b \t\r\n"), "a b");
  EXPECT_EQ(trim("x"), "x");
  EXPECT_EQ(trim(" \t "), "");
  EXPECT_EQ(trim(""), "");
  static_assert(trim(" k ") == "k");
}

TEST(OneLine, ReplacesLineBreaksWithBlanks) {
  EXPECT_EQ(one_line("a\nb\r\nc"), "a b  c");
  EXPECT_EQ(one_line("no break"), "no break");
  EXPECT_EQ(one_line(""), "");
}

}  // namespace
}  // namespace corlab
