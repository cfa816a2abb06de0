// Issue 41: several walls (planes at any position and orientation, cylinders), each with its own
// material, per-pair friction and rolling resistance, in every fragment; bad input in one line.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dem/dem_walls.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "corlab/dem/dem_export.hpp"
#include "support/input_errors.hpp"

namespace corlab::dem {
namespace {

using test::input_error_message;

ExportSpec soft_spec() {
  ExportSpec spec;
  spec.types.push_back(
      {parse_labelled_material("a=E=5e6,nu=0.3,rho=1000", "type").material, 0.004, "a"});
  spec.types.push_back(
      {parse_labelled_material("b=E=1e7,nu=0.3,rho=2000", "type").material, 0.005, "b"});
  spec.restitution = 0.5;
  spec.v_max = 2.0;
  return spec;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(DemWalls, ParsesPlanesAndCylinders) {
  const Wall floor = parse_wall_shape("floor");
  EXPECT_EQ(floor.shape, WallShape::plane);
  EXPECT_EQ(plane_axis(floor), 2);
  const Wall side = parse_wall_shape("plane:0.04,0,0,-2,0,0");
  EXPECT_DOUBLE_EQ(side.normal[0], -1.0);  // normalised
  EXPECT_EQ(plane_axis(side), 0);
  const Wall oblique = parse_wall_shape("plane:0,0,0.1,1,0,1,0.05");
  EXPECT_EQ(plane_axis(oblique), -1);
  EXPECT_NEAR(oblique.normal[0], std::sqrt(0.5), 1e-15);
  EXPECT_DOUBLE_EQ(oblique.half_width, 0.05);
  const Wall cyl = parse_wall_shape("cylinder:y,0.1,0.2,0.05,-1,1");
  EXPECT_EQ(cyl.shape, WallShape::cylinder);
  EXPECT_EQ(cyl.axis, 1);
  EXPECT_DOUBLE_EQ(cyl.centre[1], 0.2);
  EXPECT_DOUBLE_EQ(cyl.hi, 1.0);
}

TEST(DemWalls, ObliqueSquareHasTheNormalAndHalfWidth) {
  const Wall w = parse_wall_shape("plane:0,0,0.1,1,0,1,0.05");
  const auto c = plane_square(w);
  for (const auto& p : c) {  // every corner on the plane, at distance sqrt(2) h from its point
    double along = 0.0;
    double dist = 0.0;
    for (std::size_t a = 0; a < 3; ++a) {
      along += (p[a] - w.point[a]) * w.normal[a];
      dist += (p[a] - w.point[a]) * (p[a] - w.point[a]);
    }
    EXPECT_NEAR(along, 0.0, 1e-15);
    EXPECT_NEAR(std::sqrt(dist), std::sqrt(2.0) * 0.05, 1e-15);
  }
  // the right-hand rule gives the normal: (c1 - c0) x (c2 - c0) along n
  std::array<double, 3> u{};
  std::array<double, 3> v{};
  for (std::size_t a = 0; a < 3; ++a) {
    u[a] = c[1][a] - c[0][a];
    v[a] = c[2][a] - c[0][a];
  }
  const double nx = u[1] * v[2] - u[2] * v[1];
  const double nz = u[0] * v[1] - u[1] * v[0];
  EXPECT_GT(nx * w.normal[0] + nz * w.normal[2], 0.0);
  EXPECT_EQ(count(wall_stl(w), "vertex"), 6U);
}

TEST(DemWalls, BadShapesAreOneLineErrors) {
  EXPECT_EQ(input_error_message([] { parse_wall_shape("plane:0,0,0,0,0,0"); }),
            "invalid wall shape = 'plane:0,0,0,0,0,0': must be a plane normal that is not zero");
  EXPECT_NE(input_error_message([] {
              parse_wall_shape("plane:0,0,0,1,0,1");
            }).find("a half-width HALF [m] for an oblique plane"),
            std::string::npos);
  EXPECT_NE(input_error_message([] { parse_wall_shape("cylinder:w,0,0,1,0,1"); }).find("x|y|z"),
            std::string::npos);
  EXPECT_NE(input_error_message([] {
              parse_wall_shape("cylinder:z,0,0,-1,0,1");
            }).find("a cylinder radius R > 0"),
            std::string::npos);
  EXPECT_NE(input_error_message([] { parse_wall_shape("cylinder:z,0,0,1,1,0"); }).find("HI > LO"),
            std::string::npos);
  EXPECT_NE(input_error_message([] { parse_wall_shape("sphere:1"); }).find("plane:"),
            std::string::npos);
  EXPECT_NE(input_error_message([] { parse_wall_shape("plane:0,0,nan,0,0,1"); }).find("wall shape"),
            std::string::npos);
  for (const auto* bad : {"plane:1,2", "cylinder:z,0,0,1", ""}) {
    EXPECT_NE(input_error_message([bad] { parse_wall_shape(bad); }), "") << bad;
  }
}

TEST(DemWalls, EachWallMaterialIsCalibratedAndWrittenInEveryCode) {
  ExportSpec spec = soft_spec();
  add_wall(spec, "floor_mat=E=2e7,nu=0.3,rho=2000");
  add_wall(spec, "side=E=3e7,nu=0.3,rho=2000@plane:0.04,0,0,-1,0,0");
  add_wall(spec, "floor_mat=E=2e7,nu=0.3,rho=2000@cylinder:z,0,0,0.05,0,0.3");
  add_wall(spec, "side=E=3e7,nu=0.3,rho=2000@plane:0,0,0.1,1,0,1,0.05");
  spec.friction = 0.3;
  spec.pair_friction.push_back(parse_pair_value("a/side=0.6", "friction"));
  spec.rolling = 0.1;
  ASSERT_EQ(spec.walls.size(), 4U);
  ASSERT_EQ(spec.extra_walls.size(), 1U);  // two wall materials, each named twice
  EXPECT_EQ(spec.walls[2].material, 0);
  EXPECT_EQ(spec.walls[3].material, 1);
  const auto pairs = calibrate_export(spec);
  ASSERT_EQ(pairs.size(), 7U);  // 3 particle pairs, 2 types x 2 wall materials
  int side_pairs = 0;
  for (const auto& p : pairs) {
    if (p.type_j != 0 || p.wall != 1) continue;
    ++side_pairs;
    EXPECT_EQ(p.label, p.type_i == 1 ? "a-side" : "b-side");
    EXPECT_DOUBLE_EQ(p.friction, p.type_i == 1 ? 0.6 : 0.3);
  }
  EXPECT_EQ(side_pairs, 2);
  const std::string lammps = write_lammps(spec, pairs);
  EXPECT_EQ(count(lammps, "wall/gran/region granular"), 8U);  // 4 walls x 2 types
  EXPECT_NE(lammps.find("region corlab_wall3 cylinder z 0 0 0.05 0 0.3 side in units box open 1 "
                        "open 2"),
            std::string::npos);
  EXPECT_EQ(count(lammps, " rolling sds "), 3U + 8U);
  EXPECT_NE(lammps.find("29Sep2021"), std::string::npos);
  EXPECT_EQ(lammps.find("7Jan2022"), std::string::npos);
  const std::string liggghts = write_liggghts(spec, pairs);
  EXPECT_NE(liggghts.find("primitive type 4 xplane 0.04"), std::string::npos);
  EXPECT_NE(liggghts.find("primitive type 3 zcylinder 0.05 0 0"), std::string::npos);
  EXPECT_NE(liggghts.find("mesh/surface file corlab_wall4.stl type 4"), std::string::npos);
  EXPECT_NE(liggghts.find("coefficientFriction peratomtypepair 4 0.3 0.3 0.3 0.6 "),
            std::string::npos);
  EXPECT_NE(liggghts.find("rolling_friction cdt"), std::string::npos);
  const std::string yade = write_yade(spec, pairs);
  EXPECT_NE(
      yade.find("utils.wall(0.040000000000000001, axis=0, sense=-1, material=corlab_wall_mat2)"),
      std::string::npos);
  EXPECT_NE(yade.find("geom.facetCylinder("), std::string::npos);
  EXPECT_EQ(count(yade, "utils.facet("), 2U);
  EXPECT_NE(yade.find("(corlab_mat1, corlab_wall_mat2, 0.54041950027058"), std::string::npos);
  EXPECT_NE(yade.find("includeMoment=True"), std::string::npos);
}

TEST(DemWalls, TheHookDampsEveryWall) {
  ExportSpec spec;
  spec.types.push_back(
      {parse_labelled_material("copper=E=120e9,nu=0.34,rho=8900,sy=200e6", "type").material, 0.002,
       "copper"});
  spec.model = "thornton1997";
  spec.v_min = 0.5;
  spec.v_max = 4.0;
  spec.wall_only = true;
  add_wall(spec, "steel=E=200e9,nu=0.3,rho=7800");
  add_wall(spec, "glass=E=63e9,nu=0.22,rho=2500@cylinder:x,0,0,0.05,0,1");
  const auto pairs = calibrate_export(spec);
  const std::string lammps = write_lammps(spec, pairs);
  EXPECT_NE(
      lammps.find("corlab_walls = [(\"plane\", (0, 0, 0), (0, 0, 1)), (\"cylinder\", 0, 0, 0, "
                  "0.050000000000000003, 0, 1)]"),
      std::string::npos);
  EXPECT_NE(lammps.find("corlab_wall_row = [np.array([-1, 0]), np.array([-1, 1])]"),
            std::string::npos);
  // LIGGGHTS's yield ratio is per atom type: with two wall materials it writes model hertz
  EXPECT_FALSE(liggghts_uses_thornton_ning(pairs));
  EXPECT_NE(write_liggghts(spec, pairs).find("pair_style gran model hertz"), std::string::npos);
}

TEST(DemWalls, WallsAndPairsAreRefusedInOneLine) {
  ExportSpec spec = soft_spec();
  add_wall(spec, "soft=E=2e7,nu=0.3,rho=2000");
  EXPECT_NE(input_error_message([&] {
              add_wall(spec, "soft=E=3e7,nu=0.3,rho=2000@floor");
            }).find("the material of wall soft as given before"),
            std::string::npos);
  add_wall(spec, "side=E=3e7,nu=0.3,rho=2000@plane:0.04,0,0,-1,0,0");
  ExportSpec named = spec;
  named.pair_restitution.push_back(parse_pair_restitution("a/wall=0.3"));
  EXPECT_NE(input_error_message([&] {
              calibrate_export(named);
            }).find("a wall named by its label (the export has several wall materials)"),
            std::string::npos);
  ExportSpec twice = spec;
  twice.pair_friction.push_back(parse_pair_value("a/side=0.6", "friction"));
  twice.pair_friction.push_back(parse_pair_value("side/1=0.2", "friction"));
  EXPECT_NE(input_error_message([&] { calibrate_export(twice); }).find("one mu per pair"),
            std::string::npos);
  EXPECT_EQ(input_error_message([] { parse_pair_value("a/b=-1", "friction"); }),
            "invalid friction a/b = -1: must be >= 0");
  EXPECT_NE(input_error_message([] { parse_pair_value("ab=1", "friction"); }).find("A/B=X"),
            std::string::npos);
  ExportSpec rolling = spec;
  rolling.rolling = -0.1;
  EXPECT_NE(input_error_message([&] { calibrate_export(rolling); }).find("rolling"),
            std::string::npos);
  // a per-wall --pair names the wall by its label and reaches that wall's pair only
  ExportSpec own = spec;
  own.pair_restitution.push_back(parse_pair_restitution("b/side=0.8"));
  for (const auto& p : calibrate_export(own)) {
    if (p.type_j == 0) {
      EXPECT_DOUBLE_EQ(*p.constant, p.type_i == 2 && p.wall == 1 ? 0.8 : 0.5);
    }
  }
}

}  // namespace
}  // namespace corlab::dem
