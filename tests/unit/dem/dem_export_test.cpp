// Calibration of type pairs and the text exports (LAMMPS, LIGGGHTS, YADE, CSV, JSON).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dem/dem_export.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "corlab/core/error.hpp"
#include "corlab/core/units.hpp"
#include "corlab/dem/calibration.hpp"
#include "corlab/dem/lammps_mapping.hpp"
#include "corlab/dem/time_step.hpp"
#include "corlab/materials/material_database.hpp"
#include "corlab/restitution/corlab2026p.hpp"
#include "corlab/restitution/registry.hpp"

namespace corlab::dem {
namespace {

const Material& material(const char* name) { return MaterialDatabase::builtin().get(name); }

ExportSpec constant_spec() {
  ExportSpec spec;
  spec.types = {{material("steel_ma2023"), 0.005, ""}, {material("alumina_ma2023"), 0.003, ""}};
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
  EXPECT_NE(lammps.find("fix corlab_wall1_t2 corlab_type2 wall/gran/region granular"),
            std::string::npos);
  // Issue 41: the cutoff is the farthest contact, 2 r_max [m] (here two 5 mm spheres), and a
  // guard stops a run whose atoms of a walled type are outside that type's group.
  EXPECT_NE(lammps.find("pair_style granular 0.01\n"), std::string::npos);
  EXPECT_NE(lammps.find("variable corlab_orphan atom (type==1)*(1-gmask(corlab_type1))+"
                        "(type==2)*(1-gmask(corlab_type2))\n"),
            std::string::npos);
  EXPECT_NE(lammps.find("fix corlab_guard all halt 100 v_corlab_orphans > 0.5 error hard"),
            std::string::npos);
  // 1-2: R* = R1 R2/(R1 + R2), kn = 4/3 E*
  EXPECT_NEAR(pairs[1].effective_radius, 0.005 * 0.003 / 0.008, 1e-15);
  const std::string liggghts = write_liggghts(spec, pairs);
  EXPECT_NE(liggghts.find("coefficientRestitution peratomtypepair 3"), std::string::npos);
  EXPECT_NE(write_yade(spec, pairs).find("(corlab_mat1, corlab_mat2, 0.6)"), std::string::npos);
  // Labels: the material names; each fragment sets the step it states.
  EXPECT_EQ(pairs[1].name(), "1-2 (steel_ma2023-alumina_ma2023)");
  EXPECT_NE(lammps.find(fmt::format("timestep {:.4g}\n", lammps_time_step(pairs, true))),
            std::string::npos);
  EXPECT_NE(liggghts.find(fmt::format("timestep {:.4g}\n", liggghts_time_step(pairs))),
            std::string::npos);
  EXPECT_NE(write_yade(spec, pairs).find(fmt::format("O.dt = {:.4g}\n", yade_time_step(pairs))),
            std::string::npos);
  // The step is the shortest contact time at v_max over the measured steps per contact.
  double shortest = 1.0;
  for (const auto& p : pairs) shortest = std::min(shortest, p.contact_time_fast);
  EXPECT_DOUBLE_EQ(lammps_time_step(pairs, true),
                   shortest / step_rule(CodeLaw::lammps_tsuji).steps_per_contact);
  EXPECT_GT(pairs[0].contact_time_slow, pairs[0].contact_time_fast);
}

TEST(DemExport, ModelCurveFitsAndJson) {
  ExportSpec spec;
  spec.types = {{material("alumina_ma2023"), 0.005, ""}};
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
  // A wall pair is the model itself: the sphere's own density (rho* = rho against the wall).
  const auto model = restitution::make_model("thornton1997", material("alumina_ma2023"),
                                             material("aluminium_ma2023"));
  for (const double v : {0.5, 2.0, 5.0}) EXPECT_DOUBLE_EQ(pairs[0].curve(v), model.cor(v));
  EXPECT_LT(pairs[0].liggghts->max_abs_error, 0.02);
  EXPECT_GT(pairs[0].viscoelastic->max_abs_error, pairs[0].liggghts->max_abs_error);
  const auto json = nlohmann::json::parse(write_json(spec, pairs, 8));
  EXPECT_EQ(json["pairs"][0]["pair"], "1-wall");
  EXPECT_EQ(json["pairs"][0]["label"], "alumina_ma2023-aluminium_ma2023");
  EXPECT_EQ(json["pairs"][0]["table"].size(), 8u);
  EXPECT_NEAR(json["pairs"][0]["liggghts_yield_ratio"].get<double>(),
              pairs[0].liggghts_yield_ratio(), 1e-12);
  // --wall-only still defines the particle pairs (elastic), so many particles see each other.
  const std::string lammps = write_lammps(spec, pairs);
  EXPECT_NE(lammps.find("\npair_style granular 0.01\n"), std::string::npos);  // 2 r_max [m]
  EXPECT_NE(lammps.find("pair_coeff 1 1 hertz"), std::string::npos);
  // e(v): the python/invoke hook in lammps.in, none in the fallback.
  EXPECT_NE(lammps.find("fix corlab_ev all python/invoke 1 post_force corlab_ev_force"),
            std::string::npos);
  EXPECT_EQ(write_lammps(spec, pairs, false).find("python/invoke 1"), std::string::npos);
  EXPECT_LT(lammps_delivery(spec, pairs[0], true).max_abs_error, 1e-3);
  EXPECT_EQ(lammps_delivery(spec, pairs[0], false).max_abs_error,
            std::min(pairs[0].viscoelastic->max_abs_error, pairs[0].best_constant->max_abs_error));
  // YADE's hook takes each contact's normal approach speed and sets that contact's damping, every
  // corlab_every steps; YADE's own en -> betan (Thornton et al. 2013) on the material pairs.
  const std::string yade = write_yade(spec, pairs);
  EXPECT_NE(yade.find("(b1.state.vel - b2.state.vel).dot(i.geom.normal)"), std::string::npos);
  EXPECT_NE(yade.find("p.betan = p.betas = corlab_beta("), std::string::npos);
  EXPECT_NE(yade.find("Ip2_FrictMat_FrictMat_MindlinPhys(betan=MatchMaker("), std::string::npos);
  EXPECT_NE(yade.find("neverErase=True"), std::string::npos);
  EXPECT_NE(yade.find("PyRunner(command='corlab_visit()', iterPeriod=corlab_every, initRun=True)"),
            std::string::npos);
  // A constant-e export keeps en and no hook.
  ExportSpec plain = spec;
  plain.model.clear();
  plain.restitution = 0.5;
  const std::string constant = write_yade(plain, calibrate_pairs(plain));
  EXPECT_NE(constant.find("(en=MatchMaker(matches=corlab_en)"), std::string::npos);
  EXPECT_EQ(constant.find("corlab_hook"), std::string::npos);
  EXPECT_EQ(constant.find("neverErase"), std::string::npos);
}

// corlab_every: the steps in which 2 v_max closes the margin 0.1 r_min, at most half the shortest
// contact time (so no contact starts and ends between two visits).
TEST(DemExport, YadeHookVisitsBeforeAContactCanCloseTheMargin) {
  ExportSpec spec;
  spec.types = {{material("alumina_ma2023"), 0.005, ""}};
  spec.wall = material("aluminium_ma2023");
  spec.model = "thornton1997";
  spec.v_min = 0.3;
  spec.v_max = 3.0;
  spec.wall_only = true;
  const auto pairs = calibrate_pairs(spec);
  const double dt = yade_time_step(pairs);
  const double every = std::min(std::floor(0.1 * 0.005 / (2 * 3.0 * dt)),
                                std::floor(0.5 * pairs[0].contact_time_fast / dt));
  EXPECT_GE(every, 1.0);
  const std::string yade = write_yade(spec, pairs);
  EXPECT_NE(yade.find(fmt::format("\ncorlab_every = {:.0f}\n", every)), std::string::npos);
  EXPECT_NE(yade.find(fmt::format("\ncorlab_margin = {:.17g}\n", 0.1 * 0.005)), std::string::npos);
}

// A model is written for a sphere of density rho on a flat; two identical spheres (R* = R/2,
// m* = m/2) are a sphere of density rho* = 3 m*/(4 pi R*^3) = 4 rho on it, so every model (all
// depend on the density only through rho v^2) gives the pair at v what one sphere of density rho
// gives at 2 v: the pair first yields at half the wall's approach speed.
TEST(DemExport, ParticlePairsTakeTheModelAtTheEffectiveDensity) {
  const Material& aluminium = material("aluminium_ma2023");
  for (const char* name : {"thornton1997", "corlab2026"}) {
    ExportSpec spec;
    spec.types = {{aluminium, 0.005, ""}};
    spec.model = name;
    spec.v_min = 0.3;
    spec.v_max = 3.0;
    const auto pairs = calibrate_pairs(spec);
    ASSERT_EQ(pairs.size(), 1u);
    EXPECT_DOUBLE_EQ(pairs[0].effective_density, 4.0 * aluminium.density);
    Material dense = aluminium;
    dense.density = 4.0 * aluminium.density;
    const auto at_rho_star = restitution::make_model(name, dense, aluminium);
    const auto one_sphere = restitution::make_model(name, aluminium, aluminium);
    for (const double v : {0.3, 1.0, 3.0}) {
      EXPECT_DOUBLE_EQ(pairs[0].curve(v), at_rho_star.cor(v)) << name << " v=" << v;
      EXPECT_NEAR(pairs[0].curve(v), one_sphere.cor(2.0 * v), 1e-12) << name << " v=" << v;
      EXPECT_LT(pairs[0].curve(v), one_sphere.cor(v)) << name << " v=" << v;
    }
    EXPECT_NE(pairs[0].target.find("rho* = 10800 kg/m^3"), std::string::npos) << pairs[0].target;
  }
}

// A 2 mm alumina type and a 5 mm aluminium type (aluminium first if asked) against `wall`, their
// e(v) from `model` over 0.3-3 m/s; the elastic alumina pair is given e = 1.
ExportSpec alumina_and_aluminium(const std::string& model,
                                 const Material& wall,
                                 bool aluminium_first) {
  const ParticleType alumina{material("alumina_ma2023"), 0.002, ""};
  const ParticleType aluminium{material("aluminium_ma2023"), 0.005, ""};
  ExportSpec spec;
  spec.types = aluminium_first ? std::vector{aluminium, alumina} : std::vector{alumina, aluminium};
  spec.wall = wall;
  spec.model = model;
  spec.pair_restitution = {parse_pair_restitution(aluminium_first ? "2/2=1" : "1/1=1")};
  spec.v_min = 0.3;
  spec.v_max = 3.0;
  return spec;
}

// Unequal spheres: the JSON's R* and m* are the pair's, and the model sees rho* = 3 m*/(4 pi R*^3);
// a wall pair keeps the particle's own density, also when the particle is the body that yields.
TEST(DemExport, UnequalPairsAndWallPairsDensities) {
  const Material& aluminium = material("aluminium_ma2023");
  const Material& alumina = material("alumina_ma2023");
  ExportSpec spec = alumina_and_aluminium("thornton1997", alumina, false);
  spec.pair_restitution.push_back(parse_pair_restitution("1/wall=1"));
  const auto pairs = calibrate_pairs(spec);
  ASSERT_EQ(pairs.size(), 5u);  // 1-1, 1-2, 2-2, 1-wall, 2-wall
  const double m1 = 4.0 / 3.0 * units::kPi * std::pow(0.002, 3) * alumina.density;
  const double m2 = 4.0 / 3.0 * units::kPi * std::pow(0.005, 3) * aluminium.density;
  const double r_star = 0.002 * 0.005 / 0.007;
  const double m_star = m1 * m2 / (m1 + m2);
  const auto json = nlohmann::json::parse(write_json(spec, pairs, 8));
  EXPECT_EQ(json["pairs"][1]["pair"], "1-2");
  EXPECT_NEAR(json["pairs"][1]["effective_radius_m"].get<double>(), r_star, 1e-15);
  EXPECT_NEAR(json["pairs"][1]["effective_mass_kg"].get<double>() / m_star, 1.0, 1e-12);
  const double rho_star = 3.0 * m_star / (4.0 * units::kPi * std::pow(r_star, 3));
  EXPECT_NEAR(pairs[1].effective_density / rho_star, 1.0, 1e-12);
  Material sphere = alumina;  // aluminium yields: the flat
  sphere.density = rho_star;
  const auto model = restitution::make_model("thornton1997", sphere, aluminium);
  for (const double v : {0.3, 3.0}) EXPECT_NEAR(pairs[1].curve(v), model.cor(v), 1e-12);
  // 2-wall: the yielding aluminium particle on the elastic alumina wall is the model's flat; its
  // sphere (the wall's material) takes the particle's density (m* = m2, R* = R2).
  EXPECT_EQ(pairs[4].label, "aluminium_ma2023-alumina_ma2023");
  EXPECT_DOUBLE_EQ(pairs[4].effective_density, aluminium.density);
  Material wall_as_sphere = alumina;
  wall_as_sphere.density = aluminium.density;
  const auto swapped = restitution::make_model("thornton1997", wall_as_sphere, aluminium);
  EXPECT_DOUBLE_EQ(pairs[4].curve(1.0), swapped.cor(1.0));
}

// corlab2026p reads the pair whole: both densities and R1/R2 of the model's sphere over its flat
// (the yielding body); against the wall, a flat (R1/R2 = 0).
TEST(DemExport, Corlab2026pTakesThePairsRadiusRatio) {
  const Material& aluminium = material("aluminium_ma2023");
  const Material& alumina = material("alumina_ma2023");
  const auto unequal = restitution::corlab2026p(alumina, aluminium, 0.4);
  const auto equal = restitution::corlab2026p(aluminium, aluminium, 1.0);
  const auto on_wall = restitution::corlab2026p(aluminium, aluminium, 0.0);
  // Types in either order: the yielding aluminium is the model's flat, the alumina its sphere.
  for (const bool aluminium_first : {false, true}) {
    const auto pairs =
        calibrate_pairs(alumina_and_aluminium("corlab2026p", aluminium, aluminium_first));
    ASSERT_EQ(pairs.size(), 5u);  // 1-1, 1-2, 2-2, 1-wall, 2-wall
    const std::size_t al_al = aluminium_first ? 0 : 2;
    const std::size_t al_wall = aluminium_first ? 3 : 4;
    for (const double v : {0.3, 3.0}) {
      EXPECT_DOUBLE_EQ(pairs[1].curve(v), unequal.cor(v)) << v << " " << aluminium_first;
      EXPECT_DOUBLE_EQ(pairs[al_al].curve(v), equal.cor(v)) << v << " " << aluminium_first;
      EXPECT_DOUBLE_EQ(pairs[al_wall].curve(v), on_wall.cor(v)) << v << " " << aluminium_first;
    }
  }
}

// --pair-table: one pair's own e(v) (an FE run of those two spheres); the other pairs keep the
// export's target, and the 1-2 pair's hooks carry the table, not the 1-1 or 2-2 e(v).
TEST(DemExport, PairTableReplacesOnePairsTarget) {
  const auto glass = parse_labelled_material("glass=E=63e9,nu=0.22,rho=2500", "type");
  const auto copper = parse_labelled_material("copper=E=120e9,nu=0.34,rho=8900,sy=200e6", "type");
  ExportSpec spec;
  spec.types = {{glass.material, 0.002, glass.label}, {copper.material, 0.005, copper.label}};
  spec.model = "corlab2026";
  spec.v_min = 0.5;
  spec.v_max = 4.0;
  spec.pair_restitution = {parse_pair_restitution("glass/glass=1")};
  PairTable table = parse_pair_table("copper/glass=fe pair.csv");
  EXPECT_EQ(table.first, "copper");
  EXPECT_EQ(table.second, "glass");
  EXPECT_EQ(table.source, "fe pair.csv");
  table.curve = tabulated_curve({0.5, 4.0}, {0.9, 0.6});
  spec.pair_tables = {table};
  const auto pairs = calibrate_pairs(spec);
  ASSERT_EQ(pairs.size(), 3u);  // 1-1, 1-2, 2-2
  EXPECT_EQ(pairs[1].target, "table fe pair.csv (--pair-table)");
  EXPECT_DOUBLE_EQ(pairs[1].curve(2.25), 0.75);
  EXPECT_NE(pairs[2].target.find("corlab2026 (copper on copper"), std::string::npos);
  const std::string yade = write_yade(spec, pairs);
  const auto row = yade.find("(1, 2): ([0.5, ");
  ASSERT_NE(row, std::string::npos);
  EXPECT_NE(yade.find("], [0.9, ", row), std::string::npos);
  EXPECT_LT(yade.find("], [0.9, ", row), yade.find("(2, 2):", row));
  // No export-wide target: fine while every pair has its own, else the uncovered pair is named.
  spec.model.clear();
  spec.pair_restitution.push_back(parse_pair_restitution("copper/copper=0.7"));
  EXPECT_EQ(calibrate_pairs(spec).size(), 3u);
  spec.pair_restitution.pop_back();
  try {
    calibrate_pairs(spec);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "target of pair 2-2 (copper-copper)") << e.what();
  }
  // A pair given a table and a constant, or two tables, is refused; so is a bad spec.
  spec.model = "corlab2026";
  spec.pair_restitution.push_back(parse_pair_restitution("1/2=0.5"));
  EXPECT_THROW(calibrate_pairs(spec), InputError);
  spec.pair_restitution.pop_back();
  spec.pair_tables.push_back(table);
  EXPECT_THROW(calibrate_pairs(spec), InputError);
  for (const char* bad : {"glass=fe.csv", "glass/copper", "glass/copper=", "/copper=fe.csv"}) {
    try {
      parse_pair_table(bad);
      FAIL() << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), "pair-table") << bad;
      EXPECT_EQ(std::string(e.what()).rfind("invalid pair-table = ", 0), 0u) << e.what();
    }
  }
}

