// Error-bar estimators over several grids (error_bar.hpp): the least-squares fits recover exact
// power laws, the estimators' limits, bad input.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/error_bar.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "corlab/core/error.hpp"
#include "support/coverage_tally.hpp"

namespace corlab::fem {
namespace {

const std::array<double, 4> kRatios{1.0, std::sqrt(2.0), 2.0, 2.0 * std::sqrt(2.0)};
const std::array<double, 4> kUniform{0.25, 0.25, 0.25, 0.25};

std::vector<double> power_law(double e0, double a, double p) {
  std::vector<double> e;
  for (const double h : kRatios) e.push_back(e0 + a * std::pow(h, p));
  return e;
}

TEST(ErrorBar, FreeOrderFitRecoversAnExactPowerLaw) {
  const std::vector<double> e = power_law(0.53, 0.004, 1.5);
  const ConvergenceFit f = fit_free_order(e, kRatios, kUniform);
  ASSERT_TRUE(f.valid);
  EXPECT_NEAR(f.order, 1.5, 1e-6);
  EXPECT_NEAR(f.e0, 0.53, 1e-9);
  EXPECT_NEAR(f.fit_1, 0.534, 1e-9);
  EXPECT_NEAR(f.sigma, 0.0, 1e-9);
}

TEST(ErrorBar, FixedOrdersFitTwoTerms) {
  std::vector<double> e;
  for (const double h : kRatios) e.push_back(0.4 - 0.01 * h + 0.003 * h * h);
  const std::array<double, 2> orders{1.0, 2.0};
  const ConvergenceFit f = fit_fixed_orders(e, kRatios, kUniform, orders);
  ASSERT_TRUE(f.valid);
  EXPECT_NEAR(f.e0, 0.4, 1e-12);
  EXPECT_NEAR(f.fit_1, 0.393, 1e-12);
  EXPECT_NEAR(f.sigma, 0.0, 1e-12);
}

TEST(ErrorBar, LeastSquaresOnATrustedOrderIsOneAndAQuarterTimesTheError) {
  // p = 1.5 lies in [0.5, 2.1) and the fit is exact: U = 1.25 |e_1 - e_0|.
  const std::vector<double> e = power_law(0.53, 0.004, 1.5);
  EXPECT_NEAR(error_bar("least_squares", e, kRatios), 1.25 * 0.004, 1e-8);
}

TEST(ErrorBar, LeastSquaresOutsideTheTrustedOrdersUsesTheSafetyFactorThree) {
  // p = 3 (too fast to trust): the best of the p = 1, 2, (1, 2) fits, Fs = 3, plus its residuals.
  // Those fits miss the curvature (0.534 ... 0.62 over the grids), so the bar is wide: it covers
  // three times the true error and stays below the values' whole spread.
  const std::vector<double> e = power_law(0.53, 0.004, 3.0);
  const double u = error_bar("least_squares", e, kRatios);
  EXPECT_GT(u, 3.0 * 0.004);
  EXPECT_LT(u, e.back() - e.front());
}

TEST(ErrorBar, ScatterWiderThanTheDataRangeWidensTheBar) {
  // Non-monotone values (as e(h) of the paper case): the bar is not smaller than the values'
  // own spread around e_1.
  const std::vector<double> e{0.5349, 0.5421, 0.5367, 0.5384};
  const double u = error_bar("least_squares", e, kRatios);
  EXPECT_GT(u, 0.5384 - 0.5349);
  EXPECT_TRUE(std::isfinite(u));
}

TEST(ErrorBar, ScatterIsTwoAndAHalfDeviationsOfTheFinerValue) {
  // sigma^2 = mean of (e_i - e_1)^2 / (1 + h_i^2) over the three coarser grids.
  const double d = 0.003;
  const std::vector<double> e{0.5, 0.5 + d, 0.5 - d, 0.5};
  const double sigma = std::sqrt((d * d / 3.0 + d * d / 5.0) / 3.0);
  EXPECT_NEAR(error_bar("scatter", e, kRatios), 2.5 * sigma * std::sqrt(1.25), 1e-15);
  // A single coarser grid is enough for a value; the default estimator is the first listed.
  const std::array<double, 2> two{0.5, 0.51};
  const std::array<double, 2> ratios{1.0, 2.0};
  EXPECT_NEAR(error_bar("scatter", two, ratios), 2.5 * 0.01 / std::sqrt(5.0) * std::sqrt(1.25),
              1e-15);
  EXPECT_EQ(error_bar_estimators().front(), "scatter");
}

TEST(ErrorBar, ScatterCoarseIsTwoDeviationsOverItsFourCompanions) {
  // Issue 43's candidate companions (2, 2 sqrt 2, 4, 4 sqrt 2 h): sigma from four values,
  // the factor 2.0 calibrated on them.
  const double d = 0.004;
  const std::vector<double> e{0.5, 0.5 + d, 0.5, 0.5 - d, 0.5};
  const std::vector<double> h{1.0, 2.0, 2.0 * std::sqrt(2.0), 4.0, 4.0 * std::sqrt(2.0)};
  const double sigma = std::sqrt((d * d / 5.0 + d * d / 17.0) / 4.0);
  EXPECT_NEAR(error_bar("scatter_coarse", e, h), 2.0 * sigma * std::sqrt(1.25), 1e-15);
  EXPECT_NEAR(error_bar("scatter_coarse", e, h), 0.8 * error_bar("scatter", e, h), 1e-15);
}

TEST(ErrorBar, The3dNormalBarIsTheScatterBarAtOneAndAHalfDeviations) {
  const std::vector<double> e{0.8, 0.81, 0.79, 0.8};
  EXPECT_NEAR(error_bar("scatter_3d_e_n", e, kRatios), 1.5 / 2.5 * error_bar("scatter", e, kRatios),
              1e-15);
}

TEST(ErrorBar, The3dTangentialBarHoldsNinetyFivePercentOfItsOwnModel) {
  // e(h_i) = e* + sigma h_i z_i at the 3-D companions and at h / sqrt 2, drawn with another seed
  // and normal transform than the factor's: the bar holds the reference value in 95 % of the
  // draws.
  const std::array<double, 4> h{1.0, std::sqrt(2.0), std::pow(2.0, 0.75), 2.0};
  std::mt19937_64 rng(20261130);
  std::normal_distribution<double> z;
  const int draws = 20000;
  int inside = 0;
  for (int k = 0; k < draws; ++k) {
    std::array<double, 4> e{};
    for (std::size_t i = 0; i < h.size(); ++i) e[i] = 0.7 + 0.01 * h[i] * z(rng);
    const double reference = 0.7 + 0.01 * z(rng) / std::sqrt(2.0);
    inside += std::abs(reference - e[0]) <= error_bar("scatter_3d", e, h) ? 1 : 0;
  }
  // 95 % +/- 4 binomial deviations (0.15 % each) and the factor's own +/- 0.3 %.
  EXPECT_NEAR(inside / static_cast<double>(draws), 0.95, 0.0075);
}

TEST(ErrorBar, The3dTangentialBarIsTheModelFactorOnTheFinerValuesSpread) {
  const std::array<double, 4> h{1.0, std::sqrt(2.0), std::pow(2.0, 0.75), 2.0};
  const std::array<double, 4> e{0.8, 0.81, 0.79, 0.8};
  const double sigma = std::sqrt((1e-4 / 3.0 + 1e-4 / (1.0 + h[2] * h[2])) / 3.0);
  const double f = scatter_model_factor(h, 1.0 / std::sqrt(2.0), 0.95);
  EXPECT_NEAR(error_bar("scatter_3d", e, h), f * sigma * std::sqrt(1.5), 1e-15);
  // Fewer companions, sigma from fewer values: a wider factor (Student-like); none, no bar.
  const std::array<double, 3> two{1.0, std::sqrt(2.0), std::pow(2.0, 0.75)};
  const std::array<double, 2> one{1.0, std::sqrt(2.0)};
  const double f2 = scatter_model_factor(two, 1.0 / std::sqrt(2.0), 0.95);
  EXPECT_GT(f2, f);
  EXPECT_GT(scatter_model_factor(one, 1.0 / std::sqrt(2.0), 0.95), f2);
  EXPECT_TRUE(std::isnan(scatter_model_factor(std::span(h).first(1), 0.5, 0.95)));
  // A function of its arguments: the same factor every time.
  EXPECT_EQ(scatter_model_factor(h, 1.0 / std::sqrt(2.0), 0.95), f);
  EXPECT_THROW(scatter_model_factor(h, 0.0, 0.95), InputError);
  EXPECT_THROW(scatter_model_factor(h, 0.5, 1.0), InputError);
  EXPECT_THROW(scatter_model_factor(h, 0.5, std::nan("")), InputError);
}

TEST(ErrorBar, TheScatterModelsWidthIsOverThreeOnTheThreeCompanions) {
  // Issue 39 item 5 asks 95 % at a median bar <= 3 x the median change. Where the next change is
  // scatter of the model's kind, the model's own 95 % bar on the 3-D model's three companions is
  // 3.6 times it. Redrawn here with another seed and normal transform than the library's.
  const double reference = 1.0 / std::sqrt(2.0);
  const std::array<double, 4> h{1.0, std::sqrt(2.0), std::pow(2.0, 0.75), 2.0};
  std::mt19937_64 rng(20261201);
  std::normal_distribution<double> z;
  const int draws = 40000;
  std::vector<double> bars, changes;
  for (int k = 0; k < draws; ++k) {
    std::array<double, 4> e{};
    for (std::size_t i = 0; i < h.size(); ++i) e[i] = 0.7 + 0.01 * h[i] * z(rng);
    const double finer = 0.7 + 0.01 * reference * z(rng);
    bars.push_back(error_bar("scatter_3d", e, h));
    changes.push_back(std::abs(finer - e[0]));
  }
  const double width = scatter_model_width(h, reference, 0.95);
  // The medians of 40,000 draws: about 1 % each.
  EXPECT_NEAR(test::median(bars) / test::median(changes), width, 0.03 * width);
  EXPECT_GT(width, 3.4);
  EXPECT_LT(width, 3.8);
  // Two companions: sigma_hat from fewer values, a wider bar still.
  const std::array<double, 3> two{1.0, std::sqrt(2.0), 2.0};
  const double width_two = scatter_model_width(two, reference, 0.95);
  std::printf("scatter model's width: %.3f (three companions), %.3f (two)\n", width, width_two);
  EXPECT_GT(width_two, width);
  EXPECT_TRUE(std::isnan(scatter_model_width(std::span(h).first(1), reference, 0.95)));
  EXPECT_THROW(scatter_model_width(h, reference, 0.0), InputError);
  EXPECT_THROW(scatter_model_width(h, -1.0, 0.95), InputError);
}

TEST(ErrorBar, TwoGridIsTheGci) {
  const std::vector<double> e{0.5349, 0.5367, 0.5384, 0.5421};
  EXPECT_NEAR(error_bar("two_grid", e, kRatios), 0.5384 - 0.5349, 1e-15);
}

TEST(ErrorBar, EqualValuesHaveNoBarAndNonFiniteOnesNoValue) {
  const std::vector<double> same(4, 0.5);
  EXPECT_EQ(error_bar("least_squares", same, kRatios), 0.0);
  std::vector<double> failed{0.5, 0.51, std::nan(""), 0.52};
  EXPECT_TRUE(std::isnan(error_bar("least_squares", failed, kRatios)));
  EXPECT_TRUE(std::isnan(error_bar("two_grid", failed, kRatios)));
}

TEST(ErrorBar, BadInputNamesItsField) {
  const std::vector<double> e{0.5, 0.51};
  EXPECT_THROW(error_bar("gci3", power_law(0.5, 0.01, 1.0), kRatios), InputError);
  EXPECT_THROW(error_bar("least_squares", e, kRatios), InputError);
  // Issue 42: a ratio that is not a mesh size is refused, not turned into a number.
  for (const std::vector<double>& ratios :
       {std::vector<double>{1.0, 0.0}, std::vector<double>{1.0, -2.0},
        std::vector<double>{1.0, std::nan("")}, std::vector<double>{2.0, 4.0}}) {
    for (const auto name : error_bar_estimators()) {
      EXPECT_THROW(error_bar(name, e, ratios), InputError) << name << " " << ratios[1];
    }
  }
}

}  // namespace
}  // namespace corlab::fem
