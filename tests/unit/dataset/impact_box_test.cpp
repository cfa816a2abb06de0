// Dataset design: the Sobol sequence's stratification, the box map and its inverse, first yield,
// and the committed spec (studies/dataset/fe_restitution.toml) being what the design writes.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "corlab/core/error.hpp"
#include "corlab/dataset/dataset_spec.hpp"
#include "corlab/dataset/sobol_sequence.hpp"
#include "corlab/restitution/first_yield.hpp"
#include "corlab/restitution/thornton1997.hpp"
#include "corlab/study/sweep_spec.hpp"

namespace corlab::dataset {
namespace {

TEST(SobolSequence, EveryPrefixOfPowerOfTwoPointsIsStratifiedInEachCoordinate) {
  const auto points = sobol_points(kBoxDimension, 256);
  ASSERT_EQ(points.size(), 256U);
  for (const double x : points[0]) EXPECT_EQ(x, 0.0);  // the origin GSL leaves out
  for (std::size_t n = 2; n <= points.size(); n *= 2) {
    for (int d = 0; d < kBoxDimension; ++d) {
      std::set<long> cells;
      for (std::size_t i = 0; i < n; ++i) {
        const double x = points[i][static_cast<std::size_t>(d)];
        ASSERT_GE(x, 0.0);
        ASSERT_LT(x, 1.0);
        cells.insert(static_cast<long>(std::floor(x * static_cast<double>(n))));
      }
      EXPECT_EQ(cells.size(), n) << "dimension " << d << ", first " << n << " points";
    }
  }
}

TEST(SobolSequence, RefusesDimensionsGslLacks) {
  EXPECT_THROW((void)sobol_points(0, 4), InputError);
  EXPECT_THROW((void)sobol_points(kSobolMaxDimension + 1, 4), InputError);
}

TEST(FirstYield, WeakerBodyYieldsFirstAtThorntonsVelocity) {
  Material sphere{.name = "s",
                  .youngs_modulus = 100e9,
                  .poisson_ratio = 0.25,
                  .density = 5000.0,
                  .yield_stress = std::nullopt,
                  .hardening_modulus = 0.0,
                  .source = ""};
  Material substrate{.name = "b",
                     .youngs_modulus = 200e9,
                     .poisson_ratio = 0.35,
                     .density = 7000.0,
                     .yield_stress = 400e6,
                     .hardening_modulus = 0.0,
                     .source = ""};
  const double e_star = effective_modulus(sphere, substrate);
  const double c_b = 1.295 * std::exp(0.736 * 0.35);
  auto y = restitution::first_yield(sphere, substrate);  // elastic sphere: the substrate
  EXPECT_FALSE(y.sphere_first);
  EXPECT_DOUBLE_EQ(y.pressure, c_b * 400e6);
  // v_y = sqrt(pi^4/40) sqrt(p^5 / (E*^4 rho_sphere)), written out.
  EXPECT_NEAR(y.velocity,
              std::sqrt(std::pow(M_PI, 4) / 40.0 * std::pow(y.pressure, 5) /
                        (std::pow(e_star, 4) * 5000.0)),
              1e-12 * y.velocity);
  sphere.yield_stress = 300e6;  // C(0.25) 300 MPa < C(0.35) 400 MPa: the sphere first
  y = restitution::first_yield(sphere, substrate);
  EXPECT_TRUE(y.sphere_first);
  EXPECT_DOUBLE_EQ(y.pressure, 1.295 * std::exp(0.736 * 0.25) * 300e6);
}

// The configuration a design point's settings give (dataset base + point settings).
fem::ImpactConfig point_config(const ImpactBox& box, const DimensionlessImpact& p) {
  fem::ImpactConfig config;
  study::apply_settings(config, dataset_base_settings(box));
  study::apply_settings(config, point_settings(box, p));
  fem::validate(config);
  return config;
}

TEST(ImpactBox, SettingsGiveBackTheDimensionlessPoint) {
  const DatasetDesign design{.name = "t", .points = 64, .box = {}};
  for (const DesignPoint& dp : design_points(design)) {
    const DimensionlessImpact& p = dp.point;
    const DimensionlessInputs d = dimensionless_inputs(point_config(design.box, p));
    const double tol = 1e-12;
    EXPECT_NEAR(d.k2 / p.k2, 1.0, tol) << dp.index;
    EXPECT_NEAR(d.velocity_ratio / p.velocity_ratio, 1.0, tol) << dp.index;
    EXPECT_NEAR(d.modulus_ratio / p.modulus_ratio, 1.0, tol) << dp.index;
    EXPECT_DOUBLE_EQ(d.nu_sphere, p.nu_sphere);
    EXPECT_DOUBLE_EQ(d.nu_substrate, p.nu_substrate);
    EXPECT_NEAR(d.hardening_ratio_substrate, p.hardening_ratio, tol);
    if (p.sphere_yield_ratio) {
      EXPECT_NEAR(d.sphere_yield_ratio / *p.sphere_yield_ratio, 1.0, tol);
      EXPECT_NEAR(d.hardening_ratio_sphere, p.hardening_ratio, tol);
    } else {
      EXPECT_TRUE(std::isinf(d.sphere_yield_ratio));
      EXPECT_EQ(d.hardening_ratio_sphere, 0.0);
    }
    EXPECT_EQ(d.density_ratio, 1.0);
  }
}

TEST(ImpactBox, EveryPointIsInsideTheBoxAndItsSpeedBounds) {
  const ImpactBox box;
  const DatasetDesign design{.name = "t", .points = 512, .box = box};
  int elastic = 0;
  for (const DesignPoint& dp : design_points(design)) {
    const DimensionlessImpact& p = dp.point;
    EXPECT_GE(p.k2, box.k2.min * (1 - 1e-12));
    EXPECT_LE(p.k2, box.k2.max);
    EXPECT_GE(p.velocity_ratio, box.velocity_ratio_min * (1 - 1e-12));
    const DimensionlessInputs d = dimensionless_inputs(point_config(box, p));
    const double v = d.velocity_ratio * d.first_yield_velocity;
    EXPECT_LE(v, box.velocity_max * (1 + 1e-12)) << dp.index;
    EXPECT_LE(d.damage_number, box.damage_number_max * (1 + 1e-12)) << dp.index;
    EXPECT_GE(p.nu_sphere, box.nu.min);
    EXPECT_LE(p.nu_substrate, box.nu.max);
    EXPECT_LE(p.hardening_ratio, box.hardening_ratio.max);
    elastic += p.sphere_yield_ratio ? 0 : 1;
  }
  EXPECT_EQ(elastic, 256);  // elastic_sphere_fraction 0.5 of a stratified design
}

TEST(DatasetSpec, CommittedSpecIsWhatTheDesignWrites) {
  std::ifstream in(CORLAB_SOURCE_DIR "/studies/dataset/fe_restitution.toml", std::ios::binary);
  ASSERT_TRUE(in) << "studies/dataset/fe_restitution.toml missing";
  std::ostringstream text;
  text << in.rdbuf();
  const std::string expected = dataset_spec_toml(
      DatasetDesign{}, "corlab dataset design --out studies/dataset/fe_restitution.toml");
  EXPECT_TRUE(text.str() == expected)
      << "regenerate: corlab dataset design --out studies/dataset/fe_restitution.toml";
  const study::SweepSpec spec = study::parse_sweep_spec(expected, "fe_restitution.toml");
  EXPECT_EQ(spec.run_count(), DatasetDesign{}.points);
}

}  // namespace
}  // namespace corlab::dataset
