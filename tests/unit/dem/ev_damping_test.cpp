// The e(v) damping of the compiled LAMMPS fix (ev_damping.hpp): chi table, onset law, walls.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dem/ev_damping.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "corlab/core/error.hpp"
#include "corlab/dem/contact_ode.hpp"
#include "corlab/dem/hysteresis_chi.hpp"

namespace corlab::dem {
namespace {

TEST(DemEvDamping, ChiTableHoldsExactChiAtItsNodesAndIsLinearBetween) {
  const UniformTable chi = chi_table(1.0, 3.0, {0.9, 0.7, 0.5});
  EXPECT_DOUBLE_EQ(chi(1.0), exact_chi(0.9));
  EXPECT_DOUBLE_EQ(chi(2.0), exact_chi(0.7));
  EXPECT_DOUBLE_EQ(chi(2.5), 0.5 * (exact_chi(0.7) + exact_chi(0.5)));
  EXPECT_DOUBLE_EQ(chi(0.2), exact_chi(0.9));  // end values outside
  EXPECT_DOUBLE_EQ(chi(9.0), exact_chi(0.5));
  EXPECT_EQ(chi_table(1.0, 2.0, {1.2, 1.0})(1.5), 0.0);  // e >= 1: undamped
  EXPECT_THROW(chi_table(2.0, 1.0, {0.5, 0.5}), InputError);
  EXPECT_THROW(chi_table(1.0, 2.0, {0.5}), InputError);
  EXPECT_THROW(chi_table(1.0, 2.0, {0.5, 0.0}), InputError);
}

TEST(DemEvDamping, OnsetLawDampsHertzToTheTableE) {
  // Elastic Hertz plus the damping, integrated as one contact: e of the table at v_in.
  const double estar = 1e9;
  const double radius = 1e-3;
  const double mass = 1e-5;
  const UniformTable chi = chi_table(0.5, 2.0, {0.8, 0.6});
  for (const double v : {0.5, 1.25, 2.0}) {
    const HysteresisLaw law = onset_law(chi, v, estar, radius);
    EXPECT_DOUBLE_EQ(law.stiffness, hertz_stiffness(estar, radius));
    EXPECT_DOUBLE_EQ(law.impact_velocity, v);
    const double e = simulate_impact(
                         [&law](double d, double rate, const ContactHistory&) {
                           return HertzLaw{law.stiffness}.force(d) + law.damping(d, rate);
                         },
                         mass, v)
                         .restitution;
    EXPECT_NEAR(e, exact_restitution(chi(v)), 1e-6) << "v = " << v;
  }
  // A contact that begins separating is undamped.
  EXPECT_EQ(onset_law(chi, -0.1, estar, radius).damping(1e-6, -0.1), 0.0);
  EXPECT_EQ(onset_law(chi, 0.0, estar, radius).damping(1e-6, 1.0), 0.0);
}

TEST(DemEvDamping, DampingIsTheDampedPartOfTheHysteresisLaw) {
  const HysteresisLaw law{.stiffness = 2e8, .chi = 0.4, .impact_velocity = 1.5};
  for (const double rate : {-1.0, 0.3, 1.5}) {
    const double d = 2e-6;
    EXPECT_NEAR(law.damping(d, rate), law.force(d, rate) - law.force(d, 0.0),
                1e-12 * law.force(d, 0.0));
  }
  EXPECT_EQ(law.damping(0.0, 1.0), 0.0);
  EXPECT_EQ(law.damping(-1e-6, 1.0), 0.0);
}

TEST(DemEvDamping, WallContactOfAPlaneAndACylinder) {
  Wall plane;
  plane.point = {0.0, 0.0, 1.0};
  plane.normal = {0.0, 0.6, 0.8};
  const auto hit = wall_contact(plane, {0.0, 0.0, 1.0 + 0.8 * 0.009}, 0.01);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->overlap, 0.01 - 0.8 * 0.8 * 0.009, 1e-15);
  EXPECT_EQ(hit->normal, plane.normal);
  EXPECT_FALSE(wall_contact(plane, {0.0, 0.0, 1.02}, 0.01).has_value());

  Wall cylinder;
  cylinder.shape = WallShape::cylinder;
  cylinder.axis = 0;  // along x, centre (y, z) = (1, 2)
  cylinder.centre = {1.0, 2.0};
  cylinder.radius = 0.1;
  cylinder.lo = -1.0;
  cylinder.hi = 1.0;
  const auto in = wall_contact(cylinder, {0.5, 1.0, 2.095}, 0.01);
  ASSERT_TRUE(in.has_value());
  EXPECT_NEAR(in->overlap, 0.005, 1e-12);
  EXPECT_NEAR(in->normal[2], -1.0, 1e-15);  // from the wall back to the axis
  EXPECT_EQ(in->normal[0], 0.0);
  EXPECT_FALSE(wall_contact(cylinder, {0.5, 1.0, 2.05}, 0.01).has_value());
  EXPECT_FALSE(wall_contact(cylinder, {1.5, 1.0, 2.095}, 0.01).has_value());  // past HI
}

}  // namespace
}  // namespace corlab::dem
