// corlab2026p where accurate, the FE elsewhere (auto_restitution.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dataset/auto_restitution.hpp"

#include <gtest/gtest.h>

#include "corlab/materials/material_database.hpp"
#include "corlab/restitution/registry.hpp"

namespace corlab::dataset {
namespace {

study::FePair pair(const char* sphere, const char* substrate, double radius_ratio = 0.0) {
  return {.sphere = parse_material_spec(sphere, "sphere"),
          .substrate = parse_material_spec(substrate, "substrate"),
          .shape = radius_ratio > 0 ? fem::SubstrateShape::kSphere : fem::SubstrateShape::kFlat,
          .radius_ratio = radius_ratio};
}

ModelRangeCheck check(const study::FePair& p, double v) {
  return corlab2026p_accurate(study::fe_curve_config(p, v));
}

TEST(AutoRestitution, TheModelAnswersInsideItsRangeOnly) {
  // v_y = 0.0601 m/s: the model answers from 1.1 v_y to 3 v_y (kCorlab2026pAccurateVelocityRatio).
  const auto al = pair("alumina_ma2023", "aluminium_ma2023");
  EXPECT_TRUE(check(al, 0.12).accurate) << check(al, 0.12).why;
  EXPECT_TRUE(check(al, 0.18).accurate) << check(al, 0.18).why;
  EXPECT_NE(check(al, 0.19).why.find("v/v_y = 3.162 above 3"), std::string::npos)
      << check(al, 0.19).why;
  EXPECT_NE(check(al, 2.0).why.find("near-yield"), std::string::npos);
  EXPECT_NE(check(al, 1e-3).why.find("first yield"), std::string::npos);  // below v_y
  EXPECT_NE(check(pair("alumina_ma2023", "E=70e9,nu=0.22,rho=2500"), 1.0).why.find("not yield"),
            std::string::npos);
  auto rigid = al;
  rigid.shape = fem::SubstrateShape::kRigid;
  EXPECT_NE(check(rigid, 0.12).why.find("rigid"), std::string::npos);
  // R1/R2 = 0.05 is below the pair box's 0.1; 0.5 is inside.
  EXPECT_NE(check(pair("alumina_ma2023", "aluminium_ma2023", 0.05), 0.12).why.find("R1/R2"),
            std::string::npos);
  const auto half = pair("alumina_ma2023", "aluminium_ma2023", 0.5);
  EXPECT_TRUE(check(half, 0.08).accurate) << check(half, 0.08).why;
  // nu = 0.1 is outside [0.2, 0.45].
  EXPECT_NE(check(pair("E=370e9,nu=0.1,rho=3958", "aluminium_ma2023"), 0.12).why.find("nu_sphere"),
            std::string::npos);
}

TEST(AutoRestitution, InsideTheRangeTheModelAnswersWithItsInterval) {
  const auto al = pair("alumina_ma2023", "aluminium_ma2023");
  const auto points = auto_curve(al, {0.1, 0.15}, {});  // no FE run: both inside
  restitution::ModelOptions options;
  const auto model = restitution::make_model("corlab2026p", al.sphere, al.substrate, options);
  for (const auto& p : points) {
    EXPECT_EQ(p.answered_by, "corlab2026p");
    EXPECT_EQ(p.status, "model");
    EXPECT_EQ(p.e, model.cor(p.velocity));
    constexpr double kP = kCorlab2026pAccurateInterval95;
    EXPECT_DOUBLE_EQ(p.e_error, p.e * kP / (1 - kP));
  }
}

}  // namespace
}  // namespace corlab::dataset
