// The 3-D model's steps (hex_step.cpp) in the time loop every geometry shares (time_loop.hpp):
// its history rows, status details, cancellation and the stop at maximum compression, as the
// axisymmetric model's.
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <string>

#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/solver/simulate.hpp"
#include "support/hex_cases.hpp"

namespace corlab::fem {
namespace {

// The elastic steel sphere sliding on the rigid flat (7,542 elements), stopped 50 us into its
// 280 us contact unless `full`.
ImpactConfig sliding(bool full = false) {
  ImpactConfig c = test::sliding_on_rigid_flat();
  if (!full) c.solver.t_max = contact_start_time(c) + 5e-5;
  return c;
}

TEST(HexStep, ARunWritesHistoryRowsAndAStatusDetail) {
  const ImpactConfig c = sliding();
  const ImpactResult r = simulate(c);
  ASSERT_EQ(r.status, RunStatus::kNotSeparated);
  EXPECT_EQ(r.status_detail.rfind("no clean rebound by t_max = ", 0), 0u) << r.status_detail;
  const ImpactHistory& h = r.history;
  // A row at every output.history_every-th step, from step 0.
  const auto every = static_cast<long long>(c.output.history_every);
  ASSERT_EQ(static_cast<long long>(h.time.size()), (r.steps + every - 1) / every);
  // The whole sphere's kinetic energy at the start (both halves), the clock from the release.
  EXPECT_NEAR(h.kinetic_energy.front() / r.energy_initial, 1.0, 1e-12);
  EXPECT_NEAR(h.time.front(), contact_start_time(c), 1e-15);
  EXPECT_GT(h.time.back(), h.time.front());
  // In contact at the end: a force and an indentation, the energy balance closed (friction
  // included).
  EXPECT_GT(h.contact_force.back(), 0.0);
  EXPECT_GT(h.indentation.back(), 0.0);
  EXPECT_GT(*std::max_element(h.contact_energy.begin(), h.contact_energy.end()), 0.0);
  for (const double b : h.energy_balance_error) EXPECT_LT(std::abs(b), 1e-3);
  EXPECT_EQ(r.element_updates, static_cast<long long>(r.elements) * r.steps);
}

TEST(HexStep, CancelAndMaxCompressionStopTheRun) {
  const ImpactConfig c = sliding();
  const std::atomic<bool> cancel{true};
  SimulationControl control;
  control.cancel = &cancel;
  const ImpactResult cancelled = simulate(c, control);
  EXPECT_EQ(cancelled.status, RunStatus::kCancelled);
  EXPECT_EQ(cancelled.status_detail, "interrupted");
  EXPECT_EQ(cancelled.steps, 0);

  ImpactConfig longer = sliding(true);
  SimulationControl compression;
  compression.stop_at_max_compression = true;
  const ImpactResult r = simulate(longer, compression);
  ASSERT_EQ(r.status, RunStatus::kMaxCompression);
  EXPECT_EQ(r.status_detail.rfind("stopped at maximum compression", 0), 0u) << r.status_detail;
  EXPECT_GT(r.delta_max, 0.0);
}

}  // namespace
}  // namespace corlab::fem
