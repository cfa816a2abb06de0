// `--model auto` on the held-out rows of the shipped datasets (issue 40): where corlab2026p
// answers (corlab2026p_accurate), its e is within 2 % of the row's FE e or inside the row's FE
// error bar; elsewhere auto answers with the FE run itself (fe_curve_config is the dataset's run:
// docs/user/predict.md). The sample is every held-out row (the random 20 %: case id = 0 mod 5,
// and issue 26's corners: E ratio > 10, density ratio > 5) of data/fe_restitution and
// data/fe_restitution_pairs, the worst corlab2026p rows among them; no FE run.
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "corlab/dataset/auto_restitution.hpp"
#include "corlab/restitution/registry.hpp"
#include "corlab/study/fe_curve.hpp"
#include "corlab/study/results_table.hpp"

namespace corlab::dataset {
namespace {

Material row_material(const study::ResultsTable& t, std::size_t i, const std::string& body) {
  const auto number = [&](const char* column) { return std::stod(t.cell(i, body + "_" + column)); };
  Material m;
  m.youngs_modulus = number("E");
  m.poisson_ratio = number("nu");
  m.density = number("rho");
  if (const double sy = number("sigma_y"); std::isfinite(sy)) m.yield_stress = sy;
  m.hardening_modulus = number("H");
  return m;
}

bool held_out(const study::ResultsTable& t, std::size_t i) {
  const std::string& id = t.cell(i, "case_id");
  const bool random = std::stoull(id.substr(1), nullptr, 16) % 5 == 0;
  const bool corner =
      std::stod(t.cell(i, "modulus_ratio")) > 10.0 || std::stod(t.cell(i, "density_ratio")) > 5.0;
  return random || corner;
}

struct Score {
  int rows = 0;          // held-out rows
  int model_rows = 0;    // answered by corlab2026p
  int beyond_2pc = 0;    // of those, neither within 2 % nor inside the FE error bar
  double worst = 0.0;    // worst |e_model - e_FE| / e_FE where the model answers [-]
  double skipped = 0.0;  // worst of the same where the model does not answer [-]
};

void score(const char* file, bool pairs, Score& s) {
  const study::ResultsTable t =
      study::read_results(std::string(CORLAB_SOURCE_DIR) + "/data/" + file + "/dataset.csv")
          .where("included", "true");
  ASSERT_GT(t.size(), 1000U) << file;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!held_out(t, i)) continue;
    const double ratio = pairs ? std::stod(t.cell(i, "radius_ratio")) : 0.0;
    const study::FePair pair{
        .sphere = row_material(t, i, "sphere"),
        .substrate = row_material(t, i, "substrate"),
        .shape = ratio > 0.0 ? fem::SubstrateShape::kSphere : fem::SubstrateShape::kFlat,
        .radius_ratio = ratio};
    const double v = std::stod(t.cell(i, "velocity"));
    const double e_fe = std::stod(t.cell(i, "e"));
    const double e_error = std::stod(t.cell(i, "e_error"));
    restitution::ModelOptions options;
    options.radius_ratio = ratio;
    const double e_model =
        restitution::make_model("corlab2026p", pair.sphere, pair.substrate, options).cor(v);
    const double rel = std::abs(e_model - e_fe) / e_fe;
    ++s.rows;
    if (!corlab2026p_accurate(study::fe_curve_config(pair, v)).accurate) {
      s.skipped = std::max(s.skipped, rel);
      continue;
    }
    ++s.model_rows;
    s.worst = std::max(s.worst, rel);
    if (rel > 0.02 && std::abs(e_model - e_fe) > e_error) {
      ++s.beyond_2pc;
      ADD_FAILURE() << file << " row " << t.cell(i, "design_index") << ": corlab2026p " << e_model
                    << " against the FE " << e_fe << " +- " << e_error;
    }
  }
}

TEST(AutoHeldOut, TheModelAnswersOnlyWithin2PercentOfTheFe) {
  Score s;
  score("fe_restitution", false, s);
  score("fe_restitution_pairs", true, s);
  // Measured (2026-11-28): 1,208 held-out rows, 130 answered by the model, worst 1.62 %; the
  // rows it leaves to the FE include its worst (9.7 % off inside its damage number, 46 %
  // beyond). With the v/v_y bound lifted, 184 answered rows miss 2 %.
  std::printf(
      "held-out rows %d, answered by corlab2026p %d (worst %.2f %%), by the FE %d "
      "(corlab2026p's worst there %.1f %%)\n",
      s.rows, s.model_rows, 100 * s.worst, s.rows - s.model_rows, 100 * s.skipped);
  EXPECT_EQ(s.beyond_2pc, 0);
  EXPECT_GE(s.model_rows, 40);  // a sample, not a vacuous pass
  EXPECT_GT(s.skipped, 0.09);   // the worst rows are in the sample (and left to the FE)
}

}  // namespace
}  // namespace corlab::dataset
