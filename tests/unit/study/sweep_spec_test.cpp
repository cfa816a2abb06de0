// Sweep spec: parsing, expansion (counts, order, ids) and every bad-spec message.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/study/sweep_spec.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <set>
#include <string>

#include "corlab/core/error.hpp"
#include "support/input_errors.hpp"

namespace corlab::study {
namespace {

const std::string kExample = R"(
[study]
name = "table2"
description = "two pairs"
[base]
"mesh.h_min" = 0.5e-3
[grid]
"sphere.rho" = [3925.0, 7850.0]
"impact.velocity" = [1.0, 5.0, 20.0]
[[cases]]
"sphere.material" = "alumina_ma2023"
"substrate.material" = "aluminium_ma2023"
[[cases]]
"sphere.material" = "steel_ma2023"
"substrate.material" = "steel_ma2023"
)";

std::string message_of(const std::string& toml) {
  try {
    parse_sweep_spec(toml, "t.toml");
  } catch (const InputError& err) {
    return err.what();
  }
  return "(no error)";
}

TEST(SweepSpec, ParsesAndExpandsCasesTimesGrid) {
  const SweepSpec spec = parse_sweep_spec(kExample, "table2.toml");
  EXPECT_EQ(spec.name, "table2");
  EXPECT_EQ(spec.description, "two pairs");
  ASSERT_EQ(spec.base.size(), 1u);
  EXPECT_EQ(spec.base[0], (Setting{"mesh.h_min", "0.0005"}));
  ASSERT_EQ(spec.grid.size(), 2u);
  // Document order, not the alphabetical order of the TOML table.
  EXPECT_EQ(spec.grid[0].first, "sphere.rho");
  EXPECT_EQ(spec.grid[1].first, "impact.velocity");
  EXPECT_EQ(spec.grid[1].second, (std::vector<std::string>{"1", "5", "20"}));
  EXPECT_EQ(spec.cases.size(), 2u);
  EXPECT_EQ(spec.run_count(), 12u);
  EXPECT_EQ(spec.swept_keys(), (std::vector<std::string>{"sphere.material", "substrate.material",
                                                         "sphere.rho", "impact.velocity"}));

  const auto runs = spec.expand();
  ASSERT_EQ(runs.size(), 12u);
  // Case-major, last grid key fastest.
  EXPECT_EQ(runs[0].config.impact.velocity, 1.0);
  EXPECT_EQ(runs[1].config.impact.velocity, 5.0);
  EXPECT_EQ(runs[3].config.sphere.material.density, 7850.0);
  EXPECT_EQ(runs[0].config.mesh.h_min, 0.5e-3);
  // The grid density overrides the density of the case's material (materials apply first).
  EXPECT_EQ(runs[0].config.sphere.material.youngs_modulus, 370e9);
  EXPECT_EQ(runs[0].config.sphere.material.density, 3925.0);
  EXPECT_EQ(runs[6].config.sphere.material.youngs_modulus, 210e9);
  EXPECT_EQ(runs[6].config.substrate.material.yield_stress.value(), 500e6);
  EXPECT_EQ(runs[0].settings.front().first.find(".material") != std::string::npos, true);

  std::set<std::string> ids;
  for (const auto& run : runs) {
    EXPECT_EQ(run.id.size(), 11u);
    EXPECT_EQ(run.id.front(), 'c');
    ids.insert(run.id);
  }
  EXPECT_EQ(ids.size(), runs.size()) << "ids must be unique";
}

TEST(SweepSpec, IdsAreStableAcrossParsesAndKeyOrder) {
  const auto a = parse_sweep_spec(kExample, "a.toml").expand();
  const auto b = parse_sweep_spec(kExample, "b.toml").expand();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].id, b[i].id);
  // Same settings written differently (dotted keys, sub-tables, other order, 5e-4 for 0.5e-3)
  // -> same ids: numbers are canonicalised to their shortest text before hashing.
  const std::string reordered = R"(
