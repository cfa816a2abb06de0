// A pair's target as `corlab predict` takes it (dem_export.cpp: pair_bodies, model_curve): the
// particle is the sphere, predict's accuracy warnings, and the external targets of
// --model fe|auto (ExportSpec::target_source), elastic pairs included.
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "corlab/core/error.hpp"
#include "corlab/dem/dem_export.hpp"
#include "corlab/materials/material_database.hpp"
#include "corlab/restitution/registry.hpp"

namespace corlab::dem {
namespace {

Material spec_material(const char* text) { return parse_material_spec(text, "test"); }

// The issue 41 pair: brass (sigma_y 250 MPa) particles on a stainless wall that yields later.
ExportSpec brass_on_stainless(double v_max) {
  ExportSpec spec;
  spec.types = {{spec_material("E=100e9,nu=0.34,rho=8500,sy=250e6"), 0.002, "brass"}};
  spec.wall = spec_material("E=193e9,nu=0.29,rho=8000,sy=300e6");
  spec.wall_label = "stainless";
  spec.model = "corlab2026p";
  spec.v_min = 0.1;
  spec.v_max = v_max;
  spec.wall_only = true;
  return spec;
}

TEST(DemExportTargets, TheParticleIsTheSphereAsPredictTakesIt) {
  const ExportSpec spec = brass_on_stainless(10.0);
  const auto pairs = calibrate_pairs(spec);
  ASSERT_EQ(pairs.size(), 1U);
  // Before: the softer brass was the flat ("stainless on brass"), 0.0012-0.024 from predict's
  // e at 0.1-10 m/s.
  EXPECT_EQ(pairs[0].target, "corlab2026p (brass on stainless)");
  const auto predict = restitution::make_model("corlab2026p", spec.types[0].material, *spec.wall);
  for (const double v : {0.1, 1.0, 10.0}) EXPECT_DOUBLE_EQ(pairs[0].curve(v), predict.cor(v));
  // predict's warnings: rho v^2/sigma_y of the particle on the wall is 8500 * 10^2 / 300e6 =
  // 2.8e-3 at 10 m/s, inside corlab2026p's 0.003; 1.1e-2 at 20 m/s, beyond.
  EXPECT_TRUE(pairs[0].warnings.empty());
  const auto fast = calibrate_pairs(brass_on_stainless(20.0));
  ASSERT_EQ(fast[0].warnings.size(), 1U);
  EXPECT_NE(fast[0].warnings[0].find("damage number"), std::string::npos) << fast[0].warnings[0];
}

TEST(DemExportTargets, AnElasticOtherBodyIsTheSphereOnTheYieldingParticle) {
  ExportSpec spec = brass_on_stainless(5.0);
  spec.wall = spec_material("E=70e9,nu=0.22,rho=2500");  // glass: a model needs a yielding flat
  spec.wall_label = "glass";
  const auto pairs = calibrate_pairs(spec);
  EXPECT_EQ(pairs[0].target, "corlab2026p (glass on brass, sphere density rho* = 8500 kg/m^3)");
}

TEST(DemExportTargets, FeAndAutoTakeEveryPairFromTheSourceElasticOnesIncluded) {
  ExportSpec spec;
  spec.types = {{spec_material("E=370e9,nu=0.22,rho=3958"), 0.001, "alumina"},
                {spec_material("E=70e9,nu=0.22,rho=2500"), 0.004, "glass"}};
  spec.wall = spec_material("E=70e9,nu=0.22,rho=2500");
  spec.wall_label = "plate";
  spec.model = "fe";
  spec.fit_points = 3;
  try {  // no source (the C library, the explorer): the model named, never a silent e = 1
    calibrate_pairs(spec);
    ADD_FAILURE() << "no throw";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "model");
    EXPECT_NE(std::string(e.what()).find("FE solver"), std::string::npos);
  }
  std::vector<PairBodies> asked;
  spec.target_source = [&asked](const PairBodies& b, std::span<const double> speeds) {
    asked.push_back(b);
    EXPECT_EQ(speeds.size(), 3U);
    const double e = b.radius_ratio > 0 ? 0.9999 : 0.99;
    return ExternalTarget{[e](double) { return e; }, "FE of " + b.sphere_label, {"a warning"}};
  };
  const auto pairs = calibrate_pairs(spec);  // every pair elastic: none refused
  ASSERT_EQ(pairs.size(), 5U);               // 1-1, 1-2, 2-2, 1-wall, 2-wall
  ASSERT_EQ(asked.size(), 5U);
  EXPECT_EQ(asked[1].sphere_label, "alumina");  // 1-2: the alumina particle on the glass one
  EXPECT_EQ(asked[1].substrate_label, "glass");
  EXPECT_DOUBLE_EQ(asked[1].radius_ratio, 0.25);
  EXPECT_EQ(asked[3].substrate_label, "plate");  // 1-wall: the particle on the wall, a flat
  EXPECT_EQ(asked[3].radius_ratio, 0.0);
  EXPECT_EQ(asked[3].sphere.density, 3958.0);
  EXPECT_EQ(pairs[3].target, "FE of alumina");
  EXPECT_EQ(pairs[3].warnings, std::vector<std::string>{"a warning"});
  EXPECT_DOUBLE_EQ(pairs[3].curve(2.0), 0.99);
  EXPECT_TRUE(pairs[3].thornton.has_value());  // fitted like any e(v)
}

}  // namespace
}  // namespace corlab::dem
