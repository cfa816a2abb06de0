// Fuzz target: user text in the DEM exports (issue 42). The input, split at NUL bytes, gives the
// table's file name, a pair table's file name, a type's and the wall's material names and a type
// label; the export is refused with a one-line InputError (a bad label) or its LAMMPS, LIGGGHTS
// and YADE scripts run exactly the commands of the same export with plain names (and that label):
// the text stays in comments, whatever it holds.
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "corlab/dem/calibration.hpp"
#include "corlab/dem/dem_export.hpp"
#include "corlab/materials/material_database.hpp"
#include "fuzz_target.hpp"

namespace {

using corlab::dem::ExportSpec;

// One type on a wall, both e(v) from tables (the cheapest export that shows every kind of text).
ExportSpec spec_with(const std::vector<std::string>& text) {
  const auto field = [&](std::size_t k, const char* plain) {
    return k < text.size() ? text[k] : std::string(plain);
  };
  const auto& db = corlab::MaterialDatabase::builtin();
  ExportSpec spec;
  corlab::Material type = db.get("aluminium_ma2023");
  type.name = field(2, "aluminium_ma2023");
  const std::string label = field(4, "al");
  spec.types = {{type, 0.005, label.empty() ? std::string("al") : label}};
  spec.wall = db.get("steel_ma2023");
  spec.wall->name = field(3, "steel_ma2023");
  spec.wall_label = "plate";
  spec.wall_only = true;
  spec.table = corlab::dem::tabulated_curve({0.3, 3.0}, {0.9, 0.7});
  spec.table_source = field(0, "fe.csv");
  spec.v_min = 0.3;
  spec.v_max = 3.0;
  spec.fit_points = 2;
  corlab::dem::PairTable pair;
  pair.first = "1";
  pair.second = "wall";
  pair.source = field(1, "fe_pair.csv");
  pair.curve = corlab::dem::tabulated_curve({0.3, 3.0}, {0.8, 0.6});
  if (text.size() > 1) spec.pair_tables = {pair};
  return spec;
}

// The lines of the five scripts that are not comments.
std::string commands(const ExportSpec& spec) {
  const auto pairs = corlab::dem::calibrate_pairs(spec);
  std::string out;
  for (const auto& script :
       {corlab::dem::write_lammps(spec, pairs), corlab::dem::write_lammps(spec, pairs, false),
        corlab::dem::write_lammps_compiled(spec, pairs), corlab::dem::write_liggghts(spec, pairs),
        corlab::dem::write_yade(spec, pairs)}) {
    std::istringstream in(script);
    for (std::string line; std::getline(in, line);) {
      if (line.rfind('#', 0) != 0) out += line + "\n";
      if (!line.empty() && line.back() == '&') {
        std::fprintf(stderr, "dem_export: a line ends with '&': %s\n", line.c_str());
        std::abort();
      }
    }
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> text(1);
  for (std::size_t i = 0; i < size && text.size() <= 5; ++i) {
    if (data[i] == 0) {
      text.emplace_back();
    } else {
      text.back() += static_cast<char>(data[i]);
    }
  }
  corlab::fuzz::expect_clean("dem_export", [&] {
    std::vector<std::string> plain{"fe.csv", "fe_pair.csv", "aluminium_ma2023", "steel_ma2023"};
    plain.resize(text.size());
    if (text.size() > 4) plain[4] = text[4];  // the label is a name the scripts use
    static std::map<std::vector<std::string>, std::string> known;  // plain exports, once each
    auto it = known.find(plain);
    if (it == known.end()) it = known.emplace(plain, commands(spec_with(plain))).first;
    const std::string& expected = it->second;
    if (commands(spec_with(text)) != expected) {
      std::fprintf(stderr, "dem_export: user text changed a command\n");
      std::abort();
    }
  });
  return 0;
}
