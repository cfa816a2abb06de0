// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file run_status.hpp
/// How one impact run ended. Only `kSeparated` is a clean rebound whose e may be reported; every
/// other status leaves e undefined (NaN in the result, null in JSON, empty in CSV).

#include <optional>
#include <string_view>

namespace corlab::fem {

enum class RunStatus {
  kSeparated,           ///< the sphere left the substrate moving away from it; e is valid
  kNotSeparated,        ///< t_max reached before a clean rebound
  kStepCollapsed,       ///< the stable time step fell below kMinStepFraction of the first step
  kElementInverted,     ///< an element reached zero or negative area / volume
  kNonFinite,           ///< a NaN or infinity appeared in the state (energies)
  kStepBudgetExceeded,  ///< more steps than solver.max_steps
  kCancelled,           ///< stopped on request (Ctrl-C, sweep interruption)
  kMaxCompression,      ///< stopped on request at maximum compression (yield-onset probes)
};

/// The status's name in outputs (summary.json, results.csv, Python): "separated", ...
std::string_view to_string(RunStatus status);
/// The status named `name`, or nullopt.
std::optional<RunStatus> run_status_from_string(std::string_view name);

}  // namespace corlab::fem
