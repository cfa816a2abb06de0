// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file config_keys.hpp
/// The one table of ImpactConfig text keys (`--set key=value`, TOML tables, sweep specs): for every
/// key its unit, allowed range, default and meaning. Parsing (apply_setting), range validation
/// (validate), `corlab simulate --help` and the error messages all come from this table; adding a
/// key is one entry in config_keys.cpp.

#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "corlab/fem/config/impact_config.hpp"

namespace corlab::fem {

/// How a key's text is read.
enum class KeyKind {
  number,        ///< one finite number
  integer,       ///< one integer
  number_list,   ///< comma-separated numbers, optionally in [brackets] (TOML: an array)
  yield_stress,  ///< a number, or `none` for a purely elastic body
  material,      ///< a database name and/or E=..,nu=..,rho=..[,sy=..][,H=..] (one of each)
  path,          ///< a file name
  choice,        ///< one of a few names (substrate.shape: flat, rigid)
};

/// Allowed interval of a numeric key; `why` says where the limits come from (may be empty).
struct KeyRange {
  double lo = 0.0;
  double hi = 0.0;
  bool lo_open = false;  ///< true: lo itself is excluded
  bool hi_open = false;  ///< true: hi itself is excluded
  std::string_view why;

  bool contains(double value) const;
  /// "in (0, 1] [m] (why)", the constraint of the error message.
  std::string text(std::string_view unit) const;
};

/// Public description of one key.
struct ConfigKeyInfo {
  std::string_view key;  ///< e.g. "impact.velocity"
  KeyKind kind = KeyKind::number;
  std::string_view unit;          ///< e.g. "[m/s]", "[-]"; empty for text keys
  std::optional<KeyRange> range;  ///< for number, integer, number_list and yield_stress keys
  std::string_view doc;           ///< one line
  /// Empty: summary.json echoes the key at its dotted name. Else the material key whose object
  /// holds it under the key's last name (sphere.E is echoed as sphere.material.E).
  std::string_view echo_in;
};

/// Every key, in documentation order.
const std::vector<ConfigKeyInfo>& config_keys();

/// The entry of `key`, or nullptr.
const ConfigKeyInfo* find_config_key(std::string_view key);

/// Every key name, in table order.
std::vector<std::string> config_key_names();

/// Reads `value` (text) into `key` of `config` (syntax only; ranges: validate_key_ranges). Throws
/// InputError for an unknown key ("must be one of ...") or unreadable text.
void set_config_key(ImpactConfig& config, std::string_view key, std::string_view value);

/// The table as text (key, unit, range, default, doc), one key per line, for `--help` and docs.
std::string config_keys_help();

/// The current value of `key` in `config` as text (defaults: of ImpactConfig{}).
std::string config_value_text(const ImpactConfig& config, std::string_view key);

/// The current value of `key` in `config` as JSON: a number, an integer, a list as an array, an
/// unset yield stress as null, a material as {name, E, nu, rho, sigma_y, hardening, source}, a
/// path as a string. Null for an unknown key.
nlohmann::json config_value_json(const ImpactConfig& config, std::string_view key);

/// Where summary.json's config echo puts `info`'s value: its dotted name split at the dots
/// ({"impact", "velocity"}), or under its `echo_in` key ({"sphere", "material", "E"}).
std::vector<std::string> config_echo_path(const ConfigKeyInfo& info);

/// Checks every numeric key of `config` against its range; throws InputError
/// "invalid <key> = <value>: must be in [lo, hi] <unit> (<why>)" for the first one outside.
void validate_key_ranges(const ImpactConfig& config);

}  // namespace corlab::fem
