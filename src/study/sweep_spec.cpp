// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/study/sweep_spec.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "corlab/core/error.hpp"
#include "corlab/core/hash.hpp"
#include "corlab/core/number.hpp"
#include "corlab/core/text.hpp"
#include "corlab/core/text_file.hpp"
#include "spec_error.hpp"
#include "study/sweep_spec_detail.hpp"

namespace corlab::study {

namespace {

constexpr std::string_view kTopLevel = "[study], [base], [grid], [[cases]]";

/// A leaf of a TOML table with its dotted key and where it was written.
struct Leaf {
  std::string key;
  const toml::node* node = nullptr;
  std::uint32_t line = 0;
  std::uint32_t column = 0;
};

/// Flattens nested tables ([base.mesh] h_min = .., or mesh.h_min = ..) into dotted keys, in the
/// order they appear in the document (toml++ tables are sorted by key).
void collect_leaves(const toml::table& table, const std::string& prefix, std::vector<Leaf>& out) {
  for (const auto& [key, node] : table) {
    std::string full =
        prefix.empty() ? std::string(key.str()) : prefix + "." + std::string(key.str());
    if (const auto* sub = node.as_table()) {
      collect_leaves(*sub, full, out);
    } else {
      out.push_back({std::move(full), &node, node.source().begin.line, node.source().begin.column});
    }
  }
}

std::vector<Leaf> leaves_in_order(const toml::table& table,
                                  const SpecError& error,
                                  std::string_view section) {
  std::vector<Leaf> leaves;
  collect_leaves(table, "", leaves);
  std::set<std::string> keys;
  for (const Leaf& leaf : leaves) {
    if (!keys.insert(leaf.key).second) {
      error.fail(fmt::format("{}.\"{}\"", section, leaf.key),
                 "is set twice (as a quoted and as a dotted key)");
    }
  }
  std::stable_sort(leaves.begin(), leaves.end(), [](const Leaf& a, const Leaf& b) {
    return a.line != b.line ? a.line < b.line : a.column < b.column;
  });
  return leaves;
}

std::string value_text(const toml::node& node, const SpecError& error, const std::string& where) {
  if (const auto* s = node.as_string()) return s->get();
  if (const auto* i = node.as_integer()) return fmt::format("{}", i->get());
  if (const auto* f = node.as_floating_point()) return fmt::format("{}", f->get());
  if (const auto* b = node.as_boolean()) return b->get() ? "true" : "false";
  error.fail(where, "must be a number, a string or a boolean");
}

bool valid_name(std::string_view name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-';
  });
}

// A grid is a product: a few keys make millions of runs. Refuse more than [study] max_runs before
// anything is read or expanded (the count in double: it may not fit an integer). `lengths` are the
// grid's array lengths.
void check_run_count(const SweepSpec& spec,
                     const SpecError& error,
                     const std::vector<std::size_t>& lengths = {}) {
  double count = spec.cases.empty() ? 1.0 : static_cast<double>(spec.cases.size());
  for (const std::size_t n : lengths) count *= static_cast<double>(n);
  if (count > static_cast<double>(spec.max_runs)) {
    error.fail(
        "",
        fmt::format("expands to {:.0f} runs, more than [study] max_runs = {} (default "
                    "{}, at most {}){}",
                    count, spec.max_runs, kDefaultMaxRuns, kMaxRunsLimit,
                    count <= static_cast<double>(kMaxRunsLimit)
                        ? fmt::format("; set max_runs = {:.0f} in [study] to run them all", count)
                        : std::string("; split the study")));
  }
}

}  // namespace

std::string quoted_key(std::string_view key) { return fmt::format("\"{}\"", key); }

void set_or_replace(Settings& settings, const std::string& key, const std::string& value) {
  for (auto& [k, v] : settings) {
    if (k == key) {
      v = value;
      return;
    }
  }
  settings.emplace_back(key, value);
}

