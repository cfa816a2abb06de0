// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/run_status.hpp"

#include <gtest/gtest.h>

namespace corlab::fem {
namespace {

TEST(RunStatus, NamesRoundTrip) {
  for (const RunStatus s :
       {RunStatus::kSeparated, RunStatus::kNotSeparated, RunStatus::kStepCollapsed,
        RunStatus::kElementInverted, RunStatus::kNonFinite, RunStatus::kStepBudgetExceeded,
        RunStatus::kCancelled, RunStatus::kMaxCompression}) {
    const auto back = run_status_from_string(to_string(s));
    ASSERT_TRUE(back.has_value()) << to_string(s);
    EXPECT_EQ(*back, s);
  }
  EXPECT_EQ(to_string(RunStatus::kSeparated), "separated");
  EXPECT_FALSE(run_status_from_string("ok").has_value());
}

}  // namespace
}  // namespace corlab::fem
