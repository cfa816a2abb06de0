// fit_linear(): NIST StRD Norris (certified values), synthetic recovery, t quantiles, bad input.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fit/linear_regression.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "corlab/core/error.hpp"
#include "unit/fit/nist_dat.hpp"

namespace corlab::study {
namespace {

TEST(StudentT, MatchesClosedFormsForOneAndTwoDegreesOfFreedom) {
  // dof 1 is the Cauchy distribution: t_p = tan(pi (p - 1/2)); dof 2: t_p = (2p-1)/sqrt(2p(1-p))
  for (double p : {0.6, 0.9, 0.975, 0.995}) {
    EXPECT_NEAR(student_t_quantile(p, 1.0), std::tan(std::numbers::pi * (p - 0.5)),
                1e-9 * std::tan(std::numbers::pi * (p - 0.5)));
    const double t2 = (2 * p - 1) / std::sqrt(2 * p * (1 - p));
    EXPECT_NEAR(student_t_quantile(p, 2.0), t2, 1e-10 * t2);
  }
  EXPECT_NEAR(student_t_quantile(0.975, 1.0), 12.706204736, 1e-8);
  // symmetric, and the normal limit z_0.975 = 1.959963985 for large dof
  EXPECT_NEAR(student_t_quantile(0.025, 7.0), -student_t_quantile(0.975, 7.0), 1e-12);
  EXPECT_NEAR(student_t_quantile(0.975, 1e7), 1.959963985, 1e-6);
  // widely tabled: t_{0.975, 10} = 2.228139
  EXPECT_NEAR(student_t_quantile(0.975, 10.0), 2.228139, 1e-6);
}

TEST(StudentT, RejectsProbabilityOutsideOpenUnitInterval) {
  EXPECT_THROW(student_t_quantile(1.0, 3.0), InputError);
  EXPECT_THROW(student_t_quantile(0.5, 0.0), InputError);
}

TEST(FitLinear, NistNorrisCertifiedValues) {
  const auto nist = test::read_nist(CORLAB_DATA_DIR "/nist/Norris.dat");
  ASSERT_EQ(nist.y.size(), 36u);
  Eigen::MatrixXd X(36, 2);
  Eigen::VectorXd y(36);
  for (int i = 0; i < 36; ++i) {
    X(i, 0) = 1.0;
    X(i, 1) = nist.x[static_cast<std::size_t>(i)];
    y[i] = nist.y[static_cast<std::size_t>(i)];
  }
  const LinearFit fit = fit_linear(X, y, {.names = {"B0", "B1"}});
  // the task bar is >= 6 significant digits; SVD gives far more on Norris
  EXPECT_GE(test::significant_digits(fit.coefficients[0], nist.certified.at("B0")), 9.0);
  EXPECT_GE(test::significant_digits(fit.coefficients[1], nist.certified.at("B1")), 9.0);
  EXPECT_GE(test::significant_digits(fit.standard_errors[0], nist.certified_sd.at("B0")), 9.0);
  EXPECT_GE(test::significant_digits(fit.standard_errors[1], nist.certified_sd.at("B1")), 9.0);
  EXPECT_GE(test::significant_digits(fit.goodness.residual_sum_squares,
                                     nist.certified.at("residual_sum_sq")),
            9.0);
  EXPECT_GE(test::significant_digits(fit.goodness.r_squared, nist.certified.at("r_squared")), 9.0);
  EXPECT_GE(
      test::significant_digits(fit.goodness.residual_std_error * fit.goodness.residual_std_error,
                               nist.certified.at("mean_square_error")),
      9.0);
  EXPECT_EQ(fit.dof, 34);
  EXPECT_EQ(fit.names[1], "B1");
  // intervals are b -+ t_{0.975,34} se
  EXPECT_NEAR(fit.ci_upper[1] - fit.coefficients[1], fit.t_quantile * fit.standard_errors[1],
              1e-15);
}

TEST(FitLinear, RecoversKnownCoefficientsAndIntervalsCoverTruth) {
  // e = a_i + s ln k1 with three intercepts: truth inside the 95 % intervals in most trials
  const Eigen::Vector4d truth(0.2, 0.3, 0.4, 0.056);
  std::mt19937 rng(12345);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::uniform_real_distribution<double> lnk(5.0, 12.0);
  int covered = 0;
  const int trials = 200;
  for (int t = 0; t < trials; ++t) {
    Eigen::MatrixXd X = Eigen::MatrixXd::Zero(30, 4);
    Eigen::VectorXd y(30);
    for (int i = 0; i < 30; ++i) {
      X(i, i % 3) = 1.0;
      X(i, 3) = lnk(rng);
      y[i] = X.row(i).dot(truth) + noise(rng);
    }
    const LinearFit fit = fit_linear(X, y);
    EXPECT_NEAR(fit.coefficients[3], truth[3], 6 * fit.standard_errors[3]);
    if (fit.ci_lower[3] <= truth[3] && truth[3] <= fit.ci_upper[3]) ++covered;
  }
  // binomial(200, 0.95): mean 190, sd 3.1; 180 is > 3 sd below, and all 200 covered
  // (probability 0.95^200 ~ 4e-5) would mean the intervals are too wide
  EXPECT_GE(covered, 180);
  EXPECT_LE(covered, 199);
}

TEST(FitLinear, ExactDataHasZeroResidualAndUnitRSquared) {
  Eigen::MatrixXd X(5, 2);
  Eigen::VectorXd y(5);
  for (int i = 0; i < 5; ++i) {
    X(i, 0) = 1.0;
    X(i, 1) = i;
    y[i] = 2.0 + 0.5 * i;
  }
  const LinearFit fit = fit_linear(X, y);
  EXPECT_NEAR(fit.coefficients[0], 2.0, 1e-14);
  EXPECT_NEAR(fit.coefficients[1], 0.5, 1e-14);
  EXPECT_NEAR(fit.goodness.r_squared, 1.0, 1e-14);
  EXPECT_NEAR(fit.goodness.max_relative_error, 0.0, 1e-13);
}

TEST(FitLinear, RejectsCollinearColumnsTooFewRowsAndNonFiniteInput) {
  Eigen::MatrixXd X(4, 2);
  X << 1, 2, 1, 2, 1, 2, 1, 2;
  const Eigen::VectorXd y = Eigen::VectorXd::Ones(4);
  try {
    fit_linear(X, y);
    FAIL() << "collinear design accepted";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("rank deficient"), std::string::npos) << err.what();
  }
  EXPECT_THROW(fit_linear(Eigen::MatrixXd::Ones(2, 2), Eigen::VectorXd::Ones(2)), InputError);
  Eigen::MatrixXd Xn = Eigen::MatrixXd::Identity(4, 2);
  Xn(0, 1) = std::nan("");
  EXPECT_THROW(fit_linear(Xn, y), InputError);
  EXPECT_THROW(fit_linear(Eigen::MatrixXd::Identity(4, 2), Eigen::VectorXd::Ones(3)), InputError);
}

}  // namespace
}  // namespace corlab::study
