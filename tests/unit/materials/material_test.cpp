// Materials (material.hpp): derived moduli, pair quantities, validation and its bad-input
// messages. The database, the spec parser and the data directory: material_database_test.cpp.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/materials/material.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "corlab/core/error.hpp"
#include "support/input_errors.hpp"

namespace corlab {
namespace {

using test::expect_input_error;

Material steel() {
  return Material{.name = "s",
                  .youngs_modulus = 210e9,
                  .poisson_ratio = 0.3,
                  .density = 7850.0,
                  .yield_stress = 500e6,
                  .hardening_modulus = 0.0,
                  .source = ""};
}

TEST(Material, DerivedModuli) {
  const Material m = steel();
  EXPECT_NEAR(m.shear_modulus(), 210e9 / 2.6, 1.0);
  EXPECT_NEAR(m.bulk_modulus(), 210e9 / 1.2, 1.0);
  // lambda + 2G
  const double lambda = 210e9 * 0.3 / (1.3 * 0.4);
  EXPECT_NEAR(m.p_wave_modulus(), lambda + 2.0 * m.shear_modulus(), 1.0);
  EXPECT_NEAR(m.dilatational_wave_speed(), std::sqrt(m.p_wave_modulus() / 7850.0), 1e-9);
}

TEST(Material, EffectiveModulusAndGroups) {
  // Ma Table 1 baseline: both 210 GPa / 0.3 -> E* = 115.385 GPa
  EXPECT_NEAR(effective_modulus(steel(), steel()), 115.385e9, 1e6);
  EXPECT_NEAR(effective_modulus(370e9, 0.22, 68e9, 0.33), 63.7905e9, 1e5);
  EXPECT_NEAR(effective_modulus(370e9, 0.22, 200e9, 0.29), 139.8329e9, 1e5);
  EXPECT_DOUBLE_EQ(k1(100e9, 4000.0, 2.0), 100e9 / 16000.0);
  EXPECT_DOUBLE_EQ(k2(500e6, 100e9), 0.005);
}

// rho* = 3 m*/(4 pi R*^3) from the masses and radii themselves: 4 rho for two identical spheres,
// the sphere's own density on a flat (bit for bit), and an unequal pair.
TEST(Material, PairReducedSphereHasTheDensityOfThePairsHertzImpact) {
  const Material sphere = steel();
  Material other = steel();
  other.density = 2700.0;
  EXPECT_EQ(pair_reduced_sphere(sphere, other, 0.0).density, sphere.density);
  EXPECT_DOUBLE_EQ(pair_reduced_sphere(sphere, sphere, 1.0).density, 4.0 * sphere.density);
  const double r1 = 0.002;
  const double r2 = 0.005;
  const double m1 = sphere.density * r1 * r1 * r1;  // the 4 pi / 3 cancels
  const double m2 = other.density * r2 * r2 * r2;
  const double r_star = r1 * r2 / (r1 + r2);
  const double rho_star = m1 * m2 / (m1 + m2) / (r_star * r_star * r_star);
  const Material reduced = pair_reduced_sphere(sphere, other, r1 / r2);
  EXPECT_NEAR(reduced.density / rho_star, 1.0, 1e-14);
  EXPECT_EQ(reduced.youngs_modulus, sphere.youngs_modulus);
  expect_input_error([&] { (void)pair_reduced_sphere(sphere, other, -0.5); },
                     "invalid radius_ratio = -0.5: must be >= 0 and finite (R1/R2, 0 for a flat) "
                     "[-]");
  EXPECT_THROW((void)pair_reduced_sphere(sphere, other, std::nan("")), InputError);
}

TEST(Material, ValidateAcceptsGoodMaterials) {
  EXPECT_NO_THROW(validate(steel(), "m", true));
  Material elastic = steel();
  elastic.yield_stress.reset();
  EXPECT_NO_THROW(validate(elastic, "m"));
}

TEST(Material, ValidateMessages) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Material m = steel();
  m.youngs_modulus = -2e11;
  expect_input_error([&] { validate(m, "sphere"); },
                     "invalid sphere.E = -200000000000: must be > 0 [Pa]");
  m = steel();
  m.youngs_modulus = nan;
  expect_input_error([&] { validate(m, "sphere"); }, "invalid sphere.E = nan: must be > 0 [Pa]");
  m = steel();
  m.poisson_ratio = 0.5;
  expect_input_error([&] { validate(m, "x"); }, "invalid x.nu = 0.5: must be in (-1, 0.5)");
  m.poisson_ratio = -1.0;
  expect_input_error([&] { validate(m, "x"); }, "invalid x.nu = -1: must be in (-1, 0.5)");
  m = steel();
  m.density = 0.0;
  expect_input_error([&] { validate(m, "x"); }, "invalid x.rho = 0: must be > 0 [kg/m^3]");
  m = steel();
  m.yield_stress = 0.0;
  expect_input_error([&] { validate(m, "x"); },
                     "invalid x.sigma_y = 0: must be in (0, 0.1 E) [Pa] (a yield strain above "
                     "10 % is no metal)");
  m.yield_stress = 3e11;
  expect_input_error([&] { validate(m, "x"); },
                     "invalid x.sigma_y = 300000000000: must be in (0, 0.1 E) [Pa] (a yield strain "
                     "above 10 % is no metal)");
  m.yield_stress = 0.2 * m.youngs_modulus;  // a plausible unit slip: GPa-scale yield
  EXPECT_THROW(validate(m, "x"), InputError);
  m = steel();
  m.yield_stress.reset();
  expect_input_error([&] { validate(m, "substrate", true); },
                     "invalid substrate.sigma_y = 'missing': must be given for an "
                     "elastic-plastic substrate [Pa]");
  m = steel();
  m.hardening_modulus = -1.0;
  expect_input_error([&] { validate(m, "x"); }, "invalid x.H = -1: must be >= 0 [Pa]");
}

}  // namespace
}  // namespace corlab
