// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The table of ImpactConfig keys behind config_keys.hpp: each key's public description and where
// its value lives. Written in config_key_table.cpp; read by config_keys.cpp (parsing, range checks,
// echo). Private to src/fem/config.

#include <filesystem>
#include <optional>
#include <string_view>
#include <variant>
#include <vector>

#include "corlab/fem/config/config_keys.hpp"
#include "corlab/fem/config/impact_config.hpp"

namespace corlab::fem::config_table {

// Where a key's value lives in ImpactConfig; the alternative fixes how its text is read.
using Accessor = std::variant<double* (*)(ImpactConfig&),
                              long long* (*)(ImpactConfig&),
                              int* (*)(ImpactConfig&),
                              std::optional<double>* (*)(ImpactConfig&),
                              std::vector<double>* (*)(ImpactConfig&),
                              Material* (*)(ImpactConfig&),
                              std::filesystem::path* (*)(ImpactConfig&),
                              SubstrateShape* (*)(ImpactConfig&),
                              SolverModel* (*)(ImpactConfig&),
                              PlaneAngle* (*)(ImpactConfig&),
                              SubstrateBoundary* (*)(ImpactConfig&),
                              FrictionEnforcement* (*)(ImpactConfig&)>;

inline constexpr KeyKind kKindOf[] = {
    KeyKind::number,      KeyKind::integer,  KeyKind::integer, KeyKind::yield_stress,
    KeyKind::number_list, KeyKind::material, KeyKind::path,    KeyKind::choice,
    KeyKind::choice,      KeyKind::number,   KeyKind::choice,  KeyKind::choice};

struct KeyEntry {
  ConfigKeyInfo info;
  Accessor access;
};

/// Every key, in documentation order.
const std::vector<KeyEntry>& key_table();

/// The key's entry, or nullptr.
const KeyEntry* find_entry(std::string_view key);

}  // namespace corlab::fem::config_table
