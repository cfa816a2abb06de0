// Inputs refused at the boundary (issue 12 item 2): every reproducer of the issue that is an
// input problem gives one InputError line naming the field, its value and the limit.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/config/config_limits.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "corlab/core/error.hpp"
#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/solver/run_cost.hpp"
#include "corlab/materials/material_database.hpp"
#include "support/input_errors.hpp"
#include "support/scratch_files.hpp"

namespace corlab::fem {
namespace {

// The message of the InputError that applying `items` (key=value) and validating throws.
std::string refusal(const std::vector<std::string>& items) {
  return test::input_error_message([&] {
    ImpactConfig c;
    apply_settings(c, items, "--set");
    validate(c);
  });
}

struct Reproducer {
  std::vector<std::string> settings;
  std::string starts_with;  // "invalid <field> = <value>: must ..."
};

TEST(ConfigLimits, IssueReproducersAreRefusedWithOneLineNamingTheField) {
  const std::vector<Reproducer> cases{
      {{"impact.gap=1e20", "mesh.h_min=1.5e-3", "mesh.contact_elements=0"},
       "invalid impact.gap = 1e+20: must be in [0, 1] [m]"},
      {{"impact.gap=1e15"}, "invalid impact.gap = 1000000000000000: must be in [0, 1] [m]"},
      {{"impact.gap=1e10"}, "invalid impact.gap = 10000000000"},
      {{"impact.gap=0.5"}, "invalid impact.gap = 0.5: must be <= sphere.radius = 0.035 [m]"},
      {{"sphere.E=2.1e17"}, "invalid sphere.E = 2.1e+17: must be in [10000, 10000000000000]"},
      {{"substrate.E=2.1e17"}, "invalid substrate.E = 2.1e+17"},
      {{"substrate.rho=1e308"}, "invalid substrate.rho = 1e+308"},
      {{"substrate.rho=1e-3"}, "invalid substrate.rho = 0.001"},
      {{"sphere.rho=1e308"}, "invalid sphere.rho = 1e+308"},
      {{"solver.hourglass=1e308"}, "invalid solver.hourglass = 1e+308: must be in [0, 0.15]"},
      {{"solver.hourglass=10"}, "invalid solver.hourglass = 10"},
      {{"solver.bulk_viscosity_quadratic=1e308"},
       "invalid solver.bulk_viscosity_quadratic = 1e+308: must be in [0, 2]"},
      {{"solver.bulk_viscosity_linear=1"}, "invalid solver.bulk_viscosity_linear = 1"},
      {{"impact.velocity=1e308"}, "invalid impact.velocity = 1e+308: must be in (0, 1000]"},
      {{"impact.velocity=1000"},
       "invalid impact.velocity = 1000: must be low enough for the "
       "predicted contact radius"},
      {{"impact.velocity=500", "substrate.sigma_y=100e6"}, "invalid impact.velocity = 500"},
      {{"solver.penalty_scale=1.0", "solver.safety_factor=1.0"},
       "invalid solver.penalty_scale = 1: must be in [0.1, 0.5]"},
      {{"solver.penalty_scale=0.5", "solver.safety_factor=0.9"},
       "invalid solver.safety_factor = 0.9: must be <= 1/sqrt(1 + solver.penalty_scale) = 0.8165"},
      {{"solver.penalty_scale=1e-3"}, "invalid solver.penalty_scale = 0.001"},
      {{"substrate.radius=2e-3"}, "invalid substrate.radius = 0.002: must be >= 0.0106 [m]"},
      {{"substrate.E=1e6", "substrate.sigma_y=1e4"}, "invalid impact.velocity = 5"},
      {{"sphere.radius=5"}, "invalid sphere.radius = 5"},
      {{"sphere.sigma_y=50"}, "invalid sphere.sigma_y = 50: must be in [2.1e+06, 2.1e+10)"},
      {{"solver.t_max=1e-6"}, "invalid solver.t_max = 1e-06: must be 0 (automatic) or > "},
      {{"substrate.sigma_y="},
       "invalid substrate.sigma_y = '': must be a finite number, or "
       "`none`"},
      {{"impact.velocity=2", "impact.velocity=3"},
       "invalid --set impact.velocity = '3': must be given once"},
      {{"sphere.material=E=1e9,E=2e9,nu=0.3,rho=1000"},
       "invalid sphere.E = '2e9': must be given "
       "once"},
      {{"substrate.material=steel_ma2023,sy=1e8,sigma_y=2e8"}, "invalid substrate.sigma_y = '2e8'"},
      {{"substrate.hardening=3e11"}, "invalid substrate.hardening = 300000000000: must be < "},
      {{"substrate.nu=0.4999999"}, "invalid solver.max_steps = 20000000: must be >= the estimated"},
      {{"impact.velocity"}, "invalid --set = 'impact.velocity': must be key=value"},
      {{"impact.angle=90"}, "invalid impact.angle = 90: must be in [0, 90) [deg]"},
      {{"impact.angle=-1"}, "invalid impact.angle = -1: must be in [0, 90) [deg]"},
      {{"contact.friction=-0.1"}, "invalid contact.friction = -0.1: must be in [0, 10]"},
      {{"contact.friction=0.3"}, "invalid contact.friction = 0.3: must be 0 with the axisymmetric"},
      {{"solver.model=2d"}, "invalid solver.model = '2d': must be one of axisymmetric, 3d"},
      {{"impact.angle=30"},
       "invalid impact.angle = 30: must be 0 with solver.model = axisymmetric (an oblique impact "
       "needs solver.model = 3d)"},
      {{"solver.model=axisymmetric", "impact.angle=1e-10"},
       "invalid impact.angle = 1e-10: must be 0 with solver.model = axisymmetric"},
      {{"solver.model=3d", "substrate.shape=rigid", "impact.angle=1e-300"},
       "invalid impact.angle = 1e-300: must be 0 or >= 1 [deg]"},
      {{"solver.model=3d", "impact.angle=30", "substrate.shape=sphere"},
       "invalid substrate.shape = 'sphere': must be flat or rigid with the 3-D model"},
      {{"solver.model=3d", "substrate.shape=rigid", "impact.repeats=2"},
       "invalid impact.repeats = 2: must be 1 with the 3-D model"},
      {{"solver.model=3d", "substrate.shape=rigid", "mesh.h_min=1e-5", "mesh.contact_elements=0"},
       "invalid mesh.h_min = 1e-05: the 3-D mesh it gives is refused"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.settings.front());
    const std::string message = refusal(c.settings);
    EXPECT_EQ(message.rfind(c.starts_with, 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(ConfigLimits, StepBudgetCanBeRaised) {
  ImpactConfig c;
  apply_settings(c, {"substrate.nu=0.4999999"}, "--set");  // near-incompressible: fast waves
  const RunEstimate e = estimate_run(c);
  EXPECT_GT(e.steps, static_cast<double>(c.solver.max_steps));
  EXPECT_THROW(validate(c), InputError);
  c.solver.max_steps = static_cast<long long>(2.0 * e.steps);
  EXPECT_NO_THROW(validate(c));
}

TEST(ConfigLimits, EstimateOfThePaperCaseBoundsItsStepCount) {
  // The paper case runs 11,412 steps to separation (corlab simulate, defaults); the estimate is
  // of a run that never separates (to t_max = 20 Hertz times), so it must be larger.
  const RunEstimate e = estimate_run(ImpactConfig{});
  EXPECT_GT(e.steps, 11412.0);
  EXPECT_LT(e.steps, 20.0 * 11412.0);
  EXPECT_GT(e.time_step, 0.0);
}

TEST(ConfigLimits, MaterialKeysApplyFirstWhateverTheOrder) {
  ImpactConfig c;
  apply_settings(c, {"substrate.sigma_y=300e6", "substrate.material=steel_ma2023"}, "--set");
  EXPECT_DOUBLE_EQ(*c.substrate.material.yield_stress, 300e6);
}

TEST(ConfigLimits, TomlArrayForAScalarAndEmptyNumberAreErrors) {
  const auto dir = test::fresh_dir("configs");
  const auto write = [&](const std::string& name, const std::string& text) {
    const auto file = dir / name;
    test::spit(file, text);
    return file;
  };
  auto message = [](const std::filesystem::path& f) {
    return test::input_error_message([&] { (void)load_impact_config(f); });
  };
  EXPECT_EQ(message(write("corlab_cfg_a.toml", "[impact]\nvelocity = [5.0]\n")),
            "invalid impact.velocity = 'an array': must be a single value, not a list");
  EXPECT_EQ(message(write("corlab_cfg_b.toml", "[substrate]\nsigma_y = \"\"\n"))
                .rfind("invalid substrate.sigma_y = ''", 0),
            0u);
  EXPECT_NE(message(write("corlab_cfg_c.toml", "[impact]\nvelocity = 5.0\nvelocity = 6.0\n")), "");
  EXPECT_EQ(message(write("corlab_cfg_d.toml", "[output]\ntimes = [1e-5, 2e-5]\n")), "");
}

// Issue 42: a 10 m second sphere meshed 2.8 million elements and ran past 20 min with no word;
// the work caps refuse it before anything is meshed, in one line with the estimate, the cap and
// the key that raises it.
TEST(ConfigLimits, WorkCapsRefuseBeforeMeshing) {
  const auto start = std::chrono::steady_clock::now();
  const std::string message =
      refusal({"substrate.shape=sphere", "substrate.radius=10", "mesh.h_min=0.25e-3"});
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
  EXPECT_EQ(message.rfind("invalid solver.max_elements = 2e+06: must be >= the element count "
                          "estimated before meshing, 3.",
                          0),
            0u)
      << message;
  EXPECT_NE(message.find("or raise solver.max_elements to run it"), std::string::npos);
  ImpactConfig raised;
  apply_settings(raised,
                 {"substrate.shape=sphere", "substrate.radius=10", "solver.max_elements=10000000"},
                 "--set");
  EXPECT_NO_THROW(validate(raised));
  // The work cap (elements x expected steps) names its own key.
  EXPECT_EQ(refusal({"solver.max_element_steps=1e6"})
                .rfind("invalid solver.max_element_steps = 1e+06: must be >= the work (elements x "
                       "expected steps: ",
                       0),
            0u);
  ImpactConfig paper;
  validate(paper);
  const RunEstimate e = estimate_run(paper);
  EXPECT_GT(e.element_steps(), 1e6);
  EXPECT_LT(e.element_steps(), paper.solver.max_element_steps / 1000.0);
}

// The a-priori element count against the built mesh: 0.63-2.0 of it in 2-D over the shipped
// studies (docs/user/errors.md), here a few shapes held to 0.35-2.1; exact in 3-D (tensor grids
// counted from their node distributions; a graded ball gave 0.06x the sphere on the rigid flat).
TEST(ConfigLimits, ElementEstimateFollowsTheMesh) {
  const std::vector<std::vector<std::string>> cases{
      {},
      {"mesh.transitions=0"},
      {"substrate.shape=rigid"},
      {"substrate.shape=sphere", "substrate.radius=0.1"},
      {"substrate.shape=sphere", "substrate.radius=1", "mesh.h_max=0.02"},
      {"impact.velocity=0.01", "mesh.h_min=1e-3"},
      {"solver.model=3d", "mesh.h_min=1.5e-3", "mesh.contact_elements=3"},
      {"solver.model=3d", "impact.angle=30", "mesh.h_min=1.5e-3", "mesh.contact_elements=3"},
      {"solver.model=3d", "substrate.shape=rigid", "mesh.h_min=1.5e-3", "mesh.contact_elements=0"},
  };
  for (const auto& settings : cases) {
    ImpactConfig c;
    apply_settings(c, settings, "--set");
    const double estimate = estimate_elements(c);
    const double built = estimate_run_cost(c).elements;
    SCOPED_TRACE(::testing::PrintToString(settings) + " estimate " + std::to_string(estimate) +
                 " built " + std::to_string(built));
    if (uses_3d_model(c)) {  // tensor grids: counted exactly (a graded ball gave 0.06x)
      EXPECT_EQ(estimate, built);
      continue;
    }
    EXPECT_GT(estimate, 0.35 * built);
    EXPECT_LT(estimate, 2.1 * built);
  }
}

// Issue 42: mesh.h_max below mesh.h_min is refused with the 3-D model too (it left the 3-D mesh
// uniform at the contact size: 15x the elements); an unused key is not refused (a second
// sphere's substrate.depth, like a rigid flat's sizes).
TEST(ConfigLimits, SizesAndUnusedKeysAreTreatedAlikeInEveryGeometry) {
  for (const char* model : {"solver.model=axisymmetric", "solver.model=3d"}) {
    EXPECT_EQ(refusal({model, "mesh.h_max=1e-5"}),
              "invalid mesh.h_max = 1e-05: must be >= mesh.h_min = 0.00025 [m]");
  }
  ImpactConfig sphere;
  apply_settings(sphere, {"substrate.shape=sphere", "substrate.depth=1e-5"}, "--set");
  EXPECT_NO_THROW(validate(sphere));
  EXPECT_EQ(
      refusal({"substrate.depth=1e-5"}).rfind("invalid substrate.depth = 1e-05: must be >=", 0),
      0u);
}

}  // namespace
}  // namespace corlab::fem

namespace corlab::fem {
namespace {

// substrate.boundary (the flat's far faces, docs/theory/solver.md "Far boundary"): a choice key,
// echoed and refused where the target has no far face.
TEST(ConfigLimits, SubstrateBoundaryIsAChoiceOfTheFlatOnly) {
  EXPECT_EQ(refusal({"substrate.boundary=open"}),
            "invalid substrate.boundary = 'open': must be one of fixed, absorbing, viscous_spring");
  EXPECT_EQ(refusal({"substrate.boundary=absorbing", "substrate.shape=rigid"}),
            "invalid substrate.boundary = 'absorbing': must be fixed with substrate.shape = rigid "
            "(absorbing far faces need the flat substrate)");
  EXPECT_EQ(refusal({"substrate.boundary=absorbing", "substrate.shape=sphere"}).substr(0, 61),
            "invalid substrate.boundary = 'absorbing': must be fixed with ");
  EXPECT_EQ(refusal({"substrate.boundary=absorbing"}), "");
  EXPECT_EQ(refusal({"substrate.boundary=viscous_spring", "substrate.shape=rigid"}).substr(0, 66),
            "invalid substrate.boundary = 'viscous_spring': must be fixed with ");
  EXPECT_EQ(refusal({"substrate.boundary= fixed "}), "");
  ImpactConfig c;
  EXPECT_EQ(c.substrate.boundary, SubstrateBoundary::kFixed);  // the paper's fixed base
  apply_setting(c, "substrate.boundary", "absorbing");
  EXPECT_EQ(c.substrate.boundary, SubstrateBoundary::kAbsorbing);
  EXPECT_EQ(to_string(c.substrate.boundary), "absorbing");
  apply_setting(c, "substrate.boundary", "viscous_spring");
  EXPECT_EQ(to_string(c.substrate.boundary), "viscous_spring");
}

// contact.friction_enforcement (docs/theory/solver3d.md, "Contact and friction"): a choice key
// of the 3-D model, kinematic by default; the axisymmetric model, which has no friction, refuses
// the other value.
TEST(ConfigLimits, FrictionEnforcementIsAChoiceOfThe3dModel) {
  EXPECT_EQ(refusal({"contact.friction_enforcement=spring", "solver.model=3d"}),
            "invalid contact.friction_enforcement = 'spring': must be one of kinematic, penalty");
  EXPECT_EQ(refusal({"contact.friction_enforcement=penalty"}),
            "invalid contact.friction_enforcement = 'penalty': must be kinematic (the default) "
            "with the axisymmetric model (friction needs solver.model = 3d)");
  EXPECT_EQ(refusal({"contact.friction_enforcement=kinematic"}), "");
  EXPECT_EQ(refusal({"contact.friction_enforcement=penalty", "solver.model=3d", "impact.angle=40",
                     "contact.friction=0.1", "substrate.shape=rigid"}),
            "");
  ImpactConfig c;
  EXPECT_EQ(c.contact.enforcement, FrictionEnforcement::kKinematic);
  apply_setting(c, "contact.friction_enforcement", "penalty");
  EXPECT_EQ(c.contact.enforcement, FrictionEnforcement::kPenalty);
  EXPECT_EQ(to_string(c.contact.enforcement), "penalty");
}

}  // namespace
}  // namespace corlab::fem