[study]
name = "table2"
[grid]
sphere.rho = [3925.0, 7850.0]
impact.velocity = [1.0, 5.0, 20.0]
[base.mesh]
h_min = 5e-4
[[cases]]
substrate.material = "aluminium_ma2023"
sphere.material = "alumina_ma2023"
[[cases]]
substrate.material = "steel_ma2023"
sphere.material = "steel_ma2023"
)";
  const auto c = parse_sweep_spec(reordered, "c.toml").expand();
  std::set<std::string> ids_a, ids_c;
  for (const auto& r : a) ids_a.insert(r.id);
  for (const auto& r : c) ids_c.insert(r.id);
  EXPECT_EQ(ids_a, ids_c);
  // Adding a velocity keeps the ids of the existing runs (resume after extending a study).
  std::string extended = kExample;
  extended.replace(extended.find("20.0]"), 5, "20.0, 40.0]");
  const auto d = parse_sweep_spec(extended, "d.toml").expand();
  EXPECT_EQ(d.size(), 16u);
  std::set<std::string> ids_d;
  for (const auto& r : d) ids_d.insert(r.id);
  EXPECT_TRUE(std::includes(ids_d.begin(), ids_d.end(), ids_a.begin(), ids_a.end()));
}

TEST(SweepSpec, GridOnlyAndCasesOnly) {
  const auto grid_only = parse_sweep_spec(R"([study]
name = "g"
[grid]
"impact.velocity" = [1, 2])",
                                          "g.toml");
  EXPECT_EQ(grid_only.expand().size(), 2u);
  EXPECT_EQ(grid_only.expand()[1].config.impact.velocity, 2.0);
  const auto cases_only = parse_sweep_spec(R"([study]
name = "c"
[[cases]]
"impact.velocity" = 3
[[cases]]
"impact.velocity" = 4
"sphere.material" = "E=200e9,nu=0.3,rho=8000")",
                                           "c.toml");
  const auto runs = cases_only.expand();
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[1].config.sphere.material.density, 8000.0);
  EXPECT_EQ(cases_only.swept_keys(),
            (std::vector<std::string>{"impact.velocity", "sphere.material"}));
  const auto single = parse_sweep_spec("[study]\nname = \"one\"\n", "one.toml");
  EXPECT_EQ(single.expand().size(), 1u);
}

TEST(SweepSpec, ToTomlRoundTrips) {
  SweepSpec spec = parse_sweep_spec(kExample, "x.toml");
  spec.toml_text.clear();
  const SweepSpec again = parse_sweep_spec(spec.to_toml(), "regenerated");
  const auto a = spec.expand();
  const auto b = again.expand();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].id, b[i].id);
}

TEST(SweepSpec, LoadsTheTestDataFiles) {
  const auto example = load_sweep_spec(CORLAB_SOURCE_DIR "/tests/data/sweeps/example.toml");
  EXPECT_EQ(example.expand().size(), 12u);
  const auto tiny = load_sweep_spec(CORLAB_SOURCE_DIR "/tests/data/sweeps/tiny.toml");
  EXPECT_EQ(tiny.expand().size(), 6u);
}

struct BadSpec {
  const char* what;
  std::string toml;
  std::string message;  // the whole expected line
};

