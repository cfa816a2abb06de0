// The golden-section minimiser (golden_section.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/core/golden_section.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace corlab {
namespace {

TEST(GoldenSection, FindsAParabolasVertexToTheTolerance) {
  int calls = 0;
  auto parabola = [&](double x) {
    ++calls;
    return (x - 1.234) * (x - 1.234);  // no offset: one would hide |x - 1.234| < 1e-8 in round-off
  };
  const double x = golden_section_minimum(parabola, 0.0, 3.0, 1e-9);
  EXPECT_NEAR(x, 1.234, 3e-9);
  // One new evaluation per step: log(3 / 2.5e-9) / log(phi) is about 44 steps, plus the two
  // first points.
  EXPECT_LE(calls, 48);
}

TEST(GoldenSection, AMinimumAtAnEndOfTheIntervalIsApproachedFromInside) {
  const double x = golden_section_minimum([](double v) { return std::exp(v); }, -2.0, 1.0, 1e-10);
  EXPECT_NEAR(x, -2.0, 1e-9);
}

TEST(GoldenSection, AnAsymmetricUnimodalFunction) {
  // |x - 0.3|^0.5 has a cusp at its minimum: no derivative is needed.
  const double x = golden_section_minimum([](double v) { return std::sqrt(std::abs(v - 0.3)); },
                                          -1.0, 4.0, 1e-10);
  EXPECT_NEAR(x, 0.3, 1e-9);
}

}  // namespace
}  // namespace corlab