bool is_material_key(std::string_view key) {
  constexpr std::string_view suffix = ".material";
  return key.size() >= suffix.size() && key.substr(key.size() - suffix.size()) == suffix;
}

Settings application_order(Settings settings) {
  std::stable_partition(settings.begin(), settings.end(),
                        [](const Setting& s) { return is_material_key(s.first); });
  return settings;
}

/// Grid points in order, the last key varying fastest.
std::vector<Settings> grid_points(const SweepSpec& spec) {
  std::vector<Settings> points{Settings{}};
  for (const auto& [key, values] : spec.grid) {
    std::vector<Settings> next;
    next.reserve(points.size() * values.size());
    for (const auto& point : points) {
      for (const auto& value : values) {
        Settings extended = point;
        extended.emplace_back(key, value);
        next.push_back(std::move(extended));
      }
    }
    points = std::move(next);
  }
  return points;
}

Settings merged(const SweepSpec& spec, const Settings& case_settings, const Settings& point) {
  Settings all = spec.base;
  for (const auto& [k, v] : case_settings) set_or_replace(all, k, v);
  for (const auto& [k, v] : point) set_or_replace(all, k, v);
  return application_order(std::move(all));
}

std::string settings_summary(const Settings& settings) {
  std::string text;
  for (const auto& [k, v] : settings) {
    if (!text.empty()) text += ", ";
    text += fmt::format("{}={}", k, v);
  }
  return text;
}

void apply_settings(fem::ImpactConfig& config, const Settings& settings) {
  for (const auto& [key, value] : application_order(settings)) {
    fem::apply_setting(config, key, value);
  }
}

std::string case_id(const Settings& settings) {
  Settings sorted = settings;
  std::sort(sorted.begin(), sorted.end());
  std::string text;
  for (const auto& [k, v] : sorted) {
    text += k;
    text += '=';
    text += v;
    text += '\n';
  }
  return fmt::format("c{:010x}", fnv1a64(text) >> 24);
}

std::vector<SweepCase> SweepSpec::expand() const {
  std::vector<SweepCase> runs;
  runs.reserve(run_count());
  const auto points = grid_points(*this);
  const std::vector<Settings> all_cases = cases.empty() ? std::vector<Settings>{Settings{}} : cases;
  std::set<std::string> ids;
  for (const auto& case_settings : all_cases) {
    for (const auto& point : points) {
      SweepCase run;
      run.settings = merged(*this, case_settings, point);
      run.id = case_id(run.settings);
      if (!ids.insert(run.id).second) {
        throw InputError(fmt::format("invalid spec {}: two runs have identical settings ({})",
                                     origin, settings_summary(run.settings)));
      }
      apply_settings(run.config, run.settings);
      fem::validate(run.config);
      runs.push_back(std::move(run));
    }
  }
  return runs;
}

std::size_t SweepSpec::run_count() const {
  std::size_t count = cases.empty() ? 1 : cases.size();
  for (const auto& [key, values] : grid) count *= values.size();
  return count;
}

std::vector<std::string> SweepSpec::swept_keys() const {
  std::vector<std::string> keys;
  auto add = [&keys](const std::string& key) {
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
  };
  for (const auto& case_settings : cases) {
    for (const auto& [key, value] : case_settings) add(key);
  }
  for (const auto& [key, values] : grid) add(key);
  return keys;
}

