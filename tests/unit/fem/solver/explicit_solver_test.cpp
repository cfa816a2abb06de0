// The explicit solver on small meshes (explicit_solver.hpp): stability at the default safety
// factor, energy balance, momentum, cancel, bad meshes.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/explicit_solver.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <stdexcept>

#include "corlab/core/error.hpp"
#include "support/fem_test_meshes.hpp"

namespace corlab::fem {
namespace {

// Flat punch (radius 2 mm, height 2 mm) on a 4 mm x 2 mm substrate, 12 elements across.
ImpactConfig punch_config(double velocity, bool plastic) {
  ImpactConfig c;
  c.sphere.radius = 2e-3;
  c.substrate.radius = 4e-3;
  c.substrate.depth = 2e-3;
  c.impact.velocity = velocity;
  c.impact.gap = 0.0;
  c.output.history_every = 1;
  if (!plastic) c.substrate.material.yield_stress = std::nullopt;
  return c;
}

Mesh punch() { return testing::punch_mesh(2e-3, 2e-3, 4e-3, 2e-3, 0.0, 12); }

TEST(ExplicitSolver, ElasticPunchIsStableAndConservesEnergy) {
  const ImpactConfig c = punch_config(2.0, false);
  const ImpactResult r = run_impact(c, punch());
  EXPECT_TRUE(r.separated);
  // A flat punch chatters at its edge; each penalty opening/closing inside a step leaves an
  // O(k g^2) energy error, the smooth sphere contact leaves 1e-6. Measured 4.61e-3 (2026-11-27,
  // AMD EPYC AVX-512; 4.20e-3 without the step floor; "0.2 %" when first written). Bound 5e-3
  // kept, not tightened: the measurement sits at 0.92 of it.
  EXPECT_LT(r.energy_balance_error, 5e-3);
  // Bounded energies at every output step (no instability at the default safety factor).
  // Measured: the largest KE is the first row's, E0 + 1 ulp; bound E0 (1 + 1e-6) (was 1.001).
  for (std::size_t i = 0; i < r.history.time.size(); ++i) {
    ASSERT_LT(r.history.kinetic_energy[i], (1.0 + 1e-6) * r.energy_initial) << "row " << i;
    ASSERT_TRUE(std::isfinite(r.history.strain_energy[i]));
  }
  EXPECT_GT(r.F_max, 0.0);
  EXPECT_GT(r.e, 0.0);
  EXPECT_LE(r.e, 1.0 + 1e-6);
  EXPECT_EQ(r.energy_dissipated_plastic, 0.0);
  // Contact force integral = change of the punch momentum (F is the force on the sphere), so
  // its work on the c.o.m. is E0 (1 - e^2). Measured 4.8e-9 E0 apart (2026-11-27, AMD EPYC
  // AVX-512): the trapezoid against the leapfrog; bound 1e-7 E0 (was 0.02 E0): 20x margin.
  EXPECT_NEAR(r.hysteresis_area, r.energy_initial * (1.0 - r.e * r.e), 1e-7 * r.energy_initial);
}

TEST(ExplicitSolver, PlasticPunchDissipates) {
  const ImpactConfig c = punch_config(20.0, true);
  const ImpactResult r = run_impact(c, punch());
  EXPECT_GT(r.energy_dissipated_plastic, 0.0);
  EXPECT_GT(r.plastic_strain_max, 0.0);
  // Measured 4.53e-3 (2026-11-27, AMD EPYC AVX-512; 4.12e-3 without the step floor): the edge
  // chatter as above. Bound 5e-3 kept, not tightened: the measurement sits at 0.91 of it.
  EXPECT_LT(r.energy_balance_error, 5e-3);
  EXPECT_LT(r.e, 1.0);
  EXPECT_GT(r.crater_depth, 0.0);
}

TEST(ExplicitSolver, CancelStopsTheRun) {
  std::atomic<bool> cancel{true};
  SimulationControl control;
  control.cancel = &cancel;
  const ImpactResult r = run_impact(punch_config(2.0, false), punch(), control);
  EXPECT_EQ(r.status, RunStatus::kCancelled);
  EXPECT_EQ(r.steps, 0);
  EXPECT_TRUE(std::isnan(r.e));
}

TEST(ExplicitSolver, FieldsAndProgressAreReported) {
  ImpactConfig c = punch_config(2.0, false);
  c.output.field_times = {1e-7, 5e-7};
  int fields = 0;
  double last_progress = -1.0;
  SimulationControl control;
  control.on_fields = [&](double t, const FieldSnapshot& f) {
    EXPECT_GE(t, c.output.field_times[fields]);
    EXPECT_EQ(f.mesh.num_nodes(), static_cast<int>(f.displacement_r.size()));
    EXPECT_EQ(f.mesh.num_elements(), static_cast<int>(f.von_mises.size()));
    ++fields;
  };
  control.progress = [&](double p) { last_progress = p; };
  run_impact(c, punch(), control);
  EXPECT_EQ(fields, 2);
  EXPECT_EQ(last_progress, 1.0);
}

TEST(ExplicitSolver, RejectsBadMeshes) {
  Mesh m = punch();
  std::swap(m.quads[0][1], m.quads[0][3]);  // clockwise element
  EXPECT_THROW(run_impact(punch_config(2.0, false), m), InputError);
  Mesh empty;
  EXPECT_THROW(run_impact(punch_config(2.0, false), empty), InputError);
}

}  // namespace
}  // namespace corlab::fem

namespace corlab::fem {
namespace {

// Run outcomes as statuses (run_status.hpp): never an e for a run that did not rebound cleanly.
TEST(ExplicitSolverStatus, TMaxDuringContactIsNotSeparated) {
  ImpactConfig c = punch_config(2.0, false);
  const ImpactResult full = run_impact(c, punch());
  ASSERT_EQ(full.status, RunStatus::kSeparated);
  c.solver.t_max = 0.5 * full.t_contact;
  const ImpactResult r = run_impact(c, punch());
  EXPECT_EQ(r.status, RunStatus::kNotSeparated);
  EXPECT_FALSE(r.separated);
  EXPECT_TRUE(std::isnan(r.e));  // not -1 or -0.5 as a rebound
  EXPECT_NE(r.status_detail.find("t_max"), std::string::npos);
}

TEST(ExplicitSolverStatus, CleanRunIsNotSuspect) {
  const ImpactResult r = run_impact(punch_config(2.0, true), punch());
  EXPECT_EQ(r.status, RunStatus::kSeparated);
  EXPECT_TRUE(std::isfinite(r.e));
  EXPECT_GT(r.e, 0.0);
  EXPECT_EQ(r.suspect, "");
}

}  // namespace
}  // namespace corlab::fem
