// The material database (material_database.hpp): the built-in entries, database files, the
// material spec parser and every bad-input message of them (the data-directory rule:
// data_directory_test.cpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/materials/material_database.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "corlab/core/error.hpp"
#include "support/input_errors.hpp"
#include "support/scratch_files.hpp"

namespace corlab {
namespace {

using test::expect_input_error;

TEST(MaterialDatabase, BuiltinEntries) {
  const auto& db = MaterialDatabase::builtin();
  for (const char* name : {"steel_ma2023", "alumina_ma2023", "aluminium_ma2023",
                           "steel_jackson2010", "table4_case1_sphere", "table4_case4_substrate"}) {
    EXPECT_TRUE(db.contains(name)) << name;
    EXPECT_FALSE(db.get(name).source.empty()) << name;
  }
  EXPECT_FALSE(db.contains("unobtainium"));
  const Material& al = db.get("aluminium_ma2023");
  EXPECT_EQ(al.name, "aluminium_ma2023");
  EXPECT_DOUBLE_EQ(al.youngs_modulus, 68e9);
  EXPECT_DOUBLE_EQ(al.poisson_ratio, 0.33);
  ASSERT_TRUE(al.yield_stress.has_value());
  EXPECT_DOUBLE_EQ(*al.yield_stress, 380e6);
  EXPECT_FALSE(db.get("alumina_ma2023").yield_stress.has_value());
  EXPECT_DOUBLE_EQ(db.get("alumina_ma2023").density, 3958.226);
  const auto names = db.names();
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
  // the seed paper's 12 materials and the library of engineering materials
  EXPECT_EQ(std::count_if(names.begin(), names.end(),
                          [&](const std::string& n) { return db.category(n) == "paper case"; }),
            12);
}

// The library (data/materials.toml): every entry names its category and its source, and every
// kind of engineering material the explorer offers is there, with a yield stress where it yields.
TEST(MaterialDatabase, LibraryCoversTheCommonEngineeringMaterials) {
  const auto& db = MaterialDatabase::builtin();
  std::map<std::string, int> per_category;
  for (const auto& name : db.names()) {
    const Material& m = db.get(name);
    EXPECT_FALSE(m.source.empty()) << name;
    const std::string& category = db.category(name);
    EXPECT_FALSE(category.empty()) << name;
    ++per_category[category];
    const bool brittle = category == "glass" || category == "ceramic";
    if (category != "paper case") {
      EXPECT_EQ(m.yield_stress.has_value(), !brittle) << name;
    }
  }
  for (const char* category :
       {"glass", "ceramic", "steel", "copper alloy", "aluminium alloy", "titanium", "polymer"}) {
    EXPECT_GE(per_category[category], 2) << category;
  }
  const Material& glass = db.get("glass_soda_lime");
  EXPECT_DOUBLE_EQ(glass.youngs_modulus, 70e9);
  EXPECT_NE(glass.source.find("EN 572-1"), std::string::npos);
}

TEST(MaterialDatabase, UnknownNameMessage) {
  const auto& db = MaterialDatabase::builtin();
  try {
    (void)db.get("unobtainium", "sphere");
    ADD_FAILURE();
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind("invalid sphere = 'unobtainium': must be one of [acetal_pom, ", 0), 0u)
        << msg;
    EXPECT_NE(msg.find(", alumina_ma2023, "), std::string::npos) << msg;
    EXPECT_NE(msg.find("] or E=..,nu=..,rho=..[,sy=..]"), std::string::npos) << msg;
  }
}

class DatabaseFile : public ::testing::Test {
 protected:
  static std::filesystem::path write(const std::string& text) {
    const auto file = test::fresh_dir("database") / "materials.toml";
    test::spit(file, text);
    return file;
  }
};

TEST_F(DatabaseFile, LoadsEntries) {
  const auto file = write(
      "[a]\nE = 1e9\nnu = 0.25\nrho = 1000.0\nsy = 1e7\nH = 1e8\nsource = \"made up\"\n"
      "description = \"ignored\"\n[b]\nE = 2e9\nnu = 0.3\nrho = 2000.0\n");
  const auto db = MaterialDatabase::load(file);
  EXPECT_EQ(db.names(), (std::vector<std::string>{"a", "b"}));
  EXPECT_DOUBLE_EQ(*db.get("a").yield_stress, 1e7);
  EXPECT_DOUBLE_EQ(db.get("a").hardening_modulus, 1e8);
  EXPECT_EQ(db.get("a").source, "made up");
  // integers are numbers too
  const auto db2 = MaterialDatabase::load(write("[c]\nE = 1000000000\nnu = 0.25\nrho = 1000\n"));
  EXPECT_DOUBLE_EQ(db2.get("c").youngs_modulus, 1e9);
}

TEST_F(DatabaseFile, BadFileMessages) {
  const auto bad_syntax = write("[a\nE = 1\n");
  try {
    (void)MaterialDatabase::load(bad_syntax);
    ADD_FAILURE();
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind("invalid material database '" + bad_syntax.string() + "': ", 0), 0u) << msg;
    EXPECT_NE(msg.find("(line 1)"), std::string::npos) << msg;
  }
  expect_input_error([&] { (void)MaterialDatabase::load(write("a = 1\n")); },
                     "invalid material database entry = 'a': must be a [table]");
  expect_input_error([&] { (void)MaterialDatabase::load(write("[a]\nE = 1e9\nfoo = 2.0\n")); },
                     "invalid materials.a.foo = 2: must be a known key");
  expect_input_error([&] { (void)MaterialDatabase::load(write("[a]\nE = \"x\"\n")); },
                     "invalid materials.a.E = 'non-number': must be a number");
  expect_input_error([&] { (void)MaterialDatabase::load(write("[a]\nE = 1e9\nnu = 0.3\n")); },
                     "invalid materials.a.rho = 'missing': must be given (every entry gives E, nu "
                     "and rho)");
}

