// History CSV and summary JSON of one impact.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/output/impact_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "corlab/core/atomic_file.hpp"
#include "corlab/fem/config/config_keys.hpp"
#include "corlab/fem/solver/history_columns.hpp"
#include "corlab/fem/solver/result_fields.hpp"

namespace corlab::fem {

namespace {

std::ofstream open_for_writing(const std::filesystem::path& file) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error(fmt::format("cannot write '{}'", file.string()));
  return out;
}

}  // namespace

nlohmann::json config_to_json(const ImpactConfig& config) {
  nlohmann::json j = nlohmann::json::object();
  for (const ConfigKeyInfo& key : config_keys()) {
    nlohmann::json* node = &j;
    for (const std::string& name : config_echo_path(key)) node = &(*node)[name];
    *node = config_value_json(config, key.key);
  }
  return j;
}

nlohmann::json summary_to_json(const ImpactResult& r, const ImpactConfig& config) {
  nlohmann::json j;
  nlohmann::json units = nlohmann::json::object();
  const FieldInput in{&r, &config, r.wall_s};
  for (const ResultField& f : result_fields()) {
    if ((f.outputs & kSummary) == 0) continue;
    const std::string name(f.name);
    std::visit(
        [&](const auto& v) {
          if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::monostate>) {
            j[name] = nullptr;
          } else {
            j[name] = v;
          }
        },
        f.value(in));
    if (f.unit == "-") continue;
    // The energies share one entry, as summary.json has always written them.
    units[f.unit == "J" && name.starts_with("energy_") ? "energy_*" : name] = f.unit;
  }
  j["units"] = std::move(units);
  j["config"] = config_to_json(config);
  return j;
}

void write_summary_json(const ImpactResult& result,
                        const ImpactConfig& config,
                        const std::filesystem::path& file) {
  write_file_atomically(file, summary_to_json(result, config).dump(2) + '\n');
}

void write_history_csv(const ImpactHistory& h, const std::filesystem::path& file) {
  auto out = open_for_writing(file);
  const auto columns = history_columns();
  std::string line;
  for (const HistoryColumn& c : columns) {
    if (!line.empty()) line += ',';
    line += history_csv_header(c);
  }
  out << line << '\n';
  for (std::size_t i = 0; i < h.time.size(); ++i) {
    line.clear();
    for (const HistoryColumn& c : columns) {
      if (!line.empty()) line += ',';
      fmt::format_to(std::back_inserter(line), "{:.{}g}", (h.*c.series)[i], c.digits);
    }
    out << line << '\n';
  }
  if (!out) throw std::runtime_error(fmt::format("cannot write '{}'", file.string()));
}

namespace {

/// "1e-05, 2e-05 s (2 of 3)": at most five of `times`, how many of `all`.
std::string listed(std::vector<double> times, std::size_t all) {
  std::sort(times.begin(), times.end());
  constexpr std::size_t kShown = 5;
  std::string text;
  for (std::size_t i = 0; i < std::min(times.size(), kShown); ++i) {
    text += fmt::format("{}{:.6g}", i == 0 ? "" : ", ", times[i]);
  }
  if (times.size() > kShown) text += ", ...";
  return fmt::format("{} s ({} of {})", text, times.size(), all);
}

}  // namespace

std::string unreached_output_times(const ImpactConfig& config, const ImpactResult& result) {
  // The run starts when the sphere reaches the substrate: the gap is crossed in exact free flight
  // (impact_model.cpp, t_start), so no step falls before it.
  const double start = contact_start_time(config);
  std::vector<double> early;
  std::vector<double> late;
  for (const double t : config.output.field_times) {
    if (t < start) early.push_back(t);
    if (t > result.end_time) late.push_back(t);
  }
  const std::size_t all = config.output.field_times.size();
  std::string text;
  if (!early.empty()) {
    text = fmt::format(
        "output.times {} before the run's start at {:.6g} s (gap / normal speed): the first step's "
        "field file stands for {}",
        listed(early, all), start, early.size() == 1 ? "it" : "them");
  }
  if (!late.empty()) {
    text += fmt::format("{}output.times {} after the run's end at {:.6g} s: no field file for {}",
                        text.empty() ? "" : "; ", listed(late, all), result.end_time,
                        late.size() == 1 ? "it" : "them");
  }
  return text;
}

}  // namespace corlab::fem