TEST(SweepSpec, EveryBadSpecGivesOneClearLine) {
  const std::string head = "[study]\nname = \"t\"\n";
  const std::vector<BadSpec> cases{
      {"negative velocity", head + "[grid]\n\"impact.velocity\" = [1.0, 5.0, -1]\n",
       "invalid spec t.toml grid.\"impact.velocity\"[2] = -1: must be in (0, 1000] [m/s] (no "
       "equation of state for hypervelocity impact)"},
      {"empty grid", head + "[grid]\n\"impact.velocity\" = []\n",
       "invalid spec t.toml grid.\"impact.velocity\" = []: must be a non-empty array of values"},
      {"grid scalar", head + "[grid]\n\"impact.velocity\" = 5.0\n",
       "invalid spec t.toml grid.\"impact.velocity\": must be a non-empty array of values"},
      {"duplicate grid value", head + "[grid]\n\"impact.velocity\" = [1.0, 1.0]\n",
       "invalid spec t.toml grid.\"impact.velocity\"[1] = 1: must differ from "
       "grid.\"impact.velocity\"[0] (duplicate grid value)"},
      {"unknown table", head + "[gird]\n\"impact.velocity\" = [1.0]\n",
       "invalid spec t.toml: unknown table or key 'gird' (expected [study], [base], [grid], "
       "[[cases]])"},
      {"unknown study key", head + "author = \"me\"\n",
       "invalid spec t.toml study.author: unknown key (expected name, description, max_runs)"},
      {"missing study", "[grid]\n\"impact.velocity\" = [1.0]\n",
       "invalid spec t.toml: missing [study] table with name = \"...\""},
      {"missing name", "[study]\ndescription = \"x\"\n",
       "invalid spec t.toml study.name: missing (required, [A-Za-z0-9_-]+)"},
      {"bad name", "[study]\nname = \"table 2\"\n",
       "invalid spec t.toml study.name = 'table 2': must match [A-Za-z0-9_-]+"},
      {"cases not an array of tables", "cases = 3\n" + head,
       "invalid spec t.toml: 'cases' must be a [[cases]] array of tables"},
      {"bad number text", head + "[base]\n\"mesh.h_min\" = \"abc\"\n",
       "invalid spec t.toml base.\"mesh.h_min\" = 'abc': must be a finite number"},
      {"array in base", head + "[base]\n\"mesh.h_min\" = [1, 2]\n",
       "invalid spec t.toml base.\"mesh.h_min\": must be a number, a string or a boolean"},
      {"unknown material", head + "[[cases]]\n\"sphere.material\" = \"unobtainium\"\n", ""},
      {"base range", head + "[base]\n\"sphere.radius\" = 0\n",
       "invalid spec t.toml base.\"sphere.radius\" = 0: must be in [1e-06, 1] [m]"},
      {"case range", head + "[[cases]]\n\"sphere.rho\" = -5\n",
       "invalid spec t.toml cases[0].\"sphere.rho\" = -5: must be in [1, 100000] [kg/m^3] (from "
       "foams to 4 x osmium)"},
      {"combination", head + "[base]\n\"mesh.h_max\" = 1e-3\n[grid]\n\"mesh.h_min\" = [2e-3]\n",
       "invalid spec t.toml grid.\"mesh.h_min\"[0] = 0.002: invalid mesh.h_max = 0.001: must be "
       ">= mesh.h_min = 0.002 [m]"},
      {"identical runs",
       head + "[[cases]]\n\"impact.velocity\" = 2\n[[cases]]\n\"impact.velocity\" = 2\n",
       "invalid spec t.toml: runs 0 and 1 have identical settings (impact.velocity=2)"},
      {"quoted and dotted key", head + "[base]\n\"mesh.h_min\" = 1e-3\nmesh.h_min = 2e-3\n",
       "invalid spec t.toml base.\"mesh.h_min\": is set twice (as a quoted and as a dotted key)"},
      {"not TOML", head + "[grid\n", ""},
  };
  for (const auto& bad : cases) {
    SCOPED_TRACE(bad.what);
    const std::string message = message_of(bad.toml);
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.rfind("invalid spec t.toml", 0), 0u) << message;
    if (!bad.message.empty()) {
      EXPECT_EQ(message, bad.message);
    }
  }
  // Messages whose tail comes from another module: check the parts that are ours.
  const std::string material =
      message_of(head + "[[cases]]\n\"sphere.material\" = \"unobtainium\"\n");
  EXPECT_EQ(
      material.rfind("invalid spec t.toml cases[0].\"sphere.material\" = 'unobtainium': must", 0),
      0u)
      << material;
  const std::string syntax = message_of(head + "[grid\n");
  EXPECT_EQ(syntax.rfind("invalid spec t.toml line 3 column", 0), 0u) << syntax;
  EXPECT_NE(syntax.find("not valid TOML"), std::string::npos) << syntax;
  const std::string unknown_key = message_of(head + "[base]\n\"sphere.colour\" = \"red\"\n");
  EXPECT_EQ(unknown_key.rfind("invalid spec t.toml base.\"sphere.colour\" = 'red': ", 0), 0u)
      << unknown_key;
}

