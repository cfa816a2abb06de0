// lammps_compiled.in (issue 41): lammps.in with the Python hook replaced by fix corlab/ev, whose
// one line carries e at the hook's table speeds for every e(v) pair and every wall and type.
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "corlab/dem/dem_export.hpp"
#include "corlab/dem/uniform_table.hpp"

namespace corlab::dem {
namespace {

// Two types, a floor and a cylinder of another material, every pair on one e(v) table.
ExportSpec ev_spec() {
  ExportSpec spec;
  spec.types.push_back(
      {parse_labelled_material("a=E=5e6,nu=0.3,rho=1000", "type").material, 0.004, "a"});
  spec.types.push_back(
      {parse_labelled_material("b=E=1e7,nu=0.3,rho=2000", "type").material, 0.005, "b"});
  spec.wall = parse_labelled_material("w=E=4e6,nu=0.3,rho=2000", "wall").material;
  spec.extra_walls.push_back(parse_labelled_material("c=E=6e6,nu=0.3,rho=2000", "wall"));
  Wall cylinder = parse_wall_shape("cylinder:z,0,0,0.05,0,0.3");
  cylinder.material = 1;
  spec.walls = {parse_wall_shape("floor"), cylinder};
  spec.table = tabulated_curve({0.3, 3.0}, {0.9, 0.6});
  spec.v_min = 0.3;
  spec.v_max = 3.0;
  return spec;
}

// The words of the line starting with `start`.
std::vector<std::string> words_of(const std::string& text, const std::string& start) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(start, 0) != 0) continue;
    std::istringstream w(line);
    std::vector<std::string> out;
    for (std::string word; w >> word;) out.push_back(word);
    return out;
  }
  return {};
}

TEST(DemLammpsCompiled, OneFixLineWithEveryTableInPlaceOfThePythonHook) {
  const ExportSpec spec = ev_spec();
  const auto pairs = calibrate_export(spec);
  const std::string compiled = write_lammps_compiled(spec, pairs);
  const std::string hook = write_lammps(spec, pairs);
  EXPECT_EQ(compiled.find("python corlab_ev_force"), std::string::npos);
  EXPECT_EQ(compiled.find("python/invoke 1"), std::string::npos);
  EXPECT_NE(hook.find("fix corlab_ev all python/invoke"), std::string::npos);
  EXPECT_NE(compiled.find("corlab-lammps -in in.file"), std::string::npos);
  // The same pair_coeff, walls and time step as lammps.in: the same law.
  for (const std::string start : {"pair_coeff 1 2 ", "fix corlab_wall2_t1 ", "timestep "}) {
    EXPECT_EQ(words_of(compiled, start), words_of(hook, start)) << start;
  }
  const auto w = words_of(compiled, "fix corlab_ev all corlab/ev ");
  ASSERT_GE(w.size(), 8U);
  EXPECT_EQ(w[4], "speeds");
  EXPECT_EQ(std::stod(w[5]), 0.3);
  EXPECT_EQ(std::stod(w[6]), 3.0);
  const int n = std::stoi(w[7]);
  // Walk the line: 3 particle pairs, 2 walls with 2 types each, e at the n speeds of each.
  int pair_tables = 0;
  int walls = 0;
  int wall_tables = 0;
  for (std::size_t i = 8; i < w.size();) {
    if (w[i] == "wall") {
      ++walls;
      i += 8;
      continue;
    }
    ASSERT_TRUE(w[i] == "pair" || w[i] == "type") << w[i];
    const bool pair = w[i] == "pair";
    const std::size_t table = i + (pair ? 4 : 3);
    ASSERT_LE(table + static_cast<std::size_t>(n), w.size());
    EXPECT_NEAR(std::stod(w[table]), 0.9, 1e-9);
    EXPECT_NEAR(std::stod(w[table + static_cast<std::size_t>(n) - 1]), 0.6, 1e-9);
    (pair ? pair_tables : wall_tables) += 1;
    i = table + static_cast<std::size_t>(n);
  }
  EXPECT_EQ(pair_tables, 3);
  EXPECT_EQ(walls, 2);
  EXPECT_EQ(wall_tables, 4);
  EXPECT_NE(
      compiled.find(" wall cylinder 2 0 0 0.050000000000000003 0 0.29999999999999999 type 1 "),
      std::string::npos);
}

TEST(DemLammpsCompiled, ConstantPairsLeaveNoFix) {
  ExportSpec spec = ev_spec();
  spec.table.reset();
  spec.restitution = 0.5;
  const auto pairs = calibrate_export(spec);
  const std::string compiled = write_lammps_compiled(spec, pairs);
  EXPECT_EQ(compiled.find("fix corlab_ev"), std::string::npos);
  EXPECT_EQ(words_of(compiled, "timestep "), words_of(write_lammps(spec, pairs), "timestep "));
}

}  // namespace
}  // namespace corlab::dem
