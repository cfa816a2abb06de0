// The dimensionless impact box (impact_box.hpp): a design point's settings give back the point,
// and every point lies inside the box and its speed bounds.
#include "corlab/dataset/impact_box.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "corlab/dataset/dataset_spec.hpp"
#include "corlab/study/sweep_spec.hpp"

namespace corlab::dataset {
namespace {

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

}  // namespace
}  // namespace corlab::dataset
