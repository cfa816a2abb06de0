// Issue 42: the generated DEM scripts hold user text as data, never as code, and the export's
// inputs end in one-line errors naming the field (labels, pairs, radii, table rows, targets).
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "corlab/core/error.hpp"
#include "corlab/dem/calibration.hpp"
#include "corlab/dem/dem_export.hpp"
#include "corlab/dem/lammps_mapping.hpp"
#include "corlab/materials/material_database.hpp"
#include "dem/detail/script_text.hpp"
#include "support/input_errors.hpp"

namespace corlab::dem {
namespace {

using test::input_error_message;

// Names a user may give a table file: line breaks that would start a command in each code, quotes
// that would end YADE's or LAMMPS's strings, LAMMPS's `$`, `&` and `"""`, a comment, unicode,
// bytes that are not UTF-8, a carriage return.
const std::vector<std::string> kHostileNames{"x\nshell touch PWNED\n.csv",
                                             "z\n__import__(\"os\").system(\"touch PWNED\")\n#.csv",
                                             "q'); import os; os.system('touch PWNED'); ('.csv",
                                             "a\"\"\"\nshell touch PWNED\n\"\"\".csv",
                                             "v${x}$(touch PWNED)`touch PWNED`.csv",
                                             "amp &\nshell touch PWNED",
                                             "cr\rshell touch PWNED\r.csv",
                                             "r\xc3\xa9sultats \xe2\x80\xa8 \xff\x01\x7f.csv",
                                             "# comment\\\n.csv"};

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// The lines of a script that are not comments: what the code runs.
std::vector<std::string> commands(const std::string& text) {
  std::vector<std::string> out;
  for (const auto& line : lines(text)) {
    if (line.rfind('#', 0) != 0) out.push_back(line);
  }
  return out;
}

// A two-type export with a wall whose e(v) comes from the table `source` (export-wide) and the
// pair table `pair_source` for 1-wall: every writer shows both names.
ExportSpec table_spec(const std::string& source, const std::string& pair_source) {
  const auto& db = MaterialDatabase::builtin();
  ExportSpec spec;
  spec.types = {{db.get("aluminium_ma2023"), 0.005, "al"}, {db.get("steel_ma2023"), 0.003, "st"}};
  spec.wall = db.get("aluminium_ma2023");
  spec.wall_label = "plate";
  spec.table = tabulated_curve({0.3, 3.0}, {0.9, 0.7});
  spec.table_source = source;
  spec.v_min = 0.3;
  spec.v_max = 3.0;
  spec.fit_points = 3;  // the fits' cost, not the text, grows with it
  PairTable t;
  t.first = "1";
  t.second = "wall";
  t.source = pair_source;
  t.curve = tabulated_curve({0.3, 3.0}, {0.8, 0.6});
  spec.pair_tables = {t};
  return spec;
}

std::vector<std::string> scripts(const ExportSpec& spec) {
  const auto pairs = calibrate_pairs(spec);
  return {write_lammps(spec, pairs), write_lammps(spec, pairs, false),
          write_lammps_compiled(spec, pairs), write_liggghts(spec, pairs), write_yade(spec, pairs)};
}

TEST(DemScriptText, EscapesEverythingACodeReadsInAComment) {
  EXPECT_EQ(detail::script_text("fe_results.csv"), "fe_results.csv");
  EXPECT_EQ(detail::script_text("a b/c-d_e+f.csv"), "a b/c-d_e+f.csv");
  EXPECT_EQ(detail::script_text("x\nshell"), "x\\x0ashell");
  EXPECT_EQ(detail::script_text("\"'\\$&#"), "\\x22\\x27\\x5c\\x24\\x26\\x23");
  EXPECT_EQ(detail::script_text("\xc3\xa9\xff\x7f"), "\\xc3\\xa9\\xff\\x7f");
  EXPECT_EQ(detail::python_string("glass"), "'glass'");
  EXPECT_EQ(detail::python_string("it's"), "'it\\x27s'");
  for (const auto& name : kHostileNames) {
    for (const char c : detail::script_text(name)) {
      EXPECT_TRUE(c >= 0x20 && c <= 0x7e) << name;
      EXPECT_EQ(std::string("\"'$&#").find(c), std::string::npos) << name;
    }
  }
}

// Whatever the table names, each script runs the same commands as with a plain name, and no
// comment line could reach into the next one (LAMMPS: `&` at the end, `"""`).
TEST(DemScriptText, HostileTableNamesChangeNoCommand) {
  const auto plain = scripts(table_spec("fe.csv", "fe_pair.csv"));
  for (const auto& name : kHostileNames) {
    const auto spec = table_spec(name, name);
    const auto hostile = scripts(spec);
    for (std::size_t k = 0; k < plain.size(); ++k) {
      EXPECT_EQ(commands(hostile[k]), commands(plain[k])) << "script " << k << ": " << name;
      EXPECT_EQ(lines(hostile[k]).size(), lines(plain[k]).size()) << "script " << k;
      for (const auto& line : lines(hostile[k])) {
        EXPECT_FALSE(!line.empty() && line.back() == '&') << line;
      }
    }
    // The names stay findable, escaped, in the descriptions and the JSON.
    const auto pairs = calibrate_pairs(spec);
    EXPECT_NE(pairs[0].target.find(detail::script_text(name)), std::string::npos);
    EXPECT_NO_THROW(write_json(spec, pairs));
  }
}

TEST(DemScriptText, HostileMaterialNamesStayInTheComments) {
  auto spec = table_spec("fe.csv", "fe_pair.csv");
  const auto plain = scripts(spec);
  spec.types[0].material.name = "al\nshell touch PWNED\n";
  spec.wall->name = "w\"\"\"\nimport os";
  const auto hostile = scripts(spec);
  for (std::size_t k = 0; k < plain.size(); ++k) {
    EXPECT_EQ(commands(hostile[k]), commands(plain[k])) << "script " << k;
  }
}

TEST(DemExportContract, LabelsAreUniqueAndNotTypeIds) {
  auto spec = table_spec("fe.csv", "fe_pair.csv");
  spec.types[0].label = "2";  // --pair 1/2 would name type 2 by id, not this type
  EXPECT_NE(input_error_message([&] { calibrate_pairs(spec); })
                .find("invalid type label = '2': must be unique among the types and the wall, "
                      "not 'wall' and not a number"),
            std::string::npos);
  spec = table_spec("fe.csv", "fe_pair.csv");
  spec.wall_label = "st";  // --pair al/st would name the wall or type 2
  EXPECT_NE(input_error_message([&] {
              calibrate_pairs(spec);
            }).find("invalid wall label = 'st': must be unique"),
            std::string::npos);
  // A wall of a type's database material is named after it too: fine, but a pair naming it must
  // say which (the type id or `wall`).
  spec = table_spec("fe.csv", "fe_pair.csv");
  spec.types[0].label.clear();
  spec.wall_label.clear();
  EXPECT_EQ(calibrate_pairs(spec).size(), 5u);
  spec.pair_restitution = {parse_pair_restitution("aluminium_ma2023/st=0.5")};
  EXPECT_EQ(input_error_message([&] { calibrate_pairs(spec); }),
            "invalid pair = 'aluminium_ma2023/st': must be a pair whose names are unambiguous "
            "(aluminium_ma2023 names type 1 and the wall: say 1 or wall)");
  spec.pair_restitution = {parse_pair_restitution("1/st=0.5"),
                           parse_pair_restitution("wall/2=0.4")};
  EXPECT_EQ(calibrate_pairs(spec).size(), 5u);
}

TEST(DemExportContract, EachPairIsNamedOnceAndHasAParticle) {
  auto spec = table_spec("fe.csv", "fe_pair.csv");
  spec.pair_restitution = {parse_pair_restitution("wall/wall=0.3")};
  EXPECT_EQ(input_error_message([&] { calibrate_pairs(spec); }),
            "invalid pair = 'wall/wall': must be a pair with a particle type (the wall has no "
            "wall/wall contact)");
  spec.pair_restitution = {parse_pair_restitution("al/st=0.3"), parse_pair_restitution("2/1=0.4")};
  EXPECT_EQ(input_error_message([&] { calibrate_pairs(spec); }),
            "invalid pair = '2/1=0.4': must be a pair that no other --pair or --pair-table names "
            "(one target per pair)");
  spec.pair_restitution = {parse_pair_restitution("al/plate=0.3")};  // 1-wall has a table
  EXPECT_NE(input_error_message([&] { calibrate_pairs(spec); }).find("invalid pair-table"),
            std::string::npos);
}

TEST(DemExportContract, RadiusAndTableRowsInTheirRanges) {
  auto spec = table_spec("fe.csv", "fe_pair.csv");
  for (const double r : {1e-300, 1e-10, 1e4, 1e300}) {
    spec.types[0].radius = r;
    EXPECT_EQ(input_error_message([&] { calibrate_pairs(spec); }),
              fmt::format("invalid type 1 (al) radius = {}: must be in [1e-09, 1000] [m]", r));
  }
  for (const int n : {-1, 0, 1, kMaxTablePoints + 1}) {
    EXPECT_EQ(input_error_message([&] { validate_table_points(n); }),
              fmt::format("invalid table-points = {}: must be in [2, 10000] (rows per pair of the "
                          "e(v) tables)",
                          n));
  }
  spec = table_spec("fe.csv", "fe_pair.csv");
  const auto pairs = calibrate_pairs(spec);
  EXPECT_THROW(write_table_csv(spec, pairs, 1), InputError);
  EXPECT_THROW(write_json(spec, pairs, 0), InputError);
}

TEST(DemExportContract, AModelAboveOneNamesTheModelAndTheSpeed) {
  const auto& db = MaterialDatabase::builtin();
  ExportSpec spec;
  spec.types = {{db.get("aluminium_ma2023"), 0.005, ""}};
  spec.wall = db.get("aluminium_ma2023");
  spec.wall_only = true;
  spec.model = "wu2003";
  const std::string what = input_error_message([&] { calibrate_pairs(spec); });
  EXPECT_NE(what.find("invalid target e of pair 1-wall"), std::string::npos) << what;
  EXPECT_NE(what.find("wu2003 (aluminium_ma2023 on aluminium_ma2023) gives it at v = 0.316228 m/s"),
            std::string::npos)
      << what;
}

TEST(DemExportContract, TsujiAlphaOnlyWhereItIsExact) {
  EXPECT_NO_THROW(calibrate_tsuji_alpha(kMinRestitution));
  for (const double e : {1e-20, 0.0, 1.0, -0.5}) {
    EXPECT_EQ(input_error_message([&] { calibrate_tsuji_alpha(e); }),
              fmt::format("invalid restitution = {}: must be in [1e-12, 1)", e));
  }
  EXPECT_THROW(lammps_tsuji_input(1e-20), InputError);
}

}  // namespace
}  // namespace corlab::dem
