// Forms (i)-(iv) of Ma et al. 2023 on synthetic data generated from the paper's own model.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/paper/fit_paper.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "corlab/core/error.hpp"

namespace corlab::study {
namespace {

constexpr double kEStar = 210e9 / (2 * (1 - 0.3 * 0.3));  // Table 2: both bodies 210 GPa, 0.3

std::string fmt_id(double rho, double sy) {
  return std::to_string(static_cast<int>(rho)) + "_" + std::to_string(static_cast<int>(sy / 1e6));
}

std::vector<RestitutionSample> table2_like(double noise_sd, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, noise_sd);
  std::vector<RestitutionSample> out;
  for (double rho : {3925.0, 7850.0, 15700.0}) {
    for (double sy : {300e6, 500e6, 700e6, 1000e6, 1300e6}) {
      for (double v : {0.1, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 40.0, 70.0}) {
        RestitutionSample s{fmt_id(rho, sy), v, 0.0, rho, kEStar, sy, {}};
        s.e =
            std::min(1.0, 1.16 + 0.253 * std::log(s.k2()) + 0.056 * std::log(s.k1()) + noise(rng));
        out.push_back(s);
      }
    }
  }
  return out;
}

TEST(FitRestitutionLaw, RecoversPaperConstantsExactlyWithoutNoise) {
  const auto fit = fit_restitution_law(table2_like(0.0, 1));
  EXPECT_EQ(fit.cases.size(), 15u);
  EXPECT_NEAR(fit.slope.value, 0.056, 1e-12);
  EXPECT_NEAR(fit.alpha.value, 1.16, 1e-10);
  EXPECT_NEAR(fit.beta.value, 0.253, 1e-11);
  EXPECT_NEAR(fit.combined.max_relative_error, 0.0, 1e-10);
  EXPECT_GT(fit.points_excluded, 0);  // the clamped (elastic) points are left out
  // the e = 1 crossing of each case line is the paper's back-calculated v_y
  for (const auto& c : fit.cases) {
    EXPECT_NEAR(c.v_cross,
                crossing_yield_velocity(1.16, 0.253, 0.056, c.sphere_rho, c.E_star, c.sigma_y),
                1e-9 * c.v_cross);
  }
}

TEST(FitRestitutionLaw, IntervalsCoverTruthWithNoise) {
  int covered_s = 0;
  int covered_beta = 0;
  const int trials = 60;
  for (int t = 0; t < trials; ++t) {
    const auto fit = fit_restitution_law(table2_like(0.01, 100 + static_cast<unsigned>(t)));
    if (fit.slope.ci_lower <= 0.056 && 0.056 <= fit.slope.ci_upper) ++covered_s;
    if (fit.beta.ci_lower <= 0.253 && 0.253 <= fit.beta.ci_upper) ++covered_beta;
    EXPECT_LT(std::abs(fit.slope.value - 0.056), 0.01);
  }
  // binomial(60, 0.95): mean 57, sd 1.7
  EXPECT_GE(covered_s, 51);
  EXPECT_GE(covered_beta, 51);
}

TEST(FitYieldVelocity, RecoversExponentsAndCombinedConstant) {
  std::vector<YieldVelocitySample> samples;
  for (double rho : {3925.0, 7850.0}) {
    for (double es : {50e9, 60e9, 63.8e9, 70e9, 80e9}) {
      for (double sy = 100e6; sy <= 600e6 + 1; sy += 100e6) {
        samples.push_back(
            {"c", rho, es, sy, power_law_yield_velocity(15.81, 4.5, -3.5, rho, es, sy)});
      }
    }
  }
  const auto fit = fit_yield_velocity(samples);
  EXPECT_NEAR(fit.n.value, 4.5, 1e-10);
  EXPECT_NEAR(fit.m.value, -3.5, 1e-10);
  EXPECT_EQ(fit.groups.size(), 5u);
  // c = K sigma0^n E0^m = 15.81 * 1e8^4.5 * 1e11^-3.5 = 15.81 / 10^2.5
  EXPECT_NEAR(fit.c.value, 15.81 / std::pow(10.0, 2.5), 1e-9);
  EXPECT_NEAR(fit.combined.value, 15.81, 1e-6);
  EXPECT_NEAR(fit.combined_two_step, 15.81, 1e-6);
  EXPECT_NEAR(fit.combined_fixed.value, 15.81, 1e-9);
  EXPECT_NEAR(fit.combined_v.max_relative_error, 0.0, 1e-9);
}

TEST(FitYieldVelocity, PaperBackCalculationGivesExactExponentsAndAbout15point9) {
  // v_y from the paper's eq. 12 crossing: n = beta/s, m = 1 - beta/s exactly, and with the
  // exponents fixed at 4.5/-3.5 the constant is 17.41 (sigma/E*)^0.018 ~ 15.9
  // (docs/reference/models.md 1.3)
  std::vector<YieldVelocitySample> samples;
  for (double rho : {3925.0, 7850.0}) {
    for (double es : {50e9, 60e9, 63.8e9, 70e9, 80e9}) {
      for (double sy = 100e6; sy <= 600e6 + 1; sy += 100e6) {
        samples.push_back(
            {"c", rho, es, sy, crossing_yield_velocity(1.16, 0.253, 0.056, rho, es, sy)});
      }
    }
  }
  const auto fit = fit_yield_velocity(samples);
  EXPECT_NEAR(fit.n.value, 0.253 / 0.056, 1e-9);
  EXPECT_NEAR(fit.m.value, 1.0 - 0.253 / 0.056, 1e-9);
  EXPECT_NEAR(fit.combined.value, std::exp(0.16 / 0.056), 1e-6);  // 17.41
  EXPECT_GT(fit.combined_fixed.value, 15.5);
  EXPECT_LT(fit.combined_fixed.value, 16.3);
}

TEST(FitYieldVelocity, RejectsNonPositiveVelocityAndSingleYieldStress) {
  std::vector<YieldVelocitySample> s{{"a", 7850, 50e9, 100e6, 0.1}, {"b", 7850, 60e9, 100e6, 0.1}};
  EXPECT_THROW(fit_yield_velocity(s), InputError);
  s.push_back({"c", 7850, 60e9, 200e6, -1.0});
  EXPECT_THROW(fit_yield_velocity(s), InputError);
}

TEST(LogLaw, MatchesGoldenValuesOfTheSeedModel) {
  // docs/reference/models.md section 8: e(1 m/s) = 0.7932 (alumina/Al), E* = 63.7905 GPa, rho =
  // 3958.226
  EXPECT_NEAR(log_law_restitution(1.16, 0.253, 0.056, 3958.226, 63.7905e9, 0.38e9, 1.0), 0.7932,
              1e-4);
  EXPECT_NEAR(power_law_yield_velocity(15.81, 4.5, -3.5, 3958.226, 63.7905e9, 0.38e9), 0.15736,
              1e-5);
  EXPECT_EQ(log_law_restitution(1.16, 0.253, 0.056, 3958.226, 63.7905e9, 0.38e9, 0.1), 1.0);
}

}  // namespace
}  // namespace corlab::study
