// Calibration of type pairs and the text exports (LAMMPS, LIGGGHTS, YADE, CSV, JSON).
#include "corlab/dem/dem_export.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "corlab/core/error.hpp"
#include "corlab/dem/calibration.hpp"
#include "corlab/dem/lammps_mapping.hpp"
#include "corlab/materials/material_database.hpp"

namespace corlab::dem {
namespace {

const Material& material(const char* name) { return MaterialDatabase::builtin().get(name); }

ExportSpec constant_spec() {
  ExportSpec spec;
  spec.types = {{material("steel_ma2023"), 0.005}, {material("alumina_ma2023"), 0.003}};
  spec.wall = material("steel_ma2023");
  spec.restitution = 0.6;
  return spec;
}

TEST(DemExport, ConstantEPairsAndCompensatedLammpsInput) {
  const auto spec = constant_spec();
  const auto pairs = calibrate_pairs(spec);
  ASSERT_EQ(pairs.size(), 5u);  // 1-1, 1-2, 2-2, 1-wall, 2-wall
  const double e_in = lammps_tsuji_input(0.6);
  const std::string lammps = write_lammps(spec, pairs);
  EXPECT_NE(lammps.find(fmt::format("pair_coeff 1 2 hertz")), std::string::npos);
  EXPECT_NE(lammps.find(fmt::format("{:.10g} tangential", e_in)), std::string::npos);
  EXPECT_NE(lammps.find("fix corlab_wall2 corlab_type2 wall/gran"), std::string::npos);
  // 1-2: R* = R1 R2/(R1 + R2), kn = 4/3 E*
  EXPECT_NEAR(pairs[1].effective_radius, 0.005 * 0.003 / 0.008, 1e-15);
  const std::string liggghts = write_liggghts(spec, pairs);
  EXPECT_NE(liggghts.find("coefficientRestitution peratomtypepair 3"), std::string::npos);
  EXPECT_NE(write_yade(spec, pairs).find("MindlinPhys(en=0.6)"), std::string::npos);
}

TEST(DemExport, ModelCurveFitsAndJson) {
  ExportSpec spec;
  spec.types = {{material("alumina_ma2023"), 0.005}};
  spec.wall = material("aluminium_ma2023");
  spec.wall_only = true;
  spec.model = "thornton1997";
  spec.v_min = 0.5;
  spec.v_max = 5.0;
  spec.fit_points = 5;
  const auto pairs = calibrate_pairs(spec);
  ASSERT_EQ(pairs.size(), 1u);
  ASSERT_TRUE(pairs[0].viscoelastic && pairs[0].liggghts && pairs[0].thornton);
  // Thornton's own law reproduces thornton1997 (p_y = 1.6 sigma_y); LIGGGHTS's law follows it
  // closely; the viscoelastic law can only follow it roughly (e ~ 1 - c v^(1/5)).
  EXPECT_NEAR(pairs[0].thornton->parameter / (1.6 * 380e6), 1.0, 1e-4);
  EXPECT_LT(pairs[0].liggghts->max_abs_error, 0.02);
  EXPECT_GT(pairs[0].viscoelastic->max_abs_error, pairs[0].liggghts->max_abs_error);
  const auto json = nlohmann::json::parse(write_json(spec, pairs, 8));
  EXPECT_EQ(json["pairs"][0]["pair"], "1-wall");
  EXPECT_EQ(json["pairs"][0]["table"].size(), 8u);
  EXPECT_NEAR(json["pairs"][0]["liggghts_yield_ratio"].get<double>(),
              pairs[0].liggghts_yield_ratio(), 1e-12);
  EXPECT_EQ(write_lammps(spec, pairs).find("\npair_style granular\n"), std::string::npos);
}

TEST(DemExport, BadSpecsNameTheField) {
  auto spec = constant_spec();
  spec.model = "thornton1997";  // two targets
  EXPECT_THROW(calibrate_pairs(spec), InputError);
  spec = constant_spec();
  spec.types[0].radius = -1.0;
  EXPECT_THROW(calibrate_pairs(spec), InputError);
  spec = constant_spec();
  spec.restitution.reset();
  spec.model = "thornton1997";  // alumina-alumina pair has no yield stress
  try {
    calibrate_pairs(spec);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("material pair"), std::string::npos);
  }
}

}  // namespace
}  // namespace corlab::dem
