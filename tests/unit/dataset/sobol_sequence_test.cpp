// The Sobol sequence (sobol_sequence.hpp): stratification of every power-of-two prefix, the
// dimensions GSL has.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dataset/sobol_sequence.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "corlab/core/error.hpp"
#include "corlab/dataset/impact_box.hpp"

namespace corlab::dataset {
namespace {

TEST(SobolSequence, EveryPrefixOfPowerOfTwoPointsIsStratifiedInEachCoordinate) {
  const auto points = sobol_points(kBoxDimension, 256);
  ASSERT_EQ(points.size(), 256U);
  for (const double x : points[0]) EXPECT_EQ(x, 0.0);  // the origin GSL leaves out
  for (std::size_t n = 2; n <= points.size(); n *= 2) {
    for (int d = 0; d < kBoxDimension; ++d) {
      std::set<long> cells;
      for (std::size_t i = 0; i < n; ++i) {
        const double x = points[i][static_cast<std::size_t>(d)];
        ASSERT_GE(x, 0.0);
        ASSERT_LT(x, 1.0);
        cells.insert(static_cast<long>(std::floor(x * static_cast<double>(n))));
      }
      EXPECT_EQ(cells.size(), n) << "dimension " << d << ", first " << n << " points";
    }
  }
}

TEST(SobolSequence, RefusesDimensionsGslLacks) {
  EXPECT_THROW((void)sobol_points(0, 4), InputError);
  EXPECT_THROW((void)sobol_points(kSobolMaxDimension + 1, 4), InputError);
}

}  // namespace
}  // namespace corlab::dataset
