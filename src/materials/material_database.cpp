// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/materials/material_database.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <system_error>
#include <vector>

#include "corlab/core/error.hpp"
#include "corlab/core/number.hpp"
#include "corlab/core/text.hpp"
#include "corlab/core/text_file.hpp"

namespace corlab {

namespace {

// Sets one field of `m` from key=value; returns false for an unknown key.
bool set_field(Material& m, std::string_view key, double value) {
  if (key == "E") {
    m.youngs_modulus = value;
  } else if (key == "nu") {
    m.poisson_ratio = value;
  } else if (key == "rho") {
    m.density = value;
  } else if (key == "sy" || key == "sigma_y") {
    m.yield_stress = value;
  } else if (key == "H") {
    m.hardening_modulus = value;
  } else {
    return false;
  }
  return true;
}

}  // namespace

MaterialDatabase MaterialDatabase::load(const std::filesystem::path& file) {
  toml::table table;
  try {
    table =
        toml::parse(read_text_file(file, "material database", {.max_bytes = kMaxConfigFileBytes}),
                    file.string());
  } catch (const toml::parse_error& err) {
    throw InputError(fmt::format("invalid material database '{}': {} (line {})", file.string(),
                                 err.description(), err.source().begin.line));
  }
  MaterialDatabase db;
  for (const auto& [key, node] : table) {
    const auto* entry = node.as_table();
    const std::string name(key.str());
    if (entry == nullptr) throw_invalid("material database entry", name, "a [table]");
    Material m;
    m.name = name;
    for (const auto& [field_key, value] : *entry) {
      const std::string_view k = field_key.str();
      if (k == "source") {
        m.source = value.value_or(std::string());
      } else if (k == "category") {
        db.categories_[name] = value.value_or(std::string());
      } else if (k == "description") {
        continue;
      } else if (auto number = value.value<double>()) {
        if (!set_field(m, k, *number)) {
          throw_invalid(fmt::format("materials.{}.{}", name, k), *number, "a known key");
        }
      } else {
        throw_invalid(fmt::format("materials.{}.{}", name, k), "non-number", "a number");
      }
    }
    for (const std::string_view required : {"E", "nu", "rho"}) {
      if (!entry->contains(required)) {
        throw_invalid(fmt::format("materials.{}.{}", name, required), "missing",
                      "given (every entry gives E, nu and rho)");
      }
    }
    validate(m, "materials." + name);
    db.materials_.emplace(name, std::move(m));
  }
  return db;
}

const MaterialDatabase& MaterialDatabase::builtin() {
  static const MaterialDatabase db = load(data_directory() / "materials.toml");
  return db;
}

bool MaterialDatabase::contains(std::string_view name) const {
  return materials_.find(name) != materials_.end();
}

const Material& MaterialDatabase::get(std::string_view name, std::string_view field) const {
  const auto it = materials_.find(name);
  if (it == materials_.end()) {
    throw_invalid(
        field, name,
        fmt::format("one of [{}] or E=..,nu=..,rho=..[,sy=..]", fmt::join(names(), ", ")));
  }
  return it->second;
}

const std::string& MaterialDatabase::category(std::string_view name, std::string_view field) const {
  static const std::string none;
  (void)get(name, field);  // the unknown-name message
  const auto it = categories_.find(name);
  return it == categories_.end() ? none : it->second;
}

std::vector<std::string> MaterialDatabase::names() const {
  std::vector<std::string> out;
  out.reserve(materials_.size());
  for (const auto& [name, m] : materials_) out.push_back(name);
  return out;
}

namespace {

/// An inline material (no database name to start from) gives E, nu and rho: a missing one would
/// otherwise be a silent 0 (nu = 0 ran; E = 0 read "must be > 0").
void require_complete(const std::set<std::string_view>& given,
                      std::string_view spec,
                      const std::string& field) {
  std::vector<std::string_view> missing;
  for (const std::string_view key : {"E", "nu", "rho"}) {
    if (!given.contains(key)) missing.push_back(key);
  }
  if (missing.empty()) return;
  throw_invalid(field, spec,
                fmt::format("a database name or an inline material with E, nu and rho (it lacks "
                            "{}; e.g. E=200e9,nu=0.3,rho=7850 or steel_ma2023,sy=700e6)",
                            fmt::join(missing, ", ")));
}

}  // namespace

Material parse_material_spec(std::string_view spec,
                             std::string_view field,
                             const MaterialDatabase& database) {
  const std::string f(field);
  const std::string_view spec_text = spec;
  Material m;
  m.name = "inline";
  bool first = true;
  bool any_value = false;
  std::set<std::string_view> given;  // canonical keys already set in this spec
  while (true) {
    const auto comma = spec.find(',');
    const std::string_view token = trim(spec.substr(0, comma));
    const auto eq = token.find('=');
    if (eq == std::string_view::npos) {
      if (!first || token.empty()) {
        throw_invalid(f, token, "a key=value pair (keys: E, nu, rho, sy, H)");
      }
      m = database.get(token, f);
    } else {
      const std::string_view key = trim(token.substr(0, eq));
      const std::string_view canonical = key == "sigma_y" ? std::string_view("sy") : key;
      if (!given.insert(canonical).second) {
        throw_invalid(f + "." + std::string(key), trim(token.substr(eq + 1)),
                      "given once (the key is set twice in the material spec)");
      }
      const double value = parse_finite(f + "." + std::string(key), token.substr(eq + 1));
      if (!set_field(m, key, value)) {
        throw_invalid(f + " key", key, "one of E, nu, rho, sy, sigma_y, H");
      }
      any_value = true;
    }
    first = false;
    if (comma == std::string_view::npos) break;
    spec.remove_prefix(comma + 1);
  }
  if (m.name == "inline") require_complete(given, spec_text, f);
  if (any_value && m.name != "inline") m.name += " (modified)";
  validate(m, f);
  return m;
}

}  // namespace corlab
