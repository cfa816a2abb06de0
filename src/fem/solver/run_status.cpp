// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/run_status.hpp"

#include <array>
#include <utility>

namespace corlab::fem {
namespace {

constexpr std::array<std::pair<RunStatus, std::string_view>, 8> kNames{{
    {RunStatus::kSeparated, "separated"},
    {RunStatus::kNotSeparated, "not_separated"},
    {RunStatus::kStepCollapsed, "step_collapsed"},
    {RunStatus::kElementInverted, "element_inverted"},
    {RunStatus::kNonFinite, "non_finite"},
    {RunStatus::kStepBudgetExceeded, "step_budget_exceeded"},
    {RunStatus::kCancelled, "cancelled"},
    {RunStatus::kMaxCompression, "max_compression"},
}};

}  // namespace

std::string_view to_string(RunStatus status) {
  for (const auto& [s, name] : kNames) {
    if (s == status) return name;
  }
  return "unknown";
}

std::optional<RunStatus> run_status_from_string(std::string_view name) {
  for (const auto& [s, n] : kNames) {
    if (n == name) return s;
  }
  return std::nullopt;
}

}  // namespace corlab::fem
