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

}  // namespace
}  // namespace corlab::fem
