// `corlab materials`: list the built-in material database.
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/core.h>

#include "command.hpp"
#include "corlab/materials/material_database.hpp"

namespace corlab::cli {
namespace {

const CommandRegistration kRegistration{Command{
    "materials", "List the built-in materials (data/materials.toml) with their sources",
    [](CLI::App& /*sub*/) -> std::function<int()> {
      return [] {
        const auto& db = MaterialDatabase::builtin();
        fmt::print("{:<24} {:<16} {:>10} {:>6} {:>10} {:>10}  source\n", "name", "category",
                   "E [Pa]", "nu", "rho", "sigma_y");
        for (const auto& name : db.names()) {
          const Material& m = db.get(name);
          fmt::print("{:<24} {:<16} {:>10.4g} {:>6.3g} {:>10.6g} {:>10}  {}\n", name,
                     db.category(name).empty() ? "-" : db.category(name), m.youngs_modulus,
                     m.poisson_ratio, m.density,
                     m.yield_stress ? fmt::format("{:.4g}", *m.yield_stress) : std::string("-"),
                     m.source);
        }
        return 0;
      };
    },
    90}};

}  // namespace
}  // namespace corlab::cli
