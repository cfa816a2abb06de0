// Validity of the CoR models (validity.cpp): the calibration-box check per velocity and the
// warnings built on it.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/restitution/validity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "corlab/materials/material_database.hpp"
#include "corlab/restitution/registry.hpp"

namespace corlab::restitution {
namespace {

// Steel on steel (E = 210 GPa, nu = 0.3, rho = 7850 kg/m^3): ma2023's box (registry.cpp: the
// paper's FE runs, rho = 3925-15700 kg/m^3 at v = 0.1-70 m/s) spans k1 = E*/(rho v^2) of this
// sphere at 0.0707-99.0 m/s, and k2 = sigma_y/E* of 300-1300 MPa.
Material steel(double yield_stress) {
  return parse_material_spec("E=210e9,nu=0.3,rho=7850,sy=" + std::to_string(yield_stress),
                             "substrate");
}

const std::vector<double> kSpeeds = {0.01, 0.07, 0.072, 1.0, 98.0, 100.0, 500.0};  // [m/s]

TEST(CalibrationCheck, FlagsEachSpeedOutsideTheBoxInK1) {
  const auto check = calibration_check(model_info("ma2023"), kSpeeds, steel(500e6), steel(500e6));
  ASSERT_TRUE(check.known);
  EXPECT_FALSE(check.k2_outside);
  EXPECT_NEAR(check.k2, 500e6 / (210e9 / (2.0 * (1.0 - 0.09))), 1e-15);
  const std::vector<bool> expected = {true, true, false, false, false, true, true};
  EXPECT_EQ(check.k1_outside, expected);
}

TEST(CalibrationCheck, FlagsK2OutsideTheBox) {
  const std::vector<double> inside = {1.0};
  const auto low = calibration_check(model_info("ma2023"), inside, steel(500e6), steel(250e6));
  const auto high = calibration_check(model_info("ma2023"), inside, steel(500e6), steel(1400e6));
  EXPECT_TRUE(low.known && low.k2_outside);
  EXPECT_TRUE(high.known && high.k2_outside);
  EXPECT_EQ(low.k1_outside, std::vector<bool>{false});
}

TEST(CalibrationCheck, UnknownWithoutABoxOrAYieldStress) {
  const auto no_box =
      calibration_check(model_info("thornton1997"), kSpeeds, steel(5e8), steel(5e8));
  EXPECT_FALSE(no_box.known);
  EXPECT_TRUE(no_box.k1_outside.empty());
  const Material elastic = parse_material_spec("E=210e9,nu=0.3,rho=7850", "substrate");
  EXPECT_FALSE(calibration_check(model_info("ma2023"), kSpeeds, steel(5e8), elastic).known);
}

TEST(ValidityWarnings, CountTheSpeedsTheCheckFlags) {
  const auto warnings = validity_warnings(model_info("ma2023"), kSpeeds, steel(5e8), steel(5e8));
  ASSERT_EQ(warnings.size(), 1U);
  EXPECT_NE(warnings[0].find("model 'ma2023' extrapolates: 4 of 7 velocities"), std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[0].find("inside"), std::string::npos) << warnings[0];
  const std::vector<double> inside = {0.5, 5.0, 50.0};
  EXPECT_TRUE(validity_warnings(model_info("ma2023"), inside, steel(5e8), steel(5e8)).empty());
  const std::vector<double> fast = {1500.0};
  const auto beyond = validity_warnings(model_info("thornton1997"), fast, steel(5e8), steel(5e8));
  ASSERT_EQ(beyond.size(), 1U);
  EXPECT_NE(beyond[0].find("beyond 1000 m/s"), std::string::npos) << beyond[0];
}

// corlab2026p warns where its held-out errors exceed 2 % RMS: above Johnson's damage number
// rho v^2/sigma_y = 0.003; steel (7850 kg/m^3) on a 500 MPa steel reaches it at 13.8 m/s. Models
// without a measured limit never warn for it.
TEST(ValidityWarnings, ADamageNumberAboveTheMeasuredAccuracy) {
  const double limit = *model_info("corlab2026p").accurate_damage_number;
  EXPECT_EQ(limit, 0.003);
  const double v_limit = std::sqrt(limit * 5e8 / 7850.0);
  const std::vector<double> below = {1.0, 0.99 * v_limit};
  EXPECT_TRUE(validity_warnings(model_info("corlab2026p"), below, steel(5e8), steel(5e8)).empty());
  const std::vector<double> speeds = {1.0, 20.0, 40.0};
  const auto warnings =
      validity_warnings(model_info("corlab2026p"), speeds, steel(5e8), steel(5e8));
  ASSERT_EQ(warnings.size(), 1U);
  EXPECT_NE(warnings[0].find("model 'corlab2026p' is less accurate: 2 of 3 velocities give a "
                             "damage number rho v^2/sigma_y above 0.003 (up to 0.0251)"),
            std::string::npos)
      << warnings[0];
  EXPECT_FALSE(model_info("corlab2026").accurate_damage_number.has_value());
  EXPECT_TRUE(validity_warnings(model_info("corlab2026"), speeds, steel(5e8), steel(5e8)).empty());
}

// Issue 42: `predict --radius-ratio 5` was accepted silently; the model fitted to R1/R2 <= 1
// says it extrapolates (and how to stay in range), the others (rho* only) need not.
TEST(ValidityWarnings, ARadiusRatioBeyondTheFittedOne) {
  EXPECT_EQ(
      radius_ratio_warning(model_info("corlab2026p"), 5.0),
      "model 'corlab2026p' extrapolates: radius_ratio = R1/R2 = 5 is beyond its fitted 1 (the "
      "sphere is the larger body; to stay in the fitted range give the other body as the "
      "sphere and R2/R1 = 0.2)");
  EXPECT_EQ(radius_ratio_warning(model_info("corlab2026p"), 1.0), "");
  EXPECT_EQ(radius_ratio_warning(model_info("corlab2026p"), 0.0), "");
  EXPECT_EQ(radius_ratio_warning(model_info("ma2023"), 1e6), "");
}

}  // namespace
}  // namespace corlab::restitution
