// The golden tier (ctest label golden; docs/dev/testing.md): a few coarse impacts whose results
// are pinned in tests/golden/golden.json, run at every SIMD level this CPU has (simd_level.hpp).
//
//   golden_test                      check (what ctest runs), one test per case
//   golden_test --rebaseline [FILE [CASE...]]  rerun every case (or the CASEs named), print old
//                                    and new side by side (for the commit message) and rewrite
//                                    FILE (default: the source's); a case not named keeps its pins
//
// Built as golden.json's `exact_build` (compiler and build type), every value must be the pinned
// one bit for bit, at each level: a solver change of one ulp in a constant moves the energy
// balance's last digits, and the pins catch it. Any other build (a sanitizer build, another
// compiler or CPU family, a level without a pin) is held to golden.json's `tolerance`, relative
// per value, against the level's pin or the nearest pinned level below it.
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "corlab/core/atomic_file.hpp"
#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/solver/discretisation_error.hpp"
#include "corlab/fem/solver/result_fields.hpp"
#include "corlab/fem/solver/simd_level.hpp"
#include "corlab/fem/solver/simulate.hpp"

namespace corlab::fem {
namespace {

using nlohmann::json;

/// The build the exact pins hold for: compiler, version and build type (tests/CMakeLists.txt).
constexpr const char* kBuild = CORLAB_GOLDEN_BUILD;

/// The pinned values of a run: result fields by name (one table: result_fields.hpp).
constexpr const char* kPinned[] = {"e",     "e_energy",        "e_last",   "energy_balance_error",
                                   "steps", "element_updates", "e_coarse", "e_error"};

std::filesystem::path default_file() {
  return std::filesystem::path(CORLAB_SOURCE_DIR) / "tests" / "golden" / "golden.json";
}

json read_file(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(fmt::format("cannot read '{}'", file.string()));
  return json::parse(in);
}

/// The fields a case pins: its own "fields" list (e.g. e_t and omega for an oblique impact), else
/// kPinned.
std::vector<std::string> pinned_fields(const json& c) {
  if (c.contains("fields")) return c.at("fields").get<std::vector<std::string>>();
  return {std::begin(kPinned), std::end(kPinned)};
}

/// The run of one case at one level: the pinned fields (e_coarse, e_error only with an error
/// estimate).
json run_case(const json& c, SimdLevel level) {
  ImpactConfig config;
  std::vector<std::string> items;
  for (const auto& [key, value] : c.at("settings").items()) {
    items.push_back(key + "=" + value.get<std::string>());
  }
  apply_settings(config, items, "golden.json");
  validate(config);
  set_simd_level(level);
  const bool estimate = c.value("error_estimate", false);
  const ImpactResult r = estimate ? simulate_with_error_estimate(config) : simulate(config);
  json out = json::object();
  const FieldInput in{&r, &config, r.wall_s};
  for (const std::string& name : pinned_fields(c)) {
    if (!estimate && (name == "e_coarse" || name == "e_error")) continue;
    const ResultField* f = find_result_field(name);
    if (f == nullptr) throw std::runtime_error("golden.json: unknown result field '" + name + "'");
    std::visit(
        [&](const auto& v) {
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, double> || std::is_same_v<T, long long>) out[name] = v;
        },
        f->value(in));
  }
  return out;
}

/// The pins a run at `level` is checked against: the level's own (exact), else the nearest
/// pinned level below it (tolerance); nullopt when none.
struct Reference {
  json pins;
  std::string level;
  bool exact;
};

std::optional<Reference> reference(const json& c, SimdLevel level, bool exact_build) {
  const json& pins = c.at("pins");
  for (int l = static_cast<int>(level); l >= 0; --l) {
    const std::string name(to_string(static_cast<SimdLevel>(l)));
    if (pins.contains(name)) {
      return Reference{pins.at(name), name, exact_build && l == static_cast<int>(level)};
    }
  }
  return std::nullopt;
}

/// One case: every supported level against its reference.
void check_case(const json& file, const json& c) {
  const bool exact_build = file.at("exact_build").get<std::string>() == kBuild;
  for (const SimdLevel level : supported_simd_levels()) {
    const std::optional<Reference> ref = reference(c, level, exact_build);
    ASSERT_TRUE(ref.has_value()) << "no pins for " << to_string(level) << " or below";
    const json got = run_case(c, level);
    for (const auto& [name, pinned] : ref->pins.items()) {
      ASSERT_TRUE(got.contains(name)) << name << " missing at " << to_string(level);
      const double want = pinned.get<double>();
      const double have = got.at(name).get<double>();
      const std::string where = fmt::format("{} at {} (pinned at {}, {})", name, to_string(level),
                                            ref->level, ref->exact ? "exact" : "tolerance");
      const std::string values = fmt::format("{}: pinned {}, got {} (relative change {:.2e})",
                                             where, want, have, (have - want) / want);
      if (ref->exact) {
        // Bit for bit: the same compiler, flags and instruction set give the same arithmetic.
        EXPECT_TRUE(have == want) << values;
      } else {
        const double rel = file.at("tolerance").at(name).get<double>();
        EXPECT_LE(std::abs(have - want), rel * std::abs(want)) << values;
      }
    }
  }
}

class GoldenCase : public ::testing::Test {
 public:
  GoldenCase(const json* file, const json* c) : file_(file), case_(c) {}
  void TestBody() override { check_case(*file_, *case_); }