// Issue 42: each run is validated as `corlab simulate` would, all of its keys together: keys
// that are only valid together (friction with an angle, h_max with a finer h_min) are accepted in
// a grid or one case, and a combination that is invalid names its run.
TEST(SweepSpec, EachRunIsValidatedWithAllOfItsKeys) {
  const std::string head = "[study]\nname = \"t\"\n";
  const auto grid =
      parse_sweep_spec(head +
                           "[base]\n\"mesh.h_min\" = 1e-3\n\"solver.model\" = \"3d\"\n"
                           "[grid]\n\"impact.angle\" = "
                           "[30, 45]\n\"contact.friction\" = [0.2, 0.5]\n",
                       "t.toml");
  EXPECT_EQ(grid.expand().size(), 4u);
  const auto one_case =
      parse_sweep_spec(head +
                           "[[cases]]\n\"solver.model\" = \"3d\"\n\"impact.angle\" = 30\n"
                           "\"contact.friction\" = 0.3\n\"mesh.h_min\" = "
                           "1e-3\n[[cases]]\n\"mesh.h_min\" = 1e-4\n\"mesh.h_max\" = 2e-4\n",
                       "t.toml");
  EXPECT_EQ(one_case.expand().size(), 2u);
  EXPECT_EQ(message_of(head + "[grid]\n\"impact.angle\" = [0, 30]\n\"contact.friction\" = [0.3]\n"),
            "invalid spec t.toml run 0 (impact.angle=0, contact.friction=0.3): "
            "grid.\"contact.friction\"[0]: invalid contact.friction = 0.3: must be 0 with the "
            "axisymmetric model (friction needs solver.model = 3d)");
  // A value that is wrong alone is still named where it was written.
  EXPECT_EQ(message_of(head + "[[cases]]\n\"impact.angle\" = 30\n\"contact.friction\" = 11\n"),
            "invalid spec t.toml cases[0].\"contact.friction\" = 11: must be in [0, 10] [-]");
}

// Issue 42: runs whose settings are written differently but resolve to the same configuration
// (a number as text, the default model named, a material spelled with spaces) are refused, not
// run twice.
TEST(SweepSpec, RunsThatResolveToTheSameConfigurationAreRefused) {
  const std::string head = "[study]\nname = \"t\"\n";
  for (const char* velocity : {"\"5.0\"", "\"5e0\"", "\" 5\""}) {
    SCOPED_TRACE(velocity);
    const std::string message =
        message_of(head + "[[cases]]\n\"impact.velocity\" = 5\n[[cases]]\n" +
                   "\"impact.velocity\" = " + velocity + "\n");
    EXPECT_EQ(
        message.rfind("invalid spec t.toml: runs 0 (impact.velocity=5) and 1 (impact.velocity=", 0),
        0u)
        << message;
    EXPECT_NE(message.find("resolve to the same configuration"), std::string::npos) << message;
  }
  const std::string material =
      message_of(head +
                 "[[cases]]\n\"sphere.material\" = \"E=370e9,nu=0.22,rho=3958\"\n[[cases]]\n"
                 "\"sphere.material\" = \"E=370e9, nu=0.22, rho=3958\"\n");
  EXPECT_NE(material.find("resolve to the same configuration"), std::string::npos) << material;
  // The default model named and left out: the same run.
  EXPECT_NE(message_of(head + "[[cases]]\n\"solver.model\" = \"axisymmetric\"\n[[cases]]\n"
                              "\"impact.velocity\" = 5\n")
                .find("runs 0 (solver.model=axisymmetric) and 1 (impact.velocity=5) resolve"),
            std::string::npos);
  // Runs that differ in physics are kept apart.
  EXPECT_EQ(parse_sweep_spec(head + "[[cases]]\n\"impact.velocity\" = 5\n[[cases]]\n"
                                    "\"impact.velocity\" = \"5.000001\"\n",
                             "t.toml")
                .expand()
                .size(),
            2u);
}

TEST(SweepSpec, MissingFileIsAnInputError) {
  EXPECT_THROW(load_sweep_spec("/nonexistent/spec.toml"), InputError);
}

}  // namespace
}  // namespace corlab::study

