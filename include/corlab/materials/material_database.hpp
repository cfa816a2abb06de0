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

 private:
  std::map<std::string, Material, std::less<>> materials_;
};

/// Parses a material spec (see file comment) and validates the result.
/// @param field  name used in error messages, e.g. "sphere" or "substrate"
Material parse_material_spec(std::string_view spec,
                             std::string_view field,
                             const MaterialDatabase& database = MaterialDatabase::builtin());

/// Directory of shipped data files, the one rule for every caller: $CORLAB_DATA_DIR if set and
/// not empty; else `installed` if it holds materials.toml (an installed copy: the DEM C library
/// passes <prefix>/share/corlab of its build); else the source tree's data/.
std::filesystem::path data_directory(const std::filesystem::path& installed = {});

}  // namespace corlab
