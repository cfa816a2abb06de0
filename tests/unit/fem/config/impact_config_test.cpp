// ImpactConfig text input and validation (impact_config.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/config/impact_config.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "corlab/core/error.hpp"
#include "support/input_errors.hpp"
#include "support/scratch_files.hpp"

namespace corlab::fem {
namespace {

using test::input_error_message;

TEST(ImpactConfig, DefaultsAreThePaperCase) {
  const ImpactConfig c;
  EXPECT_NO_THROW(validate(c));
  EXPECT_DOUBLE_EQ(c.sphere.radius, 35e-3);
  EXPECT_DOUBLE_EQ(c.impact.velocity, 5.0);
  EXPECT_DOUBLE_EQ(*c.substrate.material.yield_stress, 500e6);
  EXPECT_FALSE(c.sphere.material.yield_stress.has_value());
}

TEST(ImpactConfig, ApplySettingSetsEveryKind) {
  ImpactConfig c;
  apply_setting(c, "impact.velocity", "2.5");
  apply_setting(c, "substrate.sigma_y", "none");
  apply_setting(c, "sphere.material", "alumina_ma2023");
  apply_setting(c, "substrate.hardening", "1e9");
  apply_setting(c, "output.times", "1e-5, 2e-5");
  apply_setting(c, "output.history_every", "5");
  apply_setting(c, "solver.hourglass", "0.1");
  EXPECT_DOUBLE_EQ(c.impact.velocity, 2.5);
  EXPECT_FALSE(c.substrate.material.yield_stress.has_value());
  EXPECT_DOUBLE_EQ(c.sphere.material.youngs_modulus, 370e9);
  EXPECT_DOUBLE_EQ(c.substrate.material.hardening_modulus, 1e9);
  ASSERT_EQ(c.output.field_times.size(), 2u);
  EXPECT_DOUBLE_EQ(c.output.field_times[1], 2e-5);
  EXPECT_EQ(c.output.history_every, 5);
  EXPECT_DOUBLE_EQ(c.solver.hourglass, 0.1);
}

TEST(ImpactConfig, ErrorsNameKeyValueAndConstraint) {
  ImpactConfig c;
  const std::string unknown = input_error_message([&] { apply_setting(c, "impact.speed", "3"); });
  EXPECT_NE(unknown.find("impact.speed"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("impact.velocity"), std::string::npos) << unknown;
  const std::string bad = input_error_message([&] { apply_setting(c, "impact.velocity", "fast"); });
  EXPECT_EQ(bad, "invalid impact.velocity = 'fast': must be a finite number");
  c.impact.velocity = -1.0;
  const std::string neg = input_error_message([&] { validate(c); });
  EXPECT_NE(neg.find("invalid impact.velocity = -1"), std::string::npos) << neg;
  ImpactConfig d;
  d.solver.safety_factor = 1.5;
  EXPECT_NE(input_error_message([&] { validate(d); }).find("solver.safety_factor"),
            std::string::npos);
  const std::string mat =
      input_error_message([&] { apply_setting(d, "sphere.material", "unobtainium"); });
  EXPECT_NE(mat.find("unobtainium"), std::string::npos) << mat;
  EXPECT_EQ(mat.find('\n'), std::string::npos);
}

TEST(ImpactConfig, SubstrateShapeRigidIsTheFlatWithoutCompliance) {
  ImpactConfig c;
  EXPECT_EQ(c.substrate.shape, SubstrateShape::kFlat);
  EXPECT_FALSE(rigid_target(c));
  const double e_star_flat = contact_effective_modulus(c);
  EXPECT_DOUBLE_EQ(e_star_flat, effective_modulus(c.sphere.material, c.substrate.material));
  apply_setting(c, "substrate.shape", " rigid ");
  EXPECT_TRUE(rigid_target(c));
  EXPECT_EQ(to_string(c.substrate.shape), "rigid");
  // 1/E* = (1 - nu^2)/E of the sphere alone: twice the steel-on-steel E*.
  EXPECT_DOUBLE_EQ(contact_effective_modulus(c), 210e9 / (1.0 - 0.3 * 0.3));
  EXPECT_DOUBLE_EQ(contact_effective_modulus(c), 2.0 * e_star_flat);
  // The contact's yield stress is the sphere's (elastic here), no longer the substrate's.
  EXPECT_FALSE(contact_yield_stress(c).has_value());
  c.sphere.material.yield_stress = 800e6;
  EXPECT_DOUBLE_EQ(*contact_yield_stress(c), 800e6);
  // The substrate's keys are unused: a substrate too small for the contact is no error.
  c.substrate.radius = 1e-6;
  c.substrate.depth = 1e-6;
  EXPECT_NO_THROW(validate(c));
}

TEST(ImpactConfig, SubstrateShapeErrors) {
  ImpactConfig c;
  EXPECT_EQ(input_error_message([&] { apply_setting(c, "substrate.shape", "round"); }),
            "invalid substrate.shape = 'round': must be one of flat, rigid, sphere");
  apply_setting(c, "substrate.shape", "rigid");
  c.mesh.file = "anything.msh";
  const std::string msg = input_error_message([&] { validate(c); });
  EXPECT_NE(msg.find("substrate.shape"), std::string::npos) << msg;
  EXPECT_NE(msg.find("mesh.file"), std::string::npos) << msg;
}

TEST(ImpactConfig, LoadsToml) {
  const auto file = test::fresh_dir("config") / "impact.toml";
  test::spit(file,
             "[impact]\nvelocity = 2\n[substrate]\nmaterial = \"steel_ma2023,sy=700e6\"\n"
             "[output]\ntimes = [1e-5, 3e-5]\nhistory_every = 4\n");
  const ImpactConfig c = load_impact_config(file);
  EXPECT_DOUBLE_EQ(c.impact.velocity, 2.0);
  EXPECT_DOUBLE_EQ(*c.substrate.material.yield_stress, 700e6);
  EXPECT_EQ(c.output.field_times.size(), 2u);
  EXPECT_EQ(c.output.history_every, 4);
  test::spit(file, "[impact]\nvelocty = 2\n");
  EXPECT_NE(input_error_message([&] { load_impact_config(file); }).find("impact.velocty"),
            std::string::npos);
  test::spit(file, "[impact\nvelocity = 2\n");
  EXPECT_NE(input_error_message([&] { load_impact_config(file); }).find("line"), std::string::npos);
  std::filesystem::remove_all(file.parent_path());
}

}  // namespace
}  // namespace corlab::fem