namespace corlab::study {
namespace {

// "[a, b, ...]" of n distinct values start, start + step, ...
std::string values(int n, double start, double step) {
  std::string out = "[";
  for (int i = 0; i < n; ++i) out += (i ? ", " : "") + std::to_string(start + i * step);
  return out + "]";
}

TEST(SweepSpec, HugeGridIsRefusedBeforeExpansionUnlessMaxRunsSaysSo) {
  const std::string grid = "[grid]\n\"impact.velocity\" = " + values(100, 1.0, 0.1) +
                           "\n\"substrate.sigma_y\" = " + values(100, 300e6, 1e6) +
                           "\n\"sphere.rho\" = " + values(100, 3000.0, 10.0) + "\n";
  try {
    (void)parse_sweep_spec("[study]\nname = \"big\"\n" + grid, "big.toml");
    ADD_FAILURE() << "a 10^6-run grid was accepted";
  } catch (const InputError& err) {
    EXPECT_EQ(std::string(err.what()),
              "invalid spec big.toml: expands to 1000000 runs, more than [study] max_runs = 10000 "
              "(default 10000, at most 1000000); set max_runs = 1000000 in [study] to run them "
              "all");
  }
  const std::string small = "[grid]\n\"impact.velocity\" = " + values(3, 1.0, 1.0) + "\n";
  EXPECT_THROW((void)parse_sweep_spec("[study]\nname = \"s\"\nmax_runs = 2\n" + small, "s.toml"),
               InputError);
  const auto spec = parse_sweep_spec("[study]\nname = \"s\"\nmax_runs = 3\n" + small, "s.toml");
  EXPECT_EQ(spec.expand().size(), 3u);
  EXPECT_NE(spec.to_toml().find("max_runs = 3"), std::string::npos);
}

// issue 31 item 3: a grid of 10^6 values for one key did not answer in 60 s (a pairwise duplicate
// check before the run count); max_runs = 9765625 ended in bad_alloc.
TEST(SweepSpec, ALongGridIsSizedBeforeItsValuesAreRead) {
  std::string many = "[";
  for (int i = 0; i < 200'000; ++i) many += (i ? ", " : "") + std::to_string(1 + i);
  many += "]";
  const auto start = std::chrono::steady_clock::now();
  test::expect_input_error(
      [&] {
        (void)parse_sweep_spec("[study]\nname = \"g\"\n[grid]\n\"impact.velocity\" = " + many,
                               "g.toml");
      },
      "invalid spec g.toml: expands to 200000 runs, more than [study] max_runs = 10000 (default "
      "10000, at most 1000000); set max_runs = 200000 in [study] to run them all");
  // the same 200,000 values with a duplicate at the end, allowed by max_runs: found in
  // O(n log n) (the pairwise check took 11 s for 80,000), and named with its first occurrence
  many.back() = ',';
  many += " 7]";
  test::expect_input_error(
      [&] {
        (void)parse_sweep_spec(
            "[study]\nname = \"g\"\nmax_runs = 300000\n[grid]\n\"impact.velocity\" = " + many,
            "g.toml");
      },
      "invalid spec g.toml grid.\"impact.velocity\"[200000] = 7: must differ from "
      "grid.\"impact.velocity\"[6] (duplicate grid value)");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
  test::expect_input_error(
      [] { (void)parse_sweep_spec("[study]\nname = \"g\"\nmax_runs = 9765625\n", "g.toml"); },
      "invalid spec g.toml study.max_runs: must be an integer in [1, 1000000]");
  test::expect_input_error(
      [&] {
        (void)parse_sweep_spec(
            "[study]\nname = \"g\"\n[grid]\n\"impact.velocity\" = " + values(1000, 1.0, 0.01) +
                "\n\"sphere.rho\" = " + values(1000, 3000.0, 1.0) +
                "\n\"substrate.sigma_y\" = " + values(1000, 300e6, 1e5),
            "g.toml");
      },
      "invalid spec g.toml: expands to 1000000000 runs, more than [study] max_runs = 10000 "
      "(default 10000, at most 1000000); split the study");
}

}  // namespace
}  // namespace corlab::study
