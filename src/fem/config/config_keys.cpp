// ImpactConfig keys (config_keys.hpp): the parsing, range checks, echo and help text that come
// from the key table (config_key_table.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/config/config_keys.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <type_traits>
#include <variant>

#include "corlab/core/error.hpp"
#include "corlab/core/number.hpp"
#include "corlab/core/text.hpp"
#include "corlab/materials/material_database.hpp"
#include "fem/config/choice_keys.hpp"
#include "fem/config/config_key_table.hpp"

namespace corlab::fem {

namespace {

using config_table::find_entry;
using config_table::key_table;
using config_table::KeyEntry;

long long parse_integer_value(std::string_view key, std::string_view text) {
  text = trim(text);
  const std::optional<long long> value = parse_integer(text);
  if (!value) throw_invalid(key, text, "an integer");
  return *value;
}

std::vector<double> parse_list(std::string_view key, std::string_view text) {
  std::vector<double> out;
  text = trim(text);
  if (!text.empty() && text.front() == '[' && text.back() == ']') {
    text = trim(text.substr(1, text.size() - 2));
  }
  if (text.empty()) return out;
  while (true) {
    const auto comma = text.find(',');
    out.push_back(parse_finite(key, text.substr(0, comma)));
    if (comma == std::string_view::npos) break;
    text.remove_prefix(comma + 1);
  }
  return out;
}

// `none` clears the yield stress; an empty value is an error (an unset shell variable must not
// silently turn plasticity off).
std::optional<double> parse_yield(std::string_view key, std::string_view text) {
  const auto t = trim(text);
  if (t == "none") return std::nullopt;
  if (t.empty()) throw_invalid(key, t, "a finite number, or `none` for an elastic body");
  return parse_finite(key, t);
}

// Reads `text` into the value `e` gives access to.
void set_value(const KeyEntry& e, ImpactConfig& c, std::string_view text) {
  const std::string_view key = e.info.key;
  std::visit(
      [&](auto get) {
        auto* target = get(c);
        using T = std::remove_pointer_t<decltype(target)>;
        if constexpr (std::is_same_v<T, double>) {
          *target = parse_finite(key, text);
        } else if constexpr (std::is_same_v<T, long long>) {
          *target = parse_integer_value(key, text);
        } else if constexpr (std::is_same_v<T, int>) {
          const long long v = parse_integer_value(key, text);
          if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) {
            throw_invalid(key, text, "an integer that fits 32 bits");
          }
          *target = static_cast<int>(v);
        } else if constexpr (std::is_same_v<T, std::optional<double>>) {
          *target = parse_yield(key, text);
        } else if constexpr (std::is_same_v<T, std::vector<double>>) {
          *target = parse_list(key, text);
        } else if constexpr (std::is_same_v<T, Material>) {
          const std::string body(key.substr(0, key.find('.')));
          try {
            *target = parse_material_spec(trim(text), body);
          } catch (const InputError& err) {
            // An error about the whole spec (unknown name, incomplete) names the key itself.
            if (err.field() != body) throw;
            throw InputError(std::string(key), err.value(), err.constraint(), true);
          }
        } else if constexpr (config_choices::kIsChoice<T>) {
          *target = config_choices::parse_choice<T>(key, text);
        } else if constexpr (std::is_same_v<T, PlaneAngle>) {
          *target = PlaneAngle::degrees(parse_finite(key, text));
        } else {
          *target = std::string(trim(text));
        }
      },
      e.access);
}

// The numeric values of a key (none for text keys and an unset yield stress).
std::vector<double> numbers_of(const KeyEntry& e, ImpactConfig& c) {
  return std::visit(
      [&](auto get) -> std::vector<double> {
        const auto* v = get(c);
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(v)>>;
        if constexpr (std::is_arithmetic_v<T>) {
          return {static_cast<double>(*v)};
        } else if constexpr (std::is_same_v<T, PlaneAngle>) {
          return {v->in_degrees()};
        } else if constexpr (std::is_same_v<T, std::optional<double>>) {
          return *v ? std::vector<double>{**v} : std::vector<double>{};
        } else if constexpr (std::is_same_v<T, std::vector<double>>) {
          return *v;
        } else {
          return {};
        }
      },
      e.access);
}

std::string text_of(const KeyEntry& e, ImpactConfig& c) {
  return std::visit(
      [&](auto get) -> std::string {
        const auto* v = get(c);
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(v)>>;
        if constexpr (std::is_arithmetic_v<T>) {
          return fmt::format("{}", *v);
        } else if constexpr (std::is_same_v<T, PlaneAngle>) {
          return fmt::format("{}", v->in_degrees());
        } else if constexpr (std::is_same_v<T, std::optional<double>>) {
          return *v ? fmt::format("{}", **v) : std::string("none");
        } else if constexpr (std::is_same_v<T, std::vector<double>>) {
          return fmt::format("[{}]", fmt::join(*v, ", "));
        } else if constexpr (std::is_same_v<T, Material>) {
          return v->name;
        } else if constexpr (config_choices::kIsChoice<T>) {
          return std::string(to_string(*v));
        } else {
          return v->string();
        }
      },
      e.access);
}

nlohmann::json material_json(const Material& m) {
  return {{"name", m.name},
          {"E", m.youngs_modulus},
          {"nu", m.poisson_ratio},
          {"rho", m.density},
          {"sigma_y", m.yield_stress ? nlohmann::json(*m.yield_stress) : nlohmann::json(nullptr)},
          {"hardening", m.hardening_modulus},
          {"source", m.source}};
}

nlohmann::json json_of(const KeyEntry& e, ImpactConfig& c) {
  return std::visit(
      [&](auto get) -> nlohmann::json {
        const auto* v = get(c);
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(v)>>;
        if constexpr (std::is_same_v<T, std::optional<double>>) {
          return *v ? nlohmann::json(**v) : nlohmann::json(nullptr);
        } else if constexpr (std::is_same_v<T, Material>) {
          return material_json(*v);
        } else if constexpr (std::is_same_v<T, std::filesystem::path>) {
          return v->string();
        } else if constexpr (config_choices::kIsChoice<T>) {
          return std::string(to_string(*v));
        } else if constexpr (std::is_same_v<T, PlaneAngle>) {
          return v->in_degrees();
        } else {
          return *v;
        }
      },
      e.access);
}

}  // namespace

