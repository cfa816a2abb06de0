// Relative errors and their statistics: the definition, what is left out, the signed worst, and
// sums in numpy's order (the values below are numpy 1.24's; a plain running sum differs from
// them in the last bits for n >= 8, which these tests catch).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fit/relative_error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "corlab/core/error.hpp"

namespace corlab::study {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(RelativeError, IsModelMinusReferenceOverReference) {
  const std::vector<double> model = {1.1, 0.5, 2.0, 1.0};
  const std::vector<double> reference = {1.0, 0.4, 0.0, kNaN};
  const std::vector<double> r = relative_errors(model, reference);
  ASSERT_EQ(r.size(), 4U);
  EXPECT_EQ(r[0], (1.1 - 1.0) / 1.0);
  EXPECT_EQ(r[1], (0.5 - 0.4) / 0.4);
  EXPECT_FALSE(std::isfinite(r[2]));  // reference 0
  EXPECT_FALSE(std::isfinite(r[3]));
}

TEST(RelativeError, SizesMustAgree) {
  const std::vector<double> two = {1.0, 2.0};
  const std::vector<double> three = {1.0, 2.0, 3.0};
  try {
    relative_error_stats(two, three);
    FAIL() << "no error for 2 model values against 3 references";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "model values");
    EXPECT_NE(e.constraint().find("(3)"), std::string::npos) << e.what();
  }
}

TEST(RelativeErrorStats, LeavesOutWhatIsNotFiniteAndKeepsTheWorstsSign) {
  const std::vector<double> r = {0.01, kNaN, -0.03, kInf, 0.02, -kInf};
  const RelativeErrorStats s = relative_error_stats(r);
  EXPECT_EQ(s.n, 3U);
  EXPECT_EQ(s.worst, -0.03);
  EXPECT_EQ(s.worst_index, 2U);
  // Fewer than 8 values: summed in turn, as written here.
  EXPECT_EQ(s.rms, std::sqrt((0.01 * 0.01 + -0.03 * -0.03 + 0.02 * 0.02) / 3.0));
  EXPECT_EQ(s.bias, (0.01 + -0.03 + 0.02) / 3.0);
}

TEST(RelativeErrorStats, FirstOfEqualMagnitudesIsTheWorst) {
  const std::vector<double> r = {0.02, -0.02, 0.01};
  const RelativeErrorStats s = relative_error_stats(r);
  EXPECT_EQ(s.worst, 0.02);
  EXPECT_EQ(s.worst_index, 0U);
}

TEST(RelativeErrorStats, NothingFiniteGivesNaN) {
  for (const std::vector<double>& r : {std::vector<double>{}, std::vector<double>{kNaN, kInf}}) {
    const RelativeErrorStats s = relative_error_stats(r);
    EXPECT_EQ(s.n, 0U);
    EXPECT_TRUE(std::isnan(s.rms));
    EXPECT_TRUE(std::isnan(s.worst));
    EXPECT_TRUE(std::isnan(s.bias));
  }
}

TEST(RelativeErrorStats, ModelAgainstReferenceIndexesThePairs) {
  const std::vector<double> model = {1.0, 5.0, 0.9, 3.0};
  const std::vector<double> reference = {1.0, 0.0, 1.0, 2.0};  // the pair at 1 is left out
  const RelativeErrorStats s = relative_error_stats(model, reference);
  EXPECT_EQ(s.n, 3U);
  EXPECT_EQ(s.worst_index, 3U);
  EXPECT_EQ(s.worst, 0.5);
}

/// Model and reference values that C++ and numpy compute to the same doubles.
struct Case {
  std::size_t n;
  double rms;
  double bias;
  std::size_t worst_index;
  double worst;
};

TEST(RelativeErrorStats, SumsInNumpysOrder) {
  // numpy: i = arange(n); model = ((i*7919) % 1000 + 500)/997; ref = ((i*104729) % 1000 + 400)/991;
  // r = (model - ref)/ref; sqrt(mean(r*r)), mean(r), argmax(abs(r)). n = 11: 8 lanes and a tail
  // (the mean differs from a running sum); 300: halves; 20000: numpy's blocks of 8192.
  const Case cases[] = {{5, 0.5847277127493019, 0.4117165747552439, 3, 1.1285098908309257},
                        {11, 0.49112129622863715, 0.24771498561293293, 3, 1.1285098908309257},
                        {300, 0.6849593597486735, 0.26154707092525525, 284, 2.4105435572773364},
                        {20000, 0.6805503037452688, 0.2575876632448144, 321, 2.642980285600076}};
  for (const Case& c : cases) {
    std::vector<double> model(c.n);
    std::vector<double> reference(c.n);
    for (std::size_t i = 0; i < c.n; ++i) {
      model[i] = static_cast<double>((i * 7919) % 1000 + 500) / 997.0;
      reference[i] = static_cast<double>((i * 104729) % 1000 + 400) / 991.0;
    }
    const RelativeErrorStats s = relative_error_stats(model, reference);
    EXPECT_EQ(s.n, c.n);
    EXPECT_EQ(s.rms, c.rms) << c.n;
    EXPECT_EQ(s.bias, c.bias) << c.n;
    EXPECT_EQ(s.worst_index, c.worst_index) << c.n;
    EXPECT_EQ(s.worst, c.worst) << c.n;
  }
}

}  // namespace
}  // namespace corlab::study