TEST(MaterialSpec, DatabaseName) {
  const Material m = parse_material_spec("alumina_ma2023", "sphere");
  EXPECT_EQ(m.name, "alumina_ma2023");
  EXPECT_DOUBLE_EQ(m.youngs_modulus, 370e9);
}

TEST(MaterialSpec, InlineValues) {
  const Material m = parse_material_spec(" E=370e9, nu=0.22 ,rho=3958,sy=380e6,H=1e9", "sphere");
  EXPECT_EQ(m.name, "inline");
  EXPECT_DOUBLE_EQ(m.youngs_modulus, 370e9);
  EXPECT_DOUBLE_EQ(m.poisson_ratio, 0.22);
  EXPECT_DOUBLE_EQ(m.density, 3958.0);
  EXPECT_DOUBLE_EQ(*m.yield_stress, 380e6);
  EXPECT_DOUBLE_EQ(m.hardening_modulus, 1e9);
  EXPECT_DOUBLE_EQ(*parse_material_spec("E=1e9,nu=0.2,rho=1,sigma_y=1e6", "x").yield_stress, 1e6);
  EXPECT_FALSE(parse_material_spec("E=1e9,nu=0.2,rho=1", "x").yield_stress.has_value());
}

TEST(MaterialSpec, NameWithOverrides) {
  const Material m = parse_material_spec("steel_ma2023,sy=700e6", "substrate");
  EXPECT_EQ(m.name, "steel_ma2023 (modified)");
  EXPECT_DOUBLE_EQ(*m.yield_stress, 700e6);
  EXPECT_DOUBLE_EQ(m.youngs_modulus, 210e9);
}

