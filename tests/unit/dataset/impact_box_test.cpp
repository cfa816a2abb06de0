// The dimensionless impact box (impact_box.hpp): a design point's settings give back the point,
// and every point lies inside the box and its speed bounds.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dataset/impact_box.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "corlab/core/error.hpp"
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

// The pair box: each point's settings give back its nine coordinates (rho* in v_y, k1 and the
// damage number), a quarter of a stratified design is on a flat, and the rest spans R1/R2.
TEST(ImpactBox, PairPointsGiveBackTheirRatiosAndSpanTheBox) {
  const DatasetDesign design{.name = "t", .points = 256, .box = pair_box()};
  const ImpactBox& box = design.box;
  int flats = 0;
  double smallest_ratio = 1.0;
  for (const DesignPoint& dp : design_points(design)) {
    const DimensionlessImpact& p = dp.point;
    const fem::ImpactConfig config = point_config(box, p);
    const DimensionlessInputs d = dimensionless_inputs(config);
    const double tol = 1e-12;
    EXPECT_NEAR(d.k2 / p.k2, 1.0, tol) << dp.index;
    EXPECT_NEAR(d.velocity_ratio / p.velocity_ratio, 1.0, tol) << dp.index;
    EXPECT_NEAR(d.modulus_ratio / p.modulus_ratio, 1.0, tol) << dp.index;
    EXPECT_NEAR(d.density_ratio / p.density_ratio, 1.0, tol) << dp.index;
    EXPECT_NEAR(d.radius_ratio, p.radius_ratio, tol) << dp.index;
    EXPECT_GE(p.density_ratio, box.density_ratio.min * (1 - tol));
    EXPECT_LE(p.density_ratio, box.density_ratio.max * (1 + tol));
    EXPECT_GE(p.modulus_ratio, box.modulus_ratio.min * (1 - tol));
    EXPECT_LE(p.modulus_ratio, box.modulus_ratio.max * (1 + tol));
    EXPECT_LE(d.damage_number, box.damage_number_max * (1 + tol)) << dp.index;
    EXPECT_LE(config.impact.velocity, box.velocity_max * (1 + tol)) << dp.index;
    if (p.radius_ratio == 0.0) {
      ++flats;
      EXPECT_FALSE(fem::sphere_target(config));
      EXPECT_DOUBLE_EQ(d.effective_density, config.sphere.material.density);
    } else {
      EXPECT_TRUE(fem::sphere_target(config));
      EXPECT_LE(p.radius_ratio, box.radius_ratio.max);
      smallest_ratio = std::min(smallest_ratio, p.radius_ratio);
      EXPECT_GT(d.effective_density, config.sphere.material.density);
    }
  }
  EXPECT_EQ(flats, 64);  // flat_fraction 0.25 of a stratified design
  EXPECT_LT(smallest_ratio, box.radius_ratio.min + 0.01);
}

TEST(ImpactBox, TheFlatBoxKeepsItsSevenCoordinates) {
  EXPECT_FALSE(is_pair_box(ImpactBox{}));
  EXPECT_EQ(box_dimension(ImpactBox{}), kBoxDimension);
  EXPECT_EQ(box_dimension(pair_box()), kPairBoxDimension);
  const std::vector<double> u(kBoxDimension, 0.5);
  EXPECT_THROW((void)box_point(pair_box(), u), InputError);
}

}  // namespace
}  // namespace corlab::dataset