 private:
  const json* file_;
  const json* case_;
};

/// Prints old and new pins side by side and returns the file with the new ones.
json rebaseline(json file, const std::vector<std::string>& only) {
  const std::vector<SimdLevel> levels = supported_simd_levels();
  fmt::print("golden rebaseline, build {} (was {})\n", kBuild, file.value("exact_build", "?"));
  fmt::print("{:<28} {:<10} {:<21} {:>24} {:>24} {:>10}\n", "case", "level", "value", "old", "new",
             "rel. change");
  for (json& c : file.at("cases")) {
    const std::string case_name = c.at("name").get<std::string>();
    if (!only.empty() && std::find(only.begin(), only.end(), case_name) == only.end()) continue;
    json fresh = json::object();
    for (const SimdLevel level : levels) {
      const std::string name(to_string(level));
      const json got = run_case(c, level);
      const json old = c.at("pins").value(name, json::object());
      for (const auto& [key, value] : got.items()) {
        const double now = value.get<double>();
        const double was = old.contains(key) ? old.at(key).get<double>() : std::nan("");
        fmt::print("{:<28} {:<10} {:<21} {:>24} {:>24} {:>10.2e}{}\n",
                   c.at("name").get<std::string>(), name, key, fmt::format("{}", was),
                   fmt::format("{}", now), (now - was) / was, now == was ? "" : "  *");
      }
      fresh[name] = got;
    }
    for (const auto& [name, pins] : c.at("pins").items()) {
      if (!fresh.contains(name)) {
        fmt::print(
            "warning: {} {}: not re-measured on this CPU, its pins are dropped (runs at {} "
            "are then held to the tolerance against the level below)\n",
            c.at("name").get<std::string>(), name, name);
      }
    }
    c["pins"] = fresh;
  }
  file["exact_build"] = kBuild;
  return file;
}

}  // namespace
}  // namespace corlab::fem

int main(int argc, char** argv) {
  using corlab::fem::json;
  try {
    if (argc >= 2 && std::strcmp(argv[1], "--rebaseline") == 0) {
      const std::filesystem::path file = argc >= 3 ? argv[2] : corlab::fem::default_file();
      const std::vector<std::string> only(argv + std::min(argc, 3), argv + argc);
      const json updated = corlab::fem::rebaseline(corlab::fem::read_file(file), only);
      corlab::write_file_atomically(file, updated.dump(2) + '\n');
      fmt::print("wrote {}\n", file.string());
      return 0;
    }
    ::testing::InitGoogleTest(&argc, argv);
    static const json file = corlab::fem::read_file(corlab::fem::default_file());
    for (const json& c : file.at("cases")) {
      const std::string name = c.at("name").get<std::string>();
      ::testing::RegisterTest(
          "GoldenImpact", name.c_str(), nullptr, nullptr, __FILE__, __LINE__,
          [&c]() -> ::testing::Test* { return new corlab::fem::GoldenCase(&file, &c); });
    }
    return RUN_ALL_TESTS();
  } catch (const std::exception& e) {
    std::cerr << "golden_test: " << e.what() << '\n';
    return 2;
  }
}
