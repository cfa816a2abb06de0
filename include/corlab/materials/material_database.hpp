// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file material_database.hpp
/// The built-in material database (data/materials.toml) and the textual material spec used by
/// the CLI, configs and Python: a database name, an inline list, or a name with overrides:
///   "alumina_ma2023"
///   "E=370e9,nu=0.22,rho=3958,sy=380e6"        (keys: E, nu, rho, sy|sigma_y, H)
///   "steel_ma2023,sy=700e6"                     (database entry with one value replaced)

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "corlab/materials/material.hpp"

namespace corlab {

class MaterialDatabase {
 public:
  /// Reads a TOML file of [name] tables; throws InputError on a malformed file or entry.
  static MaterialDatabase load(const std::filesystem::path& file);
  /// The shipped database: materials.toml of data_directory().
  static const MaterialDatabase& builtin();

  /// Throws InputError "invalid <field> = '<name>': must be one of ..." for an unknown name.
  const Material& get(std::string_view name, std::string_view field = "material") const;
  bool contains(std::string_view name) const;
  std::vector<std::string> names() const;
  /// The entry's `category` (data/materials.toml: "paper case", "glass", "steel", ...; the
  /// material library's grouping); empty for an entry without one. Throws as get() does.
  const std::string& category(std::string_view name, std::string_view field = "material") const;

 private:
  std::map<std::string, Material, std::less<>> materials_;
  std::map<std::string, std::string, std::less<>> categories_;
};

/// Parses a material spec (see file comment) and validates the result.
/// @param field  name used in error messages, e.g. "sphere" or "substrate"
Material parse_material_spec(std::string_view spec,
                             std::string_view field,
                             const MaterialDatabase& database = MaterialDatabase::builtin());

/// <prefix>/share/corlab when the code calling this (the `corlab` program, libcorlab,
/// libcorlab_dem or the Python module) runs from where `cmake --install` or the .deb put it under
/// <prefix> and that directory holds materials.toml; else empty (a build tree). Found from the
/// file the code was loaded from (dladdr), so it holds for any prefix and from any directory.
std::filesystem::path installed_data_directory();

/// Directory of shipped data files (materials.toml, fe_restitution/), the one rule for every
/// caller: $CORLAB_DATA_DIR if set and not empty; else `installed` if it holds materials.toml
/// (by default the installed copy next to the code, installed_data_directory()); else the source
/// tree's data/.
std::filesystem::path data_directory(
    const std::filesystem::path& installed = installed_data_directory());

/// Directory of the shipped study specs (<preset>/<study>.toml): studies/ of the installed
/// copy when there is one (installed_data_directory()), else the source tree's studies/.
std::filesystem::path studies_directory();

}  // namespace corlab
