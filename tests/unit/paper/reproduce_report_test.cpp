// fit.json's errors of the models against the FE runs (reproduce_report.cpp): eq. 19's per group
// and overall ("model_error"), and corlab2026 against eq. 19 on Table 2
// ("corlab2026_versus_eq19"), on a comparison built by hand.
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "paper/reproduce_internal.hpp"

namespace corlab::study::reproduce_detail {
namespace {

using json = nlohmann::json;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

json run(const std::string& study,
         const std::string& group,
         double v,
         double e_fe,
         double e_paper,
         double e_corlab2026) {
  return {{"study", study},
          {"group", group},
          {"velocity", v},
          {"e_fe", e_fe},
          {"e_paper", e_paper},
          {"e_ours", e_paper},
          {"e_corlab2026", e_corlab2026}};
}

json comparison() {
  return json::array({
      run("table2", "b", 1.0, 0.5, 0.55, 0.52),  // paper +10 %, ours +4 %
      run("table2", "b", 2.0, 0.4, 0.32, 0.42),  // -20 %, +5 %
      run("table2", "a", 5.0, 0.8, 0.84, 0.72),  // +5 %, -10 %
      run("table2", "a", 10.0, 0.8, kNaN, 0.8),  // eq. 19 undefined: not counted
      run("table2", "a", 20.0, 0.0, 0.1, 0.1),   // e_FE = 0: counted as a run, no error
      run("table4", "c", 1.0, 0.5, 0.25, kNaN),  // another study: not in the Table 2 numbers
  });
}

TEST(ReproduceReport, ModelErrorPerGroupAndOverall) {
  json fits = {{"comparison", comparison()}};
  add_comparison_numbers(fits);
  const json& e = fits["model_error"]["e_paper"];
  ASSERT_EQ(e["groups"].size(), 3U);  // by (study, group): table2/a, table2/b, table4/c
  const json& a = e["groups"][0];
  EXPECT_EQ(a["group"], "a");
  EXPECT_EQ(a["runs"], 2);  // the run at e_FE = 0 counts, the NaN one does not
  EXPECT_NEAR(a["largest_relative_error"].get<double>(), 0.05, 1e-15);
  const json& b = e["groups"][1];
  EXPECT_EQ(b["runs"], 2);
  EXPECT_NEAR(b["mean_relative_error"].get<double>(), -0.05, 1e-15);
  EXPECT_NEAR(b["rms_relative_error"].get<double>(), std::sqrt((0.01 + 0.04) / 2), 1e-15);
  EXPECT_NEAR(b["largest_relative_error"].get<double>(), -0.2, 1e-15);  // signed
  EXPECT_EQ(b["largest_at_velocity"], 2.0);
  const json& all = e["overall"];
  EXPECT_EQ(all["runs"], 4);
  EXPECT_NEAR(all["largest_relative_error"].get<double>(), 0.5, 1e-15);  // magnitude
  EXPECT_NEAR(all["rms_relative_error"].get<double>(), std::sqrt((0.0025 + 0.01 + 0.04 + 0.25) / 4),
              1e-15);
}

TEST(ReproduceReport, Corlab2026AgainstEq19OnTable2) {
  json fits = {{"comparison", comparison()}};
  add_comparison_numbers(fits);
  const json& t2 = fits["corlab2026_versus_eq19"];
  EXPECT_EQ(t2["study"], "table2");
  EXPECT_EQ(t2["cases"], 3);  // both models defined and e_FE != 0
  EXPECT_EQ(t2["corlab2026_at_least_as_close"], 2);
  const json& ours = t2["corlab2026"];
  EXPECT_EQ(ours["n"], 3);
  EXPECT_NEAR(ours["worst"].get<double>(), -0.1, 1e-15);
  EXPECT_NEAR(ours["bias"].get<double>(), (0.04 + 0.05 - 0.1) / 3, 1e-15);
  EXPECT_NEAR(ours["rms"].get<double>(), std::sqrt((0.0016 + 0.0025 + 0.01) / 3), 1e-15);
  const json& paper = t2["ma2023"];
  EXPECT_EQ(paper["n"], 3);
  EXPECT_NEAR(paper["worst"].get<double>(), -0.2, 1e-15);
  EXPECT_NEAR(paper["bias"].get<double>(), (0.1 - 0.2 + 0.05) / 3, 1e-15);
}

TEST(ReproduceReport, NoTable2RunsNoCases) {
  json fits = {{"comparison", json::array({run("table4", "c", 1.0, 0.5, 0.25, 0.5)})}};
  add_comparison_numbers(fits);
  EXPECT_EQ(fits["corlab2026_versus_eq19"]["cases"], 0);
  EXPECT_TRUE(std::isnan(fits["corlab2026_versus_eq19"]["corlab2026"]["rms"].get<double>()));
}

}  // namespace
}  // namespace corlab::study::reproduce_detail
