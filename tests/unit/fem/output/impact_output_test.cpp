// History CSV and summary JSON writers (impact_output.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/output/impact_output.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "corlab/fem/config/config_keys.hpp"
#include "support/scratch_files.hpp"

namespace corlab::fem {
namespace {

TEST(ImpactOutput, SummaryHasTheDocumentedKeys) {
  ImpactResult r;
  r.e = 0.53;
  r.F_max = 1e5;
  const auto j = summary_to_json(r, ImpactConfig{});
  for (const char* key :
       {"e", "e_energy", "F_max", "delta_max", "t_contact", "energy_initial",
        "energy_dissipated_plastic", "energy_hourglass", "energy_balance_error", "elements",
        "steps", "wall_s", "element_steps_per_s", "hysteresis_area", "energy_sphere_loss"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_DOUBLE_EQ(j["e"].get<double>(), 0.53);
  EXPECT_DOUBLE_EQ(j["config"]["impact"]["velocity"].get<double>(), 5.0);
  EXPECT_DOUBLE_EQ(j["config"]["substrate"]["material"]["sigma_y"].get<double>(), 500e6);
}

TEST(ImpactOutput, ConfigEchoHasEveryKeyOfTheTable) {
  ImpactConfig c;
  c.mesh.file = "disc.msh";
  c.output.field_times = {1e-6, 2e-6};
  const auto config = summary_to_json(ImpactResult{}, c)["config"];
  for (const ConfigKeyInfo& key : config_keys()) {
    const std::vector<std::string> path = config_echo_path(key);
    const nlohmann::json* node = &config;
    for (const std::string& name : path) {
      ASSERT_TRUE(node->contains(name)) << key.key << " (at " << name << ")";
      node = &(*node)[name];
    }
    EXPECT_EQ(*node, config_value_json(c, key.key)) << key.key;
  }
  EXPECT_EQ(config["solver"]["max_steps"].get<long long>(), c.solver.max_steps);
  EXPECT_EQ(config["sphere"]["material"]["E"].get<double>(), c.sphere.material.youngs_modulus);
  EXPECT_EQ(config["mesh"]["file"].get<std::string>(), "disc.msh");
  EXPECT_EQ(config["output"]["times"], nlohmann::json({1e-6, 2e-6}));
  EXPECT_EQ(config["output"]["history_every"].get<int>(), c.output.history_every);
  c.substrate.material.yield_stress.reset();
  EXPECT_TRUE(config_to_json(c)["substrate"]["material"]["sigma_y"].is_null());
}

TEST(ImpactOutput, HistoryCsvHasUnitsAndRows) {
  ImpactHistory h;
  for (int i = 0; i < 3; ++i) {
    h.time.push_back(i * 1e-6);
    for (auto* v : {&h.contact_force, &h.indentation, &h.sphere_velocity, &h.kinetic_energy,
                    &h.strain_energy, &h.plastic_dissipation, &h.hourglass_energy,
                    &h.viscous_dissipation, &h.contact_energy, &h.energy_balance_error}) {
      v->push_back(i);
    }
  }
  const auto file = test::fresh_dir("history") / "history.csv";
  write_history_csv(h, file);
  std::ifstream in(file);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header.rfind("time_s,contact_force_N,indentation_m", 0), 0u) << header;
  int rows = 0;
  for (std::string line; std::getline(in, line);) ++rows;
  EXPECT_EQ(rows, 3);
  std::filesystem::remove_all(file.parent_path());
}

}  // namespace
}  // namespace corlab::fem
