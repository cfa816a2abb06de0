// Mass scaling to a target step (solver.mass_scaling_*; docs/theory/solver.md section 12): off it
// leaves the model as it was; on it raises the elements below the contact's h-squares to them
// (the step floor) and each element's stable step to at least F x the floor, the whole factor at
// the contact, adds at most the allowed mass, keeps the contact's physical penalty, is refused
// where the added inertia would be felt, and keeps e.
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "corlab/fem/mesh/contact_estimate.hpp"
#include "corlab/fem/mesh/mesh_generator.hpp"
#include "corlab/fem/solver/simulate.hpp"
#include "fem/solver/impact_model.hpp"

namespace corlab::fem {
namespace {

using solver::ImpactModel;

// The small built-in case of subcycling_test.cpp at a low speed (the contact quasi-static).
ImpactConfig slow_config(double velocity, double max_factor) {
  ImpactConfig c;
  c.sphere.radius = 2.5e-3;
  c.substrate.radius = 5e-3;
  c.substrate.depth = 5e-3;
  c.impact.gap = 1e-6;
  c.impact.velocity = velocity;
  c.mesh.h_min = 0.05e-3;
  c.mesh.h_max = 0.5e-3;
  c.output.history_every = 20;
  c.solver.mass_scaling_max = max_factor;
  return c;
}

ImpactModel model_of(const ImpactConfig& c) {
  return solver::make_impact_model(c, build_impact_mesh(c));
}

using solver::physical_element_step;

TEST(MassScaling, OffLeavesMassesAndStepsPhysical) {
  const ImpactModel m = model_of(slow_config(0.1, 1.0));
  EXPECT_EQ(m.scaling.factor, 1.0);
  EXPECT_EQ(m.scaling.added_mass, 0.0);
  for (double s : m.elements.step_scale) ASSERT_EQ(s, 1.0);
  for (int i = 0; i < m.n_nodes; ++i)
    ASSERT_EQ(m.mass[i], m.scaling.physical_mass[i]) << "node " << i;
  double step_min = 1e300;
  for (int e = 0; e < m.n_elements; ++e) step_min = std::min(step_min, physical_element_step(m, e));
  EXPECT_DOUBLE_EQ(m.dt_critical, step_min);
}

TEST(MassScaling, RaisesEveryStepToTheTargetAndAddsLittleMass) {
  const ImpactModel off = model_of(slow_config(0.1, 1.0));
  const ImpactModel m = model_of(slow_config(0.1, 8.0));
  ASSERT_GE(m.scaling.factor, 2.0) << "a 0.1 m/s impact is quasi-static: scaling should apply";
  EXPECT_NEAR(m.dt_critical, m.scaling.factor * m.scaling.step_floor_scale * off.dt_critical,
              1e-12 * m.dt_critical);
  for (int e = 0; e < m.n_elements; ++e) {
    const double step = m.elements.step_scale[e] * physical_element_step(m, e);
    ASSERT_GE(step, m.dt_critical * (1.0 - 1e-12)) << "element " << e;
    // Scaled only as far as needed, except at the contact (the whole factor).
    ASSERT_TRUE(m.elements.step_scale[e] == 1.0 || m.elements.step_scale[e] == m.scaling.factor ||
                std::abs(step - m.dt_critical) < 1e-9 * m.dt_critical)
        << "element " << e;
  }
  EXPECT_GT(m.scaling.added_mass, 0.0);
  EXPECT_LE(m.scaling.added_mass, solver::kMaxAddedMassFraction * m.scaling.sphere_mass_physical);
  double total = 0.0, physical = 0.0;
  for (int i = 0; i < m.n_nodes; ++i) {
    total += m.mass[i];
    physical += m.scaling.physical_mass[i];
  }
  EXPECT_NEAR(total - physical, m.scaling.added_mass, 1e-9 * total);
}

TEST(MassScaling, TheContactKeepsItsPhysicalPenalty) {
  const ImpactConfig c = slow_config(0.1, 8.0);
  const ImpactModel off = model_of(slow_config(0.1, 1.0));
  const ImpactModel m = model_of(c);
  ASSERT_GE(m.scaling.factor, 2.0);
  ASSERT_EQ(m.slaves, off.slaves);
  const double r_contact = predicted_contact_radius(c);
  int checked = 0;
  for (std::size_t s = 0; s < m.slaves.size(); ++s) {
    if (m.r0[m.slaves[s]] > r_contact) continue;
    EXPECT_NEAR(m.penalty[s], off.penalty[s], 1e-9 * off.penalty[s]) << "slave " << s;
    // F^2, more where an element at the node was also below the step floor (the axis column).
    EXPECT_GE(m.mass[m.slaves[s]],
              m.scaling.factor * m.scaling.factor * off.mass[m.slaves[s]] * (1.0 - 1e-12));
    ++checked;
  }
  EXPECT_GT(checked, 5);
  // Away from the contact the penalty may only be softer (stability at the longer step).
  for (std::size_t s = 0; s < m.slaves.size(); ++s)
    EXPECT_LE(m.penalty[s], off.penalty[s] * 1.000001);
}

TEST(MassScaling, RefusedWhereTheAddedInertiaWouldBeFelt) {
  // At 5 m/s rho v^2 / sigma_y ~ 7e-4: scaling by 4 would add 5e-3 > 1e-4.
  EXPECT_EQ(model_of(slow_config(5.0, 8.0)).scaling.factor, 1.0);
  // And with the bound at zero, nowhere.
  ImpactConfig c = slow_config(0.1, 8.0);
  c.solver.mass_scaling_inertia = 0.0;
  EXPECT_EQ(model_of(c).scaling.factor, 1.0);
}

// The step floor at an impact too fast for F (the paper case, 5 m/s): only the elements whose
// stable step is below the contact's h-squares' are scaled, just up to the floor, which is at
// most that square's step; the contact keeps its physical penalty; the added mass is bounded.
TEST(StepFloor, RaisesOnlyTheElementsBelowTheContactSquares) {
  ImpactConfig c;
  ImpactConfig physical = c;
  physical.solver.mass_scaling_max = 1.0;
  const ImpactModel off = model_of(physical);
  const ImpactModel m = model_of(c);
  ASSERT_EQ(m.scaling.factor, 1.0);
  EXPECT_EQ(off.scaling.step_floor_scale, 1.0);
  // The axis squares (hoop term, h / sqrt(3)) and the sphere core's smallest elements (0.139 mm
  // against h / sqrt(2) = 0.177 mm: solver.md section 5) lie below the floor.
  EXPECT_GT(m.scaling.step_floor_scale, 1.2);
  const double h = c.mesh.h_min;
  const double square = m.substrate.stable_step_at_rest(h / std::sqrt(2.0));
  EXPECT_LE(m.dt_critical, square * (1.0 + 1e-9));
  EXPECT_NEAR(m.dt_critical, m.scaling.step_floor_scale * off.dt_critical, 1e-12 * m.dt_critical);
  // Scaled by more than 1 %: the axis column's squares (every one touching the contact) and the
  // sphere core's distorted elements next to the contact (measured: 131 of 2763). The zone's
  // own squares lie within round-off of the floor (scaled by < 1.001).
  int scaled = 0;
  int axis_contact_squares = 0;
  for (int e = 0; e < m.n_elements; ++e) {
    const double physical_step = physical_element_step(m, e);
    if (m.elements.step_scale[e] == 1.0) {
      ASSERT_GE(physical_step, m.dt_critical * (1.0 - 1e-12)) << "element " << e;
      continue;
    }
    ASSERT_LT(physical_step, m.dt_critical) << "element " << e;
    ASSERT_NEAR(m.elements.step_scale[e] * physical_step, m.dt_critical, 1e-12 * m.dt_critical);
    if (m.elements.step_scale[e] > 1.01) ++scaled;
    bool on_axis = false;
    bool at_contact = false;
    for (int n : m.elements.nodes(e)) {
      on_axis = on_axis || m.r0[n] == 0.0;
      at_contact = at_contact || n == m.masters[0] || n == m.slaves.front();
    }
    if (on_axis && at_contact && m.elements.step_scale[e] > 1.2) ++axis_contact_squares;
  }
  EXPECT_GT(scaled, 0);
  EXPECT_LT(scaled, m.n_elements / 10) << "a floor, not a scaling of the mesh";
  EXPECT_EQ(axis_contact_squares, 2) << "the axis squares at the contact, one per body";
  EXPECT_GT(m.scaling.added_mass, 0.0);
  EXPECT_LE(m.scaling.added_mass, solver::kMaxAddedMassFraction * m.scaling.sphere_mass_physical);
  EXPECT_EQ(m.scaling.dt_critical_physical, off.dt_critical);
  ASSERT_EQ(m.slaves, off.slaves);
  for (std::size_t s = 0; s < m.slaves.size(); ++s) {
    EXPECT_NEAR(m.penalty[s], off.penalty[s], 1e-9 * off.penalty[s]) << "slave " << s;
  }
}

// The floor leaves the contact penalty inside the stability budget: (1 + penalty_scale x
// ratio^2) safety_factor^2 <= 1, so a safety factor near its limit leaves almost no floor.
TEST(StepFloor, BoundedByThePenaltysShareOfTheStabilityBudget) {
  ImpactConfig c;
  c.solver.safety_factor = 0.88;  // limit 1 / sqrt(1.28) = 0.8839
  const ImpactModel m = model_of(c);
  const double bound = std::sqrt((1.0 / (0.88 * 0.88) - 1.0) / c.solver.penalty_scale);
  EXPECT_GT(m.scaling.step_floor_scale, 1.0);
  EXPECT_LE(m.scaling.step_floor_scale, bound * (1.0 + 1e-12));
  EXPECT_LT(m.scaling.step_floor_scale, 1.03);
}

// Where the elements below the contact squares are heavy (a 70 m/s crater: a wide zone of axis
// and core elements), the floor is lowered until the added mass is within the bound.
TEST(StepFloor, BoundedByTheAddedMass) {
  ImpactConfig c;
  c.impact.velocity = 70.0;
  const ImpactModel m = model_of(c);
  EXPECT_GT(m.scaling.step_floor_scale, 1.0);
  EXPECT_NEAR(m.scaling.added_mass, solver::kMaxAddedMassFraction * m.scaling.sphere_mass_physical,
              1e-6 * m.scaling.added_mass);
}

// What holds the factor back is the mesh's thin, heavy elements away from the contact. The
// yield-onset study's slowest probe (paper-size sphere, E = 116.1 GPa on both bodies, nu = 0.3,
// sigma_y = 100 MPa, 1.4 mm/s) scales by 4 with the generator's transitions, whose skin rows
// merge beyond the refined zone (at F = 4 the skin of the previous generator added 1.16e-3 of
// the sphere's mass, above kMaxAddedMassFraction; docs/theory/solver.md section 12); without
// any transitions it stays at 2.
TEST(MassScaling, TheSphereSkinTransitionsLetASlowImpactScaleByFour) {
  ImpactConfig c;  // the paper's sphere and substrate geometry
  c.impact.velocity = 1.4e-3;
  c.sphere.material.density = 7850.0;
  for (Material* m : {&c.sphere.material, &c.substrate.material}) {
    m->youngs_modulus = 116.116e9;
    m->poisson_ratio = 0.3;
  }
  c.substrate.material.yield_stress = 100e6;
  ASSERT_GE(c.solver.mass_scaling_max, 4.0);
  const ImpactModel m = model_of(c);
  EXPECT_EQ(m.scaling.factor, 4.0);
  // F multiplies the step floor, so the added mass is 6.6e-4 of the sphere's with
  // it (2.6e-4 without it, on the build before the floor).
  EXPECT_LE(m.scaling.added_mass, solver::kMaxAddedMassFraction * m.scaling.sphere_mass_physical);
  c.mesh.transitions = 0.0;
  EXPECT_EQ(model_of(c).scaling.factor, 2.0);
}

// The scaled run gives the e of the physical one to 2e-5 (relative), in 1 / mass_scaling of the
// steps (about half or fewer), with the energy balance closed.
TEST(MassScaling, KeepsEAtLowSpeed) {
  const ImpactResult off = simulate(slow_config(0.2, 1.0));
  const ImpactResult on = simulate(slow_config(0.2, 8.0));
  ASSERT_TRUE(off.separated) << off.status_detail;
  ASSERT_TRUE(on.separated) << on.status_detail;
  ASSERT_GE(on.mass_scaling, 2.0);
  // Measured 1.7e-7 relative (2026-11-27, AMD EPYC AVX-512; F = 2 on a step floor of 1.23,
  // added mass 8.2e-4). Bound 2e-5 (was 2e-4): 100x, since e moves by up to ~0.1 x the added
  // mass fraction (solver.md section 12) and this case happens to cancel; a penalty sized from
  // the scaled masses moved e by 4e-3.
  EXPECT_NEAR(on.e, off.e, 2e-5 * off.e);
  // The base step is mass_scaling x the physical one over the same contact: measured steps x
  // mass_scaling = 1.0028 off.steps (22,832 vs 55,984, 0.408). Bound 1.01 (was steps <= 0.52 x
  // off.steps): 3.6x the measured excess; also fails where the floor is reported but not applied.
  EXPECT_LE(static_cast<double>(on.steps) * on.mass_scaling, 1.01 * static_cast<double>(off.steps));
  std::printf("mass scaling x%g: e %.6f (off %.6f), steps %lld (off %lld), added mass %.2e\n",
              on.mass_scaling, on.e, off.e, on.steps, off.steps, on.added_mass_fraction);
  // Measured 1.0e-7 (6.2e-6 unscaled; 2026-11-27, AMD EPYC AVX-512); bound 5e-7 (was 1e-3):
  // 4.8x margin.
  EXPECT_LT(on.energy_balance_error, 5e-7);
  // Measured 1.4e-5 relative (the physical penalty kept); bound 1e-4 (was 1 %): 7x margin.
  EXPECT_NEAR(on.penetration_max, off.penetration_max, 1e-4 * off.penetration_max);
  EXPECT_GT(on.added_mass_fraction, 0.0);
  // Measured 8.2e-4; the bound is the solver's own limit (1e-3), not a tolerance.
  EXPECT_LE(on.added_mass_fraction, solver::kMaxAddedMassFraction);
}

}  // namespace
}  // namespace corlab::fem
