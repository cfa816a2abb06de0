// Quality guards of run_quality.hpp: each limit trips on its own and names itself.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/run_quality.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace corlab::fem {
namespace {

ImpactResult clean_run() {
  ImpactResult r;
  r.status = RunStatus::kSeparated;
  r.energy_initial = 100.0;
  r.energy_balance_error = 4.6e-7;  // paper case
  r.energy_hourglass = 0.049;       // 0.049 %
  r.delta_max = 1e-3;
  r.penetration_max = 3.5e-6;  // 0.35 %
  return r;
}

TEST(RunQuality, VerificationLevelsAreNotSuspect) { EXPECT_EQ(suspect_reason(clean_run()), ""); }

TEST(RunQuality, EnergyBalance) {
  ImpactResult r = clean_run();
  r.energy_balance_error = 12.2;  // penalty_scale = safety_factor = 1 (issue 12)
  EXPECT_NE(suspect_reason(r).find("energy balance error 1.22e+03 %"), std::string::npos);
  r.energy_balance_error = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(suspect_reason(r).find("energy balance"), std::string::npos);
}

TEST(RunQuality, Hourglass) {
  ImpactResult r = clean_run();
  r.energy_hourglass = 6.3;  // solver.hourglass = 10 (issue 12)
  EXPECT_NE(suspect_reason(r).find("hourglass energy 6.3 %"), std::string::npos);
  r.energy_hourglass = 0.45;
  EXPECT_EQ(suspect_reason(r), "");
}

TEST(RunQuality, Penetration) {
  ImpactResult r = clean_run();
  r.penetration_max = 0.91e-3;  // penalty_scale = 1e-3 on a coarse mesh (issue 12)
  EXPECT_NE(suspect_reason(r).find("penetration 91 %"), std::string::npos);
  QualityLimits loose;
  loose.penetration = 1.0;
  EXPECT_EQ(suspect_reason(r, loose), "");
}

// Issue 42: of 100 repeated impacts 26 had e above 1 (up to 1.00277) with `suspect` empty. An e
// above 1 beyond round-off, or beyond its error bar when it has one, is suspect, naming the
// impact.
TEST(RunQuality, RestitutionAboveOneBeyondItsBar) {
  ImpactResult r = clean_run();
  r.e = 0.98;
  r.e_impacts = {0.98, 0.999, 1.00277, 1.001};
  EXPECT_EQ(suspect_reason(r),
            "e_impacts[2] = 1.00277 above 1 by more than round-off (1e-06): the rebound gained "
            "energy");
  r.e_impacts = {0.98, 1.0000004};  // round-off
  EXPECT_EQ(suspect_reason(r), "");
  r.e = 1.5034;  // impact.angle = 89 with friction 10 (issue 42)
  r.e_impacts = {r.e};
  EXPECT_EQ(suspect_reason(r).rfind("e = 1.5034 above 1 by more than round-off", 0), 0u);
  r.e = 1.002;
  r.e_impacts = {r.e};
  r.e_error = 0.005;  // within its error bar
  EXPECT_EQ(suspect_reason(r), "");
  r.e_error = 0.001;  // beyond it
  EXPECT_EQ(suspect_reason(r),
            "e = 1.002 above 1 by more than its error bar e_error (0.001): the rebound gained "
            "energy");
}

}  // namespace
}  // namespace corlab::fem
