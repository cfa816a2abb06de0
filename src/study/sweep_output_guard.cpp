// One output directory holds one study: a second, different study is refused before it can mix
// its rows into results.csv, and a results.csv with a case twice is refused on resume.
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>

#include "corlab/core/error.hpp"
#include "corlab/core/text_file.hpp"
#include "corlab/study/results_table.hpp"
#include "sweep_internal.hpp"

namespace corlab::study::detail {

namespace {

Settings sorted(Settings settings) {
  std::sort(settings.begin(), settings.end());
  return settings;
}

}  // namespace

void check_same_study(const SweepSpec& spec, const std::filesystem::path& out_dir) {
  const auto previous_file = out_dir / "spec.toml";
  if (!std::filesystem::exists(previous_file)) return;
  const std::string where = fmt::format("invalid --out = '{}'", out_dir.string());
  SweepSpec previous;
  try {
    previous =
        parse_sweep_spec(read_text_file(previous_file, "spec", {.max_bytes = kMaxSpecFileBytes}),
                         previous_file.string());
  } catch (const InputError& err) {
    throw InputError(fmt::format(
        "{}: must hold this study or none, but its spec.toml cannot be read ({}); use another "
        "--out",
        where, err.what()));
  }
  if (previous.name != spec.name) {
    throw InputError(fmt::format(
        "{}: holds study '{}', not '{}' (a second study would mix its rows into results.csv); "
        "use another --out",
        where, previous.name, spec.name));
  }
  // Cases and grid values may be added (their ids are stable); what every run shares may not
  // change.
  if (sorted(previous.base) != sorted(spec.base)) {
    std::vector<std::string> was, now;
    for (const auto& [k, v] : sorted(previous.base)) was.push_back(fmt::format("{}={}", k, v));
    for (const auto& [k, v] : sorted(spec.base)) now.push_back(fmt::format("{}={}", k, v));
    throw InputError(fmt::format(
        "{}: holds study '{}' with another [base] ({} there, {} here; its rows would mix with "
        "these in results.csv); use another --out",
        where, spec.name, fmt::join(was, ", "), fmt::join(now, ", ")));
  }
}

void check_no_duplicate_rows(const std::filesystem::path& csv, const ExistingResults& existing) {
  if (existing.rows == existing.status.size()) return;
  std::map<std::string, int> count;
  const ResultsTable table = read_results(csv);  // named: text() refers into it
  for (const auto& id : table.text("case_id")) ++count[id];
  std::vector<std::string> twice;
  for (const auto& [id, n] : count) {
    if (n > 1) twice.push_back(fmt::format("{} x{}", id, n));
  }
  throw InputError(fmt::format(
      "invalid {}: must hold each case once, but {} case(s) appear more than once ({}); remove "
      "the duplicated rows or use another --out",
      csv.string(), twice.size(), fmt::join(twice, ", ")));
}

}  // namespace corlab::study::detail
