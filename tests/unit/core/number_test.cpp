// The one strict number parser (core/number.hpp): what every reader of numbers accepts.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/core/number.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "corlab/core/error.hpp"

namespace corlab {
namespace {

TEST(ParseDouble, ReadsTheWholeTextOrNothing) {
  EXPECT_EQ(parse_double("1e-3"), 1e-3);
  EXPECT_EQ(parse_double("+5"), 5.0);
  EXPECT_EQ(parse_double("-2.5"), -2.5);
  EXPECT_EQ(parse_double(".5"), 0.5);
  EXPECT_FALSE(parse_double(""));
  EXPECT_FALSE(parse_double("+"));
  EXPECT_FALSE(parse_double("-"));
  EXPECT_FALSE(parse_double("+-5"));
  EXPECT_FALSE(parse_double("++5"));
  EXPECT_FALSE(parse_double("5abc"));
  EXPECT_FALSE(parse_double("5 "));  // blanks are the caller's (trim first)
  EXPECT_FALSE(parse_double(" 5"));
  EXPECT_FALSE(parse_double("0x10"));
  EXPECT_FALSE(parse_double("1,5"));
}

TEST(ParseDouble, NonFiniteValuesParseSoThatCallersCanSayWhy) {
  EXPECT_TRUE(std::isnan(*parse_double("nan")));
  EXPECT_TRUE(std::isinf(*parse_double("inf")));
  EXPECT_TRUE(std::isinf(*parse_double("-inf")));
  EXPECT_FALSE(parse_double("1e999"));  // out of range: from_chars reports it, not inf
}

TEST(ParseInteger, ReadsDecimalIntegersOnly) {
  EXPECT_EQ(parse_integer("42"), 42);
  EXPECT_EQ(parse_integer("+7"), 7);
  EXPECT_EQ(parse_integer("-3"), -3);
  EXPECT_FALSE(parse_integer("1.0"));
  EXPECT_FALSE(parse_integer("1e3"));
  EXPECT_FALSE(parse_integer(""));
  EXPECT_FALSE(parse_integer("99999999999999999999"));
}

TEST(ParseFinite, TrimsAndNamesTheFieldInItsError) {
  EXPECT_EQ(parse_finite("sphere.E", "  2e11\t"), 2e11);
  try {
    parse_finite("sphere.E", " nan ");
    FAIL() << "nan accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "sphere.E");
    EXPECT_EQ(e.value(), "nan");
    EXPECT_NE(std::string(e.what()).find("must be a finite number"), std::string::npos);
  }
  EXPECT_THROW(parse_finite("x", "1e400"), InputError);
  EXPECT_THROW(parse_finite("x", ""), InputError);
}

}  // namespace
}  // namespace corlab