std::string SweepSpec::to_toml() const {
  if (!toml_text.empty()) return toml_text;
  auto value = [](const std::string& v) {
    if (parse_double(v)) return v;
    std::ostringstream quoted;
    quoted << toml::value<std::string>(v);
    return quoted.str();
  };
  std::ostringstream out;
  out << "[study]\nname = " << toml::value<std::string>(name) << "\n";
  if (!description.empty())
    out << "description = " << toml::value<std::string>(description) << "\n";
  if (max_runs != kDefaultMaxRuns) out << "max_runs = " << max_runs << "\n";
  out << "\n[base]\n";
  for (const auto& [k, v] : base) out << quoted_key(k) << " = " << value(v) << "\n";
  if (!grid.empty()) {
    out << "\n[grid]\n";
    for (const auto& [k, values] : grid) {
      out << quoted_key(k) << " = [";
      for (std::size_t i = 0; i < values.size(); ++i) out << (i ? ", " : "") << value(values[i]);
      out << "]\n";
    }
  }
  for (const auto& case_settings : cases) {
    out << "\n[[cases]]\n";
    for (const auto& [k, v] : case_settings) out << quoted_key(k) << " = " << value(v) << "\n";
  }
  return out.str();
}

namespace {

toml::table parse_toml(std::string_view toml_text,
                       std::string_view origin,
                       const SpecError& error) {
  try {
    return toml::parse(toml_text, origin);
  } catch (const toml::parse_error& err) {
    error.fail(fmt::format("line {} column {}", err.source().begin.line, err.source().begin.column),
               fmt::format("not valid TOML: {}", err.description()));
  }
}

/// Only [study], [base], [grid] and [[cases]], each of its kind.
void check_top_level(const toml::table& root, const SpecError& error) {
  for (const auto& [key, node] : root) {
    const std::string_view k = key.str();
    if (k != "study" && k != "base" && k != "grid" && k != "cases") {
      error.fail("", fmt::format("unknown table or key '{}' (expected {})", k, kTopLevel));
    }
    if (k == "cases" ? !node.is_array_of_tables() : !node.is_table()) {
      error.fail("", k == "cases" ? std::string("'cases' must be a [[cases]] array of tables")
                                  : fmt::format("'{}' must be a [{}] table", k, k));
    }
  }
}

/// [study]: name, description, max_runs.
void read_study(const toml::table& root, const SpecError& error, SweepSpec& spec) {
  const toml::table* study = root["study"].as_table();
  if (study == nullptr) error.fail("", "missing [study] table with name = \"...\"");
  for (const auto& [key, node] : *study) {
    const std::string_view k = key.str();
    const std::string where = fmt::format("study.{}", k);
    if (k != "name" && k != "description" && k != "max_runs") {
      error.fail(where, "unknown key (expected name, description, max_runs)");
    }
    if (k == "max_runs") {
      const auto* n = node.as_integer();
      if (n == nullptr || n->get() < 1 || n->get() > static_cast<std::int64_t>(kMaxRunsLimit)) {
        error.fail(where, fmt::format("must be an integer in [1, {}]", kMaxRunsLimit));
      }
      spec.max_runs = static_cast<std::size_t>(n->get());
    } else if (!node.is_string()) {
      error.fail(where, "must be a string");
    }
  }
  spec.name = (*study)["name"].value_or(std::string());
  spec.description = (*study)["description"].value_or(std::string());
  if (!study->contains("name")) error.fail("study.name", "missing (required, [A-Za-z0-9_-]+)");
  if (!valid_name(spec.name))
    error.fail_value("study.name", spec.name, "must match [A-Za-z0-9_-]+");
}

/// [base] into spec.base; returns where each setting was written.
std::vector<std::string> read_base(const toml::table& root,
                                   const SpecError& error,
                                   SweepSpec& spec) {
  std::vector<std::string> base_where;
  if (const toml::table* base = root["base"].as_table()) {
    for (const Leaf& leaf : leaves_in_order(*base, error, "base")) {
      const std::string where = "base." + quoted_key(leaf.key);
      spec.base.emplace_back(leaf.key, value_text(*leaf.node, error, where));
      base_where.push_back(where);
    }
  }
  return base_where;
}

/// [[cases]] into spec.cases; returns where each setting of each case was written.
std::vector<std::vector<std::string>> read_cases(const toml::table& root,
                                                 const SpecError& error,
                                                 SweepSpec& spec) {
  std::vector<std::vector<std::string>> case_where;
  if (const toml::array* cases = root["cases"].as_array()) {
    for (std::size_t c = 0; c < cases->size(); ++c) {
      Settings settings;
      std::vector<std::string> wheres;
      for (const Leaf& leaf :
           leaves_in_order(*cases->get(c)->as_table(), error, fmt::format("cases[{}]", c))) {
        const std::string where = fmt::format("cases[{}].{}", c, quoted_key(leaf.key));
        settings.emplace_back(leaf.key, value_text(*leaf.node, error, where));
        wheres.push_back(where);
      }
      spec.cases.push_back(std::move(settings));
      case_where.push_back(std::move(wheres));
    }
  }
  return case_where;
}

/// Where two values of one grid key are equal, the first such pair (earlier index, later index) in
/// the order of the later one; O(n log n), so a long grid answers at once (the pairwise check took
/// 11 s for 80,000 values).
std::optional<std::pair<std::size_t, std::size_t>> first_duplicate(
    const std::vector<std::string>& values) {
  std::vector<std::size_t> order(values.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&values](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  std::optional<std::pair<std::size_t, std::size_t>> found;
  for (std::size_t k = 1; k < order.size(); ++k) {
    // stable: within a run of equal values the indices ascend, so order[k - 1] is the earlier
    if (values[order[k]] != values[order[k - 1]]) continue;
    const std::pair pair{order[k - 1], order[k]};
    if (!found || pair.second < found->second) found = pair;
  }
  return found;
}

/// [grid] into spec.grid: a non-empty array of distinct values per key. The run count (cases x
/// the product of the array lengths) is checked before any value is read.
void read_grid(const toml::table& root, const SpecError& error, SweepSpec& spec) {
  const toml::table* grid = root["grid"].as_table();
  if (grid == nullptr) {
    check_run_count(spec, error);
    return;
  }
  const std::vector<Leaf> leaves = leaves_in_order(*grid, error, "grid");
  std::vector<std::size_t> lengths;
  for (const Leaf& leaf : leaves) {
    const std::string where = "grid." + quoted_key(leaf.key);
    const toml::array* array = leaf.node->as_array();
    if (array == nullptr) error.fail(where, "must be a non-empty array of values");
    if (array->empty()) error.fail(where + " = []", "must be a non-empty array of values");
    lengths.push_back(array->size());
  }
  check_run_count(spec, error, lengths);
  for (const Leaf& leaf : leaves) {
    const std::string where = "grid." + quoted_key(leaf.key);
    const toml::array* array = leaf.node->as_array();
    std::vector<std::string> values;
    values.reserve(array->size());
    for (std::size_t i = 0; i < array->size(); ++i) {
      values.push_back(value_text(*array->get(i), error, fmt::format("{}[{}]", where, i)));
    }
    if (const auto dup = first_duplicate(values)) {
      const auto [j, i] = *dup;
      error.fail_value(fmt::format("{}[{}]", where, i), values[i],
                       fmt::format("must differ from {}[{}] (duplicate grid value)", where, j));
    }
    spec.grid.emplace_back(leaf.key, std::move(values));
  }
}

}  // namespace

SweepSpec parse_sweep_spec(std::string_view toml_text, std::string_view origin) {
  const SpecError error{std::string(origin)};
  const toml::table root = parse_toml(toml_text, origin, error);
  SweepSpec spec;
  spec.origin = std::string(origin);
  spec.toml_text = std::string(toml_text);
  check_top_level(root, error);
  read_study(root, error, spec);
  SpecPlaces places;
  places.base = read_base(root, error, spec);
  places.cases = read_cases(root, error, spec);
  read_grid(root, error, spec);
  validate_spec(spec, error, places);
  return spec;
}

SweepSpec load_sweep_spec(const std::filesystem::path& file) {
  return parse_sweep_spec(read_text_file(file, "spec", {.max_bytes = kMaxSpecFileBytes}),
                          file.string());
}

}  // namespace corlab::study
