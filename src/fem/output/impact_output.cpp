// History CSV and summary JSON of one impact.
#include "corlab/fem/output/impact_output.hpp"

#include <fmt/format.h>

#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>

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

}  // namespace corlab::fem
