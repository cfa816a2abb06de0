// e(v) between FE speeds (fe_interpolation.hpp): monotone, exact at nodes, honest between.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/study/fe_interpolation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace corlab::study {
namespace {

// A smooth falling e(v) like an elastic-plastic pair's [-], v [m/s].
double smooth(double v) { return 0.9 / (1.0 + 0.3 * std::pow(v, 0.6)); }

std::vector<CurveNode> nodes_of(const std::vector<double>& speeds, double bar = 0.0) {
  std::vector<CurveNode> out;
  for (const double v : speeds) out.push_back({v, smooth(v), bar});
  return out;
}

TEST(FeInterpolation, ExactAtTheNodesNothingOutside) {
  const auto nodes = nodes_of({0.1, 1.0, 3.0, 20.0}, 0.004);
  for (const auto& n : nodes) {
    const Interpolated at = interpolate_curve(nodes, n.velocity);
    EXPECT_DOUBLE_EQ(at.e, n.e);
    EXPECT_NEAR(at.interpolation, 0.0, 1e-15);
    EXPECT_NEAR(at.e_error, 0.004, 1e-15);  // the node's own bar
  }
  EXPECT_TRUE(std::isnan(interpolate_curve(nodes, 0.05).e));
  EXPECT_TRUE(std::isnan(interpolate_curve(nodes, 21.0).e_error));
  EXPECT_TRUE(std::isnan(interpolate_curve(std::vector<CurveNode>{{1.0, 0.5, 0.0}}, 1.0).e));
}

TEST(FeInterpolation, MonotoneDataGiveAMonotoneCurve) {
  // A step-like fall: an unlimited cubic would overshoot above the first node.
  const std::vector<CurveNode> nodes{
      {1.0, 0.9, 0.0}, {2.0, 0.9, 0.0}, {3.0, 0.2, 0.0}, {4.0, 0.19, 0.0}};
  double last = 1.0;
  for (double v = 1.0; v <= 4.0; v += 0.01) {
    const double e = interpolate_curve(nodes, v).e;
    EXPECT_LE(e, last + 1e-14) << v;
    EXPECT_GE(e, 0.19 - 1e-14) << v;
    last = e;
  }
}

TEST(FeInterpolation, TheStatedErrorCoversTheTrueOneAndShrinksWithRefinement) {
  // Every 1 % of ln v between 0.1 and 20 m/s on nine nodes: the interpolant's error is within its
  // stated interpolation error. (On the five coarse nodes below it is not: smooth() turns from
  // concave to convex in ln v at 7.4 m/s, between the nodes 2, 8 and 20, where no estimate from
  // the nodes can see it; the stated error there is 2-3 times short. --tolerance starts from
  // five speeds and refines, RefinementAddsTheWorstMidpointsUntilWithinTolerance.)
  const auto nodes = nodes_of({0.1, 0.2, 0.5, 1.0, 2.0, 4.0, 8.0, 14.0, 20.0});
  for (double v = 0.1; v <= 20.0; v *= 1.01) {
    const Interpolated at = interpolate_curve(nodes, v);
    EXPECT_LE(std::abs(at.e - smooth(v)), at.interpolation + 1e-12) << v;
  }
  const auto coarse = nodes_of({0.1, 0.5, 2.0, 8.0, 20.0});
  const auto fine = nodes_of({0.1, 0.2, 0.5, 1.0, 2.0, 4.0, 8.0, 14.0, 20.0});
  EXPECT_LT(interpolate_curve(fine, 1.4).interpolation,
            interpolate_curve(coarse, 1.0).interpolation);
}

TEST(FeInterpolation, RefinementAddsTheWorstMidpointsUntilWithinTolerance) {
  auto nodes = nodes_of({0.1, 0.5, 2.0, 8.0, 20.0});
  const double tolerance = 1e-3;
  int rounds = 0;
  while (true) {
    const auto next = refinement_speeds(nodes, tolerance, 100);
    if (next.empty()) break;
    ASSERT_LT(++rounds, 10);
    for (const double v : next) nodes.push_back({v, smooth(v), 0.0});
    std::sort(nodes.begin(), nodes.end(),
              [](const CurveNode& a, const CurveNode& b) { return a.velocity < b.velocity; });
  }
  EXPECT_GT(rounds, 0);
  for (double v = 0.1; v <= 20.0; v *= 1.01) {
    EXPECT_LE(std::abs(interpolate_curve(nodes, v).e - smooth(v)), tolerance) << v;
  }
  EXPECT_EQ(refinement_speeds(nodes_of({0.1, 0.5, 2.0, 8.0, 20.0}), 1e-6, 2).size(), 2U);
}

}  // namespace
}  // namespace corlab::study