bool KeyRange::contains(double value) const {
  if (!std::isfinite(value)) return false;
  const bool above = lo_open ? value > lo : value >= lo;
  const bool below = hi_open ? value < hi : value <= hi;
  return above && below;
}

std::string KeyRange::text(std::string_view unit) const {
  std::string out = std::isinf(hi) ? fmt::format("{} {}", lo_open ? ">" : ">=", lo)
                                   : fmt::format("in {}{}, {}{}", lo_open ? '(' : '[', lo, hi,
                                                 hi_open ? ')' : ']');
  if (!unit.empty()) out += fmt::format(" {}", unit);
  if (!why.empty()) out += fmt::format(" ({})", why);
  return out;
}

const std::vector<ConfigKeyInfo>& config_keys() {
  static const std::vector<ConfigKeyInfo> infos = [] {
    std::vector<ConfigKeyInfo> out;
    for (const auto& e : key_table()) out.push_back(e.info);
    return out;
  }();
  return infos;
}

const ConfigKeyInfo* find_config_key(std::string_view key) {
  const KeyEntry* e = find_entry(key);
  return e == nullptr ? nullptr : &e->info;
}

std::string config_value_text(const ImpactConfig& config, std::string_view key) {
  const KeyEntry* e = find_entry(key);
  if (e == nullptr) return {};
  ImpactConfig copy = config;
  return text_of(*e, copy);
}

nlohmann::json config_value_json(const ImpactConfig& config, std::string_view key) {
  const KeyEntry* e = find_entry(key);
  if (e == nullptr) return nullptr;
  ImpactConfig copy = config;
  return json_of(*e, copy);
}

std::vector<std::string> config_echo_path(const ConfigKeyInfo& info) {
  std::vector<std::string> path;
  std::string_view rest = info.echo_in.empty() ? info.key : info.echo_in;
  for (auto dot = rest.find('.'); dot != std::string_view::npos; dot = rest.find('.')) {
    path.emplace_back(rest.substr(0, dot));
    rest.remove_prefix(dot + 1);
  }
  path.emplace_back(rest);
  if (!info.echo_in.empty()) path.emplace_back(info.key.substr(info.key.rfind('.') + 1));
  return path;
}

void set_config_key(ImpactConfig& config, std::string_view key, std::string_view value) {
  key = trim(key);
  const KeyEntry* e = find_entry(key);
  if (e == nullptr) {
    throw_invalid("config key", key, fmt::format("one of {}", fmt::join(config_key_names(), ", ")));
  }
  set_value(*e, config, value);
}

void validate_key_ranges(const ImpactConfig& config) {
  ImpactConfig copy = config;  // the accessors take a mutable config; nothing is written
  for (const auto& e : key_table()) {
    if (!e.info.range) continue;
    for (const double v : numbers_of(e, copy)) {
      if (!e.info.range->contains(v)) throw_invalid(e.info.key, v, e.info.range->text(e.info.unit));
    }
  }
}

std::string config_keys_help() {
  const ImpactConfig defaults;
  std::string out = "Config keys (--set key=value, TOML [table] key = value; SI units):\n";
  for (const auto& e : key_table()) {
    const std::string range = e.info.range ? e.info.range->text(e.info.unit) : std::string("text");
    const std::string value = config_value_text(defaults, e.info.key);
    out += fmt::format("  {:<32} {} (default {})\n      {}\n", e.info.key, e.info.doc,
                       value.empty() ? "none" : value, range);
  }
  return out;
}

std::vector<std::string> config_key_names() {
  std::vector<std::string> names;
  for (const auto& e : key_table()) names.emplace_back(e.info.key);
  return names;
}

}  // namespace corlab::fem
