// FE e(v) on demand (fe_curve.hpp): the target, the runs' configs and keys, refused speeds.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/study/fe_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "corlab/materials/material_database.hpp"
#include "support/input_errors.hpp"
#include "support/scratch_files.hpp"

namespace corlab::study {
namespace {

using fem::SubstrateShape;

FePair alumina_on_aluminium() {
  return {.sphere = parse_material_spec("alumina_ma2023", "sphere"),
          .substrate = parse_material_spec("aluminium_ma2023", "substrate")};
}

TEST(FeCurve, TheShapeFollowsTheRadiusRatioUnlessNamed) {
  EXPECT_EQ(resolve_fe_shape("", 0.0), SubstrateShape::kFlat);
  EXPECT_EQ(resolve_fe_shape("", 0.5), SubstrateShape::kSphere);
  EXPECT_EQ(resolve_fe_shape("sphere", 2.0), SubstrateShape::kSphere);
  EXPECT_EQ(resolve_fe_shape("rigid", 0.0), SubstrateShape::kRigid);
  test::expect_input_error([] { resolve_fe_shape("sphere", 0.0); },
                           "invalid radius_ratio = 0: must be > 0 for a second sphere (R1/R2) [-]");
  test::expect_input_error([] { resolve_fe_shape("rigid", 0.5, "--shape", "--radius-ratio"); },
                           "invalid --radius-ratio = 0.5: must be 0 for a rigid target [-]");
  test::expect_input_error([] { resolve_fe_shape("cube", 0.0); },
                           "invalid shape = 'cube': must be flat, sphere or rigid");
}

TEST(FeCurve, TheConfigIsTheDefaultWithThePairAndTheSpeed) {
  FePair pair = alumina_on_aluminium();
  const fem::ImpactConfig flat = fe_curve_config(pair, 3.0);
  const fem::ImpactConfig defaults;
  EXPECT_EQ(flat.impact.velocity, 3.0);
  EXPECT_EQ(flat.sphere.material.youngs_modulus, pair.sphere.youngs_modulus);
  EXPECT_EQ(flat.substrate.material.yield_stress, pair.substrate.yield_stress);
  EXPECT_EQ(flat.mesh.h_min, defaults.mesh.h_min);  // the default mesh
  EXPECT_EQ(flat.substrate.radius, defaults.substrate.radius);
  pair.shape = SubstrateShape::kSphere;
  pair.radius_ratio = 0.5;
  EXPECT_DOUBLE_EQ(fe_curve_config(pair, 3.0).substrate.radius, 2.0 * defaults.sphere.radius);
  EXPECT_NO_THROW(fem::validate(fe_curve_config(pair, 3.0)));
}

TEST(FeCurve, AnElasticFlatIsAHalfSpaceForTheContactTime) {
  // alumina on glass at 1 m/s: Hertz t_c = 236 us (the run's 236.2 us), glass's dilatational
  // wave 5.65 km/s: 1.5 x 5.65e3 x 236e-6 / 2 = 1.0 m of glass, far elements 1/35 of it.
  FePair pair{.sphere = parse_material_spec("alumina_ma2023", "sphere"),
              .substrate = parse_material_spec("E=70e9,nu=0.22,rho=2500", "substrate")};
  const fem::ImpactConfig c = fe_curve_config(pair, 1.0);
  const double c_l = pair.substrate.dilatational_wave_speed();
  EXPECT_NEAR(c_l, 5654.0, 1.0);
  EXPECT_NEAR(c.substrate.radius, 1.5 * c_l * 236e-6 / 2.0, 0.01);
  EXPECT_EQ(c.substrate.depth, c.substrate.radius);
  EXPECT_DOUBLE_EQ(c.mesh.h_max, c.substrate.radius / 35.0);
  EXPECT_NO_THROW(fem::validate(c));
  EXPECT_GT(fe_curve_config(pair, 0.1).substrate.radius, c.substrate.radius);  // longer contact
  // A yielding flat keeps the dataset's block; two spheres keep theirs.
  const fem::ImpactConfig defaults;
  EXPECT_EQ(fe_curve_config(alumina_on_aluminium(), 1.0).substrate.radius,
            defaults.substrate.radius);
  pair.shape = SubstrateShape::kSphere;
  pair.radius_ratio = 1.0;
  EXPECT_EQ(fe_curve_config(pair, 1.0).substrate.radius, defaults.sphere.radius);
  EXPECT_EQ(fe_curve_config(pair, 1.0).mesh.h_max, defaults.mesh.h_max);
}

TEST(FeCurve, TheKeyHoldsTheWholeConfig) {
  const FePair pair = alumina_on_aluminium();
  const auto key = fe_run_key(fe_curve_config(pair, 3.0));
  EXPECT_EQ(key["config"]["impact"]["velocity"], 3.0);
  EXPECT_TRUE(key.contains("simd") && key.contains("error_estimate"));
  EXPECT_NE(key, fe_run_key(fe_curve_config(pair, 3.0000000001)));
  fem::ImpactConfig finer = fe_curve_config(pair, 3.0);
  finer.mesh.h_min /= 2;
  EXPECT_NE(key, fe_run_key(finer));
}

TEST(FeCurve, ASpeedTheSolverRefusesIsARowABadPairThrows) {
  const auto points = fe_curve(alumina_on_aluminium(), {2000.0}, {.jobs = 1});
  ASSERT_EQ(points.size(), 1U);
  EXPECT_EQ(points[0].status, "invalid");
  EXPECT_TRUE(std::isnan(points[0].e) && std::isnan(points[0].e_error));
  EXPECT_NE(points[0].detail.find("impact.velocity"), std::string::npos) << points[0].detail;
  FePair bad = alumina_on_aluminium();
  bad.substrate.poisson_ratio = 0.6;
  EXPECT_THROW(fe_curve(bad, {1.0}, {}), InputError);
}

TEST(FeCurve, TheRefinedCurveNeedsAPositiveTolerance) {
  for (const double tolerance : {0.0, -1e-3, std::nan("")}) {
    EXPECT_THROW(fe_curve_refined(alumina_on_aluminium(), {1.0, 2.0}, tolerance, {}), InputError);
  }
}

}  // namespace
}  // namespace corlab::study
