// Validation and text input (--set key=value, TOML) of ImpactConfig. The keys, their units and
// ranges are the table of config_keys.cpp; the limits that join keys are config_limits.cpp.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/config/impact_config.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "corlab/core/error.hpp"
#include "corlab/core/text.hpp"
#include "corlab/core/text_file.hpp"
#include "corlab/core/units.hpp"
#include "corlab/fem/config/config_keys.hpp"
#include "corlab/fem/config/config_limits.hpp"

namespace corlab::fem {

namespace {

bool is_material_key(std::string_view key) {
  constexpr std::string_view suffix = ".material";
  return key.size() >= suffix.size() && key.substr(key.size() - suffix.size()) == suffix;
}

// The text of one TOML value for `key`: scalars as they are, arrays only for list keys.
std::string toml_value_text(const std::string& key, const toml::node& node) {
  const ConfigKeyInfo* info = find_config_key(key);
  if (const auto* s = node.as_string()) return s->get();
  if (const auto* i = node.as_integer()) return fmt::format("{}", i->get());
  if (const auto* f = node.as_floating_point()) return fmt::format("{}", f->get());
  if (const auto* arr = node.as_array()) {
    if (info != nullptr && info->kind != KeyKind::number_list) {
      throw_invalid(key, "an array", "a single value, not a list");
    }
    std::vector<std::string> items;
    for (const auto& item : *arr) {
      if (item.is_integer() || item.is_floating_point()) {
        items.push_back(fmt::format("{}", *item.value<double>()));
      } else {
        throw_invalid(key, "non-number array item", "a list of numbers");
      }
    }
    return fmt::format("{}", fmt::join(items, ","));
  }
  throw_invalid(key, "unsupported value", "a number, a string or a list of numbers");
}

}  // namespace

std::string_view to_string(SubstrateShape shape) {
  switch (shape) {
    case SubstrateShape::kRigid:
      return "rigid";
    case SubstrateShape::kSphere:
      return "sphere";
    case SubstrateShape::kFlat:
      break;
  }
  return "flat";
}

std::string_view to_string(SubstrateBoundary boundary) {
  switch (boundary) {
    case SubstrateBoundary::kAbsorbing:
      return "absorbing";
    case SubstrateBoundary::kViscousSpring:
      return "viscous_spring";
    case SubstrateBoundary::kFixed:
      break;
  }
  return "fixed";
}

std::string_view to_string(FrictionEnforcement enforcement) {
  return enforcement == FrictionEnforcement::kPenalty ? "penalty" : "kinematic";
}

std::string_view to_string(SolverModel model) {
  return model == SolverModel::kThreeD ? "3d" : "axisymmetric";
}

double PlaneAngle::in_degrees() const {
  return std::stod(fmt::format("{:.15g}", radians / units::kDegree));
}

double normal_velocity(const ImpactConfig& config) {
  return config.impact.velocity * std::cos(config.impact.angle.radians);
}

double contact_start_time(const ImpactConfig& config) {
  return config.impact.gap / normal_velocity(config);
}

double contact_effective_modulus(const ImpactConfig& config) {
  const Material& s = config.sphere.material;
  if (rigid_target(config)) return s.youngs_modulus / (1.0 - s.poisson_ratio * s.poisson_ratio);
  return effective_modulus(s, config.substrate.material);
}

std::optional<double> contact_yield_stress(const ImpactConfig& config) {
  const std::optional<double>& first = config.sphere.material.yield_stress;
  const std::optional<double>& second = config.substrate.material.yield_stress;
  switch (config.substrate.shape) {
    case SubstrateShape::kRigid:
      return first;
    case SubstrateShape::kSphere:
      if (first && second) return std::min(*first, *second);
      return first ? first : second;
    case SubstrateShape::kFlat:
      break;
  }
  return second;
}

void validate(const ImpactConfig& c) {
  validate_key_ranges(c);
  validate_limits(c);
}

void apply_setting(ImpactConfig& config, std::string_view key, std::string_view value) {
  set_config_key(config, key, value);
}

void apply_settings(ImpactConfig& config,
                    const std::vector<std::string>& key_value_items,
                    std::string_view origin) {
  std::vector<std::pair<std::string, std::string>> items;
  std::set<std::string> seen;
  for (const auto& item : key_value_items) {
    const auto eq = item.find('=');
    if (eq == std::string::npos) throw_invalid(origin, item, "key=value");
    std::string key(trim(std::string_view(item).substr(0, eq)));
    if (!seen.insert(key).second) {
      throw_invalid(fmt::format("{} {}", origin, key), item.substr(eq + 1),
                    "given once (the key is set twice)");
    }
    items.emplace_back(std::move(key), item.substr(eq + 1));
  }
  std::stable_partition(items.begin(), items.end(),
                        [](const auto& kv) { return is_material_key(kv.first); });
  for (const auto& [key, value] : items) apply_setting(config, key, value);
}

ImpactConfig load_impact_config(const std::filesystem::path& file) {
  // Bounded and checked (a special file, a huge or non-UTF-8 file is refused); an empty file is
  // an error, not the default case.
  const std::string text = read_text_file(file, "config file", {.max_bytes = kMaxConfigFileBytes});
  toml::table root;
  try {
    root = toml::parse(text, file.string());
  } catch (const toml::parse_error& err) {
    throw InputError(one_line(fmt::format("invalid config file '{}': {} (line {})", file.string(),
                                          err.description(), err.source().begin.line)));
  }
  if (root.empty()) {
    throw_invalid("config file", file.string(),
                  "a TOML file that sets at least one key (it sets none)");
  }
  std::vector<std::string> items;
  for (const auto& [group_key, group] : root) {
    const std::string group_name(group_key.str());
    const auto* table = group.as_table();
    if (table == nullptr) {
      throw_invalid("config key", group_name,
                    "a [table] (sphere, substrate, impact, mesh, solver, output)");
    }
    for (const auto& [key, node] : *table) {
      const std::string full = group_name + "." + std::string(key.str());
      if (node.is_table()) throw_invalid(full, "a table", "a value (no deeper tables)");
      items.push_back(full + "=" + toml_value_text(full, node));
    }
  }
  ImpactConfig config;
  apply_settings(config, items, fmt::format("config file '{}'", file.string()));
  return config;
}

}  // namespace corlab::fem
