// The tangential part of the DEM exports (--friction): Mindlin's G*, each code's keywords.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dem/tangential.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "corlab/core/error.hpp"
#include "corlab/dem/dem_export.hpp"
#include "corlab/materials/material_database.hpp"

namespace corlab::dem {
namespace {

// Kharaz et al. (2001): alumina sphere (R 2.5 mm) on a glass wall, mu = 0.092.
ExportSpec kharaz_spec(double friction) {
  ExportSpec spec;
  spec.types = {{parse_material_spec("E=380e9,nu=0.23,rho=4000", "type"), 2.5e-3, "alumina"}};
  spec.wall = parse_material_spec("E=70e9,nu=0.25,rho=2500", "wall");
  spec.wall_label = "glass";
  spec.wall_only = true;
  spec.pair_restitution = {{"alumina", "wall", 1.0}};
  spec.friction = friction;
  return spec;
}

TEST(DemTangential, MindlinShearModulus) {
  const Material alumina = parse_material_spec("E=380e9,nu=0.23,rho=4000", "type");
  const Material glass = parse_material_spec("E=70e9,nu=0.25,rho=2500", "wall");
  // 1/G* = (2 - nu1)/G1 + (2 - nu2)/G2, G = E/(2(1 + nu)): 13.5211 GPa
  const double g1 = 380e9 / 2.46;
  const double g2 = 70e9 / 2.5;
  EXPECT_NEAR(mindlin_shear_modulus(alumina, glass), 1.0 / (1.77 / g1 + 1.75 / g2), 1e-3);
  EXPECT_NEAR(mindlin_shear_modulus(alumina, glass), 13.5211e9, 1e5);
  // One material: 8 G* = 4 G/(2 - nu), LAMMPS's "k_t = 4G/(2-nu)" for the Mindlin solution.
  EXPECT_NEAR(mindlin_coefficient(mindlin_shear_modulus(glass, glass)), 4.0 * g2 / 1.75, 1e-3);
  // x_gamma = sqrt(4 G*/E*): 0.9268 for alumina on glass (E* = 62.952 GPa)
  EXPECT_NEAR(tangential_damping_ratio(13.5211e9, 62.9516e9), 0.92689, 1e-4);
}

TEST(DemTangential, EachFragmentCarriesMuAndMindlin) {
  const auto spec = kharaz_spec(0.092);
  const auto pairs = calibrate_pairs(spec);
  ASSERT_EQ(pairs.size(), 1u);
  const double kt = mindlin_coefficient(pairs[0].shear_modulus);
  const std::string lammps = write_lammps(spec, pairs);
  EXPECT_NE(lammps.find(fmt::format("tangential mindlin_rescale {:.10g} ", kt)), std::string::npos);
  EXPECT_NE(lammps.find(" 0.092 damping velocity region corlab_wall1"), std::string::npos);
  const std::string liggghts = write_liggghts(spec, pairs);
  EXPECT_NE(liggghts.find("pair_style gran model hertz tangential history\n"), std::string::npos);
  EXPECT_NE(liggghts.find("wall/gran model hertz tangential history primitive"), std::string::npos);
  // atom types 1 (alumina) and 2 (the wall): the wall-wall entry is never used
  EXPECT_NE(liggghts.find("coefficientFriction peratomtypepair 2 0.092 0.092 0.092 0\n"),
            std::string::npos);
  const std::string yade = write_yade(spec, pairs);
  EXPECT_NE(yade.find(fmt::format("frictionAngle={:.17g},", std::atan(0.092))), std::string::npos);
  const auto json = nlohmann::json::parse(write_json(spec, pairs));
  EXPECT_DOUBLE_EQ(json["pairs"][0]["friction"].get<double>(), 0.092);
  EXPECT_DOUBLE_EQ(json["pairs"][0]["mindlin_kt_per_contact_radius_Pa"].get<double>(), kt);
}

TEST(DemTangential, FrictionlessByDefaultAndBadMuRefused) {
  const auto spec = kharaz_spec(0.0);
  const auto pairs = calibrate_pairs(spec);
  EXPECT_NE(write_lammps(spec, pairs).find("tangential linear_nohistory 0.0 0.0"),
            std::string::npos);
  EXPECT_NE(write_liggghts(spec, pairs).find("tangential no_history"), std::string::npos);
  EXPECT_NE(write_yade(spec, pairs).find("frictionAngle=0,"), std::string::npos);
  EXPECT_THROW(calibrate_pairs(kharaz_spec(-0.1)), InputError);
  EXPECT_THROW(calibrate_pairs(kharaz_spec(std::numeric_limits<double>::quiet_NaN())), InputError);
}

}  // namespace
}  // namespace corlab::dem
