// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file impact_output.hpp
/// Writers for one impact: the history table (CSV) and the summary (JSON, with the config echoed).

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/solver/impact_result.hpp"

namespace corlab::fem {

/// The config as JSON (SI units): every key of config_keys() at its config_echo_path, e.g.
/// {"impact": {"velocity": 5.0}, "sphere": {"material": {"name": ..., "E": ...}}}.
nlohmann::json config_to_json(const ImpactConfig& config);

/// The summary of a result (no history): every field of result_fields() written to the summary,
/// their units under "units" and the config under "config".
nlohmann::json summary_to_json(const ImpactResult& result, const ImpactConfig& config);

/// Writes summary_to_json to `file` (pretty-printed) with write_file_atomically, so a reader never
/// sees a partial summary. Throws std::runtime_error on I/O failure.
void write_summary_json(const ImpactResult& result,
                        const ImpactConfig& config,
                        const std::filesystem::path& file);

/// One line on the requested output.times outside the run: before its start (gap / velocity: the
/// first step's field file stands for them) or after its end (no field file), e.g.
/// "output.times 0.0003 s (1 of 3) after the run's end at 0.00021 s: no field file for it";
/// empty when every requested time is inside the run.
std::string unreached_output_times(const ImpactConfig& config, const ImpactResult& result);

/// Writes the history as CSV with a header naming the units, one row per history entry.
void write_history_csv(const ImpactHistory& history, const std::filesystem::path& file);

}  // namespace corlab::fem
