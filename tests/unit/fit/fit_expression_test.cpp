// fit_expression(): NIST StRD Misra1a (certified values), user forms over columns, bad input.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fit/fit_expression.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "corlab/core/error.hpp"
#include "unit/fit/nist_dat.hpp"

namespace corlab::study {
namespace {

TEST(FitExpression, NistMisra1aFromBothStartsMatchesCertifiedValues) {
  const auto nist = test::read_nist(CORLAB_DATA_DIR "/nist/Misra1a.dat");
  ASSERT_EQ(nist.y.size(), 14u);
  const DataColumns data{{"x", nist.x}, {"y", nist.y}};
  for (const char* start : {"start1", "start2"}) {
    const auto& s = nist.starts.at(start);
    const NonlinearFit fit =
        fit_expression("y ~ b1*(1-exp(-b2*x))", {{"b1", s[0]}, {"b2", s[1]}}, data);
    ASSERT_TRUE(fit.converged) << start << ": " << fit.message;
    // the task bar is >= 4 significant digits (Ceres' NIST criterion)
    EXPECT_GE(test::significant_digits(fit.coefficients[0], nist.certified.at("b1")), 6.0) << start;
    EXPECT_GE(test::significant_digits(fit.coefficients[1], nist.certified.at("b2")), 6.0) << start;
    EXPECT_GE(test::significant_digits(fit.standard_errors[0], nist.certified_sd.at("b1")), 4.0);
    EXPECT_GE(test::significant_digits(fit.standard_errors[1], nist.certified_sd.at("b2")), 4.0);
    EXPECT_GE(test::significant_digits(fit.goodness.residual_sum_squares,
                                       nist.certified.at("residual_sum_sq")),
              6.0);
    EXPECT_GE(
        test::significant_digits(fit.goodness.residual_std_error, nist.certified.at("residual_sd")),
        6.0);
    EXPECT_EQ(fit.dof, static_cast<int>(nist.certified.at("dof")));
  }
}

TEST(FitExpression, RecoversTheRestitutionLawFromNoisySyntheticData) {
  // e = alpha + beta ln k2 + s ln k1 with noise; rows with e >= 0.999 filtered out by `where`
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.005);
  std::vector<double> e, k1, k2;
  for (double lk2 : {-6.0, -5.5, -5.0, -4.5}) {
    for (double lk1 : {8.0, 10.0, 12.0, 14.0, 16.0, 18.0, 20.0, 22.0}) {
      k1.push_back(std::exp(lk1));
      k2.push_back(std::exp(lk2));
      e.push_back(std::min(1.0, 1.16 + 0.253 * lk2 + 0.056 * lk1 + noise(rng)));
    }
  }
  NonlinearFitOptions options;
  options.where = "e < 0.999";
  const NonlinearFit fit = fit_expression("e ~ alpha + beta*ln(k2) + s*ln(k1)",
                                          {{"alpha", 1}, {"beta", 0.1}, {"s", 0.1}},
                                          {{"e", e}, {"k1", k1}, {"k2", k2}}, options);
  ASSERT_TRUE(fit.converged) << fit.message;
  EXPECT_LT(fit.observations, static_cast<int>(e.size()));  // some points are elastic
  const double truth[] = {1.16, 0.253, 0.056};
  for (int j = 0; j < 3; ++j) {
    EXPECT_LE(fit.ci_lower[j], truth[j]) << fit.names[j];
    EXPECT_GE(fit.ci_upper[j], truth[j]) << fit.names[j];
  }
}

TEST(FitExpression, PowerLawInOriginalSpace) {
  // rho v^2 = b sigma^n, exact data: recovered to round-off
  std::vector<double> sigma, rv2;
  for (double s = 1.0; s <= 6.0; s += 1.0) {
    sigma.push_back(s);
    rv2.push_back(0.7 * std::pow(s, 4.5));
  }
  const NonlinearFit fit = fit_expression("rv2 = b * sigma^n", {{"b", 1.0}, {"n", 3.0}},
                                          {{"rv2", rv2}, {"sigma", sigma}});
  ASSERT_TRUE(fit.converged) << fit.message;
  EXPECT_NEAR(fit.coefficients[0], 0.7, 1e-8);
  EXPECT_NEAR(fit.coefficients[1], 4.5, 1e-8);
}

TEST(FitExpression, ParsesParameterStarts) {
  const auto p = parse_parameter_starts({"a=1.5, b=-2e-3", "c = 4"});
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[1].name, "b");
  EXPECT_DOUBLE_EQ(p[1].start, -2e-3);
  EXPECT_THROW(parse_parameter_starts({"a"}), InputError);
  EXPECT_THROW(parse_parameter_starts({"a=x"}), InputError);
  EXPECT_THROW(parse_parameter_starts({"a=1,a=2"}), InputError);
}

TEST(FitExpression, RejectsUnknownNamesUnusedParametersAndBadForms) {
  const DataColumns data{{"x", {1, 2, 3, 4}}, {"y", {1, 2, 3, 4.1}}};
  auto message = [&](const std::string& form, std::vector<ParameterStart> p) {
    try {
      fit_expression(form, p, data);
    } catch (const InputError& err) {
      return std::string(err.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message("y ~ a*z", {{"a", 1}}).find("invalid form"), std::string::npos)
      << message("y ~ a*z", {{"a", 1}});
  EXPECT_NE(message("y ~ a*x", {{"a", 1}, {"b", 2}}).find("used in the form"), std::string::npos);
  EXPECT_NE(message("a*x", {{"a", 1}}).find("response ~ model"), std::string::npos);
  EXPECT_NE(message("q ~ a*x", {{"a", 1}}).find("a data column"), std::string::npos);
  EXPECT_NE(message("y ~ a*x + b", {{"a", 1}, {"x", 2}, {"b", 0}}).find("not also a data column"),
            std::string::npos);
  EXPECT_NE(message("y ~ a*ln(x - 5)", {{"a", 1}}).find("finite model value"), std::string::npos);
}

}  // namespace
}  // namespace corlab::study
