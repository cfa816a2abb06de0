// The accepted ranges of the solver parameters (config_keys.cpp) are ranges where the paper case
// still verifies: at each end of each range, e stays within 1 % of the default run's, the energy
// balance within 2e-5, the hourglass energy below 0.1 % of the initial energy (the README's
// criterion) and the contact penetration below 2 % of the indentation. The ends are read from the
// key table, so widening a range makes this test check the new end.
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "corlab/fem/config/config_keys.hpp"
#include "corlab/fem/solver/simulate.hpp"

namespace corlab::fem {
namespace {

const ImpactResult& default_run() {
  static const ImpactResult r = simulate(ImpactConfig{});
  return r;
}

struct RangeEnd {
  std::string key;
  bool upper = false;
};

class SolverParameterRange : public ::testing::TestWithParam<RangeEnd> {};

TEST_P(SolverParameterRange, PaperCaseStillVerifies) {
  const RangeEnd& end = GetParam();
  const ConfigKeyInfo* info = find_config_key(end.key);
  ASSERT_NE(info, nullptr);
  ASSERT_TRUE(info->range.has_value());
  const double value = end.upper ? info->range->hi : info->range->lo;
  ImpactConfig config;
  set_config_key(config, end.key, std::to_string(value));
  if (end.key == "solver.penalty_scale" && end.upper) {
    set_config_key(config, "solver.safety_factor", "0.8");  // <= 1/sqrt(1.5), the joint limit
  }
  ASSERT_NO_THROW(validate(config)) << end.key << " = " << value;
  const ImpactResult r = simulate(config);
  const ImpactResult& ref = default_run();
  EXPECT_TRUE(r.separated);
  // Measured 2026-11-27 (AMD EPYC, AVX-512) at hourglass 0.15 / 0, bulk_viscosity_linear 0.12 /
  // 0, bulk_viscosity_quadratic 2, penalty_scale 0.5 / 0.1:
  // e vs default: +4.4e-3, -3.9e-3, -4.4e-4, +1.4e-4, -3.5e-9, -2.2e-3, +9.4e-3. Bound 1 % kept,
  // not tightened: penalty_scale = 0.1 sits at 0.94 %.
  EXPECT_NEAR(r.e, ref.e, 0.01 * ref.e) << end.key << " = " << value;
  // Balance: 3.0e-6, 3.9e-6, 3.2e-6, 3.4e-6, 3.0e-6, 5.1e-6, 1.2e-6. Bound 2e-5 (was 1e-4):
  // 3.9x the largest (penalty_scale = 0.5); the unbooked subcycling transit gave 2.1e-4.
  EXPECT_LT(r.energy_balance_error, 2e-5);
  // Hourglass / E0: 9.86e-4, 0, 5.30e-4, 5.36e-4, 5.32e-4, 5.27e-4, 5.27e-4. Bound 1e-3 kept,
  // not tightened: hourglass = 0.15 sits at 0.986 of it (the README's criterion).
  EXPECT_LT(r.energy_hourglass, 1e-3 * r.energy_initial);
  // Penetration / delta_max: 0.35, 0.36, 0.31, 0.40, 0.35, 0.20, 0.97 %. Bound 2 % kept:
  // 2.1x the penalty_scale = 0.1 end (penetration ~ 1 / penalty), already "a few times".
  EXPECT_LT(r.penetration_max, 0.02 * r.delta_max);
}

INSTANTIATE_TEST_SUITE_P(RangeEnds,
                         SolverParameterRange,
                         ::testing::Values(RangeEnd{"solver.hourglass", true},
                                           RangeEnd{"solver.hourglass", false},
                                           RangeEnd{"solver.bulk_viscosity_linear", true},
                                           RangeEnd{"solver.bulk_viscosity_linear", false},
                                           RangeEnd{"solver.bulk_viscosity_quadratic", true},
                                           RangeEnd{"solver.penalty_scale", true},
                                           RangeEnd{"solver.penalty_scale", false}),
                         [](const auto& param_info) {
                           std::string name = param_info.param.key.substr(7) +
                                              (param_info.param.upper ? "_max" : "_min");
                           return name;
                         });

}  // namespace
}  // namespace corlab::fem