TEST(DemExport, LabelsAndAnElasticPairByOverride) {
  const auto glass = parse_labelled_material("glass=E=63e9,nu=0.22,rho=2500", "type");
  EXPECT_EQ(glass.label, "glass");
  EXPECT_DOUBLE_EQ(glass.material.youngs_modulus, 63e9);
  EXPECT_EQ(parse_labelled_material("E=63e9,nu=0.22,rho=2500", "type").label, "");
  EXPECT_EQ(parse_labelled_material("steel_ma2023", "type").label, "steel_ma2023");
  ExportSpec spec;
  spec.types = {{glass.material, 0.002, glass.label}};
  spec.wall = parse_labelled_material("copper=E=120e9,nu=0.34,rho=8900,sy=200e6", "wall").material;
  spec.wall_label = "copper";
  spec.model = "corlab2026";
  spec.v_min = 0.5;
  spec.v_max = 4.0;
  try {  // glass-glass: no yield stress, no model e(v): the pair and the ways out, one line
    calibrate_pairs(spec);
    FAIL();
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("pair 1-1 (glass-glass)"), std::string::npos) << what;
    EXPECT_NE(what.find("--pair glass/glass=E"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos);
  }
  spec.pair_restitution = {parse_pair_restitution("glass/glass=1")};
  const auto pairs = calibrate_pairs(spec);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0].constant.value_or(0.0), 1.0);
  EXPECT_EQ(pairs[1].label, "glass-copper");
  EXPECT_NE(pairs[1].target.find("corlab2026 (glass on copper)"), std::string::npos);
  EXPECT_NE(write_lammps(spec, pairs).find("pair_coeff 1 1 hertz 4.413619168e+10 0.0 "),
            std::string::npos);  // e = 1: no damping
  EXPECT_NE(write_yade(spec, pairs).find("label='glass'"), std::string::npos);
  EXPECT_THROW(parse_pair_restitution("glass/glass=1.5"), InputError);
  EXPECT_THROW(parse_pair_restitution("glass=0.5"), InputError);
  spec.pair_restitution = {parse_pair_restitution("glass/lead=0.5")};
  EXPECT_THROW(calibrate_pairs(spec), InputError);
}

TEST(DemExport, YadeEnMappingAsMeasured) {
  EXPECT_EQ(yade_delivered_e(0.5), 0.5);
  EXPECT_EQ(yade_delivered_e(1.0), 1.0);
  EXPECT_NEAR(yade_delivered_e(0.99), 0.97895, 1e-12);
  EXPECT_NEAR(yade_delivered_e(0.985), 0.5 * (0.97237 + 0.97895), 1e-12);
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
    EXPECT_NE(std::string(e.what()).find("pair 2-2 (alumina_ma2023-alumina_ma2023)"),
              std::string::npos);
  }
}

}  // namespace
}  // namespace corlab::dem