TEST(MaterialSpec, BadSpecMessages) {
  expect_input_error([] { (void)parse_material_spec("", "sphere"); },
                     "invalid sphere = '': must be a key=value pair (keys: E, nu, rho, sy, H)");
  expect_input_error([] { (void)parse_material_spec("steel_ma2023,oops", "sphere"); },
                     "invalid sphere = 'oops': must be a key=value pair (keys: E, nu, rho, sy, H)");
  expect_input_error([] { (void)parse_material_spec("E=1e9,,rho=1", "sphere"); },
                     "invalid sphere = '': must be a key=value pair (keys: E, nu, rho, sy, H)");
  expect_input_error([] { (void)parse_material_spec("E=abc,nu=0.3,rho=1", "sphere"); },
                     "invalid sphere.E = 'abc': must be a finite number");
  expect_input_error([] { (void)parse_material_spec("E=1e9x,nu=0.3,rho=1", "sphere"); },
                     "invalid sphere.E = '1e9x': must be a finite number");
  expect_input_error([] { (void)parse_material_spec("E=inf,nu=0.3,rho=1", "sphere"); },
                     "invalid sphere.E = 'inf': must be a finite number");
  expect_input_error([] { (void)parse_material_spec("E=,nu=0.3,rho=1", "sphere"); },
                     "invalid sphere.E = '': must be a finite number");
  expect_input_error([] { (void)parse_material_spec("E=1e9,nu=0.3,rho=1,G=1", "sphere"); },
                     "invalid sphere key = 'G': must be one of E, nu, rho, sy, sigma_y, H");
  // issue 31 item 7: a missing property was a silent 0 (nu = 0 ran; rho read "= 0: must be > 0")
  expect_input_error([] { (void)parse_material_spec("E=1e9,nu=0.3", "substrate"); },
                     "invalid substrate = 'E=1e9,nu=0.3': must be a database name or an inline "
                     "material with E, nu and rho (it lacks rho; e.g. E=200e9,nu=0.3,rho=7850 or "
                     "steel_ma2023,sy=700e6)");
  expect_input_error([] { (void)parse_material_spec("E=200e9,rho=7800", "sphere"); },
                     "invalid sphere = 'E=200e9,rho=7800': must be a database name or an inline "
                     "material with E, nu and rho (it lacks nu; e.g. E=200e9,nu=0.3,rho=7850 or "
                     "steel_ma2023,sy=700e6)");
  EXPECT_EQ(parse_material_spec("steel_ma2023,nu=0.29", "sphere").poisson_ratio, 0.29);
  // hardening must stay below E (on every body, elastic too)
  expect_input_error([] { (void)parse_material_spec("E=1e9,nu=0.3,rho=1,H=2e9", "sphere"); },
                     "invalid sphere.H = 2000000000: must be < sphere.E = 1e+09 [Pa]");
  expect_input_error([] { (void)parse_material_spec("E=1e9,nu=0.7,rho=1", "sphere"); },
                     "invalid sphere.nu = 0.7: must be in (-1, 0.5)");
  expect_input_error([] { (void)parse_material_spec("steel_ma2023,sy=1e12", "substrate"); },
                     "invalid substrate.sigma_y = 1000000000000: must be in (0, 0.1 E) [Pa] (a "
                     "yield strain above 10 % is no metal)");
  EXPECT_THROW((void)parse_material_spec("nosuch", "sphere"), InputError);
}

}  // namespace
}  // namespace corlab

namespace corlab {
namespace {

// Found by fuzzing (tests/fuzz): a line break inside a material spec was echoed raw, so the
// error spanned two lines. Control characters are now shown escaped.
TEST(MaterialSpec, LineBreakInSpecGivesOneLineError) {
  try {
    (void)parse_material_spec("al\nina_ma2023,sy=1e9,rho=3925", "sphere");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& err) {
    EXPECT_EQ(
        std::string(err.what()).rfind("invalid sphere = 'al\\nina_ma2023': must be one of", 0), 0u)
        << err.what();
  }
}

}  // namespace
}  // namespace corlab
