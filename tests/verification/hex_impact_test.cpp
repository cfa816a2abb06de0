// The 3-D impact model (hex_impact.hpp) on the rigid flat: the rigid-body sliding identity with
// Coulomb friction, Hertz for a normal elastic impact, and the axisymmetric solver's e for an
// elastic-plastic one. Coarse meshes (R/h = 23-47) keep the suite within CI's time; the converged
// comparisons are in docs/theory/solver3d.md with their commands.
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "corlab/core/units.hpp"
#include "corlab/fem/mesh/contact_estimate.hpp"
#include "corlab/fem/solver/simulate.hpp"
#include "corlab/restitution/oblique_impact.hpp"
#include "support/hex_cases.hpp"

namespace corlab::fem {
namespace {

// The paper's 35 mm steel sphere, elastic, on the rigid flat, with a coarse 3-D mesh.
ImpactConfig rigid_flat(double velocity, double h) {
  ImpactConfig c;
  c.substrate.shape = SubstrateShape::kRigid;
  c.sphere.material.yield_stress.reset();
  c.impact.velocity = velocity;
  c.solver.model = SolverModel::kThreeD;
  c.mesh.h_min = h;
  c.mesh.contact_elements = 0.0;
  validate(c);
  return c;
}

// Where the contact slides throughout (tan theta above the rigid-body threshold), the impulse
// ratio is mu whatever the deformation: e_t = 1 - mu (1 + e_n) / tan theta exactly, and the spin
// follows from the same impulse, omega = mu (1 + e_n) v_n m R / I (5/2 mu (1 + e_n) v_n / R for
// the solid sphere's I = 2/5 m R^2).
TEST(HexImpact, SlidingContactObeysTheRigidBodyIdentity) {
  const ImpactConfig c = test::sliding_on_rigid_flat();
  const double theta = c.impact.angle.radians;
  const ImpactResult r = simulate(c);
  ASSERT_EQ(r.status, RunStatus::kSeparated);
  const double v_n = std::cos(theta);
  const double v_t = std::sin(theta);
  const double radius = c.sphere.radius;
  EXPECT_GT(r.e_n, 0.995);  // elastic: only the sphere's vibration is left behind
  // The rigid-body theory (oblique_impact.hpp) at the FE's own e_n.
  const restitution::ObliqueRebound rigid = restitution::rigid_body_rebound(
      {.normal_velocity = v_n, .tangential_velocity = v_t, .spin = 0.0, .radius = radius},
      {.normal_restitution = r.e_n,
       .friction = c.contact.friction,
       .tangential_restitution = 0.0,
       .gyration = 0.4});
  ASSERT_TRUE(rigid.slides);
  EXPECT_NEAR(r.e_t, rigid.tangential_restitution, 1e-3);
  EXPECT_NEAR(r.omega / rigid.spin, 1.0, 0.01);
  // The frictional dissipation is what the tangential motion lost, less the spin it gained (the
  // normal motion being elastic); the mesh's inertia is 2/5 m R^2 (rigid_body_mass.hpp).
  const double mass = 4.0 / 3.0 * M_PI * std::pow(radius, 3) * c.sphere.material.density;
  const double spin_energy = 0.5 * 0.4 * mass * radius * radius * r.omega * r.omega;
  const double lost = 0.5 * mass * (v_t * v_t - std::pow(r.e_t * v_t, 2)) - spin_energy;
  EXPECT_NEAR(r.energy_friction / lost, 1.0, 0.03);
  EXPECT_LT(r.energy_balance_error, 5e-3);
  EXPECT_NEAR(r.rebound_angle, std::atan2(r.e_t * v_t, r.e_n * v_n) / units::kDegree, 1e-9);
  // The result fields the axisymmetric model has, from the same time loop (time_loop.hpp): the
  // energy CoR counts the rebound's translation, spin and (here < 0.5 %) vibration.
  const double rebound =
      std::pow(r.e_n * v_n, 2) + std::pow(r.e_t * v_t, 2) + 2.0 * spin_energy / mass;
  EXPECT_NEAR(r.e_energy * r.e_energy / rebound, 1.0, 5e-3);
  EXPECT_NEAR(r.energy_sphere_loss / r.energy_initial, 1.0 - r.e_energy * r.e_energy, 1e-12);
  EXPECT_GT(r.delta_max, 0.0);
  EXPECT_EQ(r.crater_depth, 0.0);             // the rigid flat
  EXPECT_EQ(r.substrate_von_mises_max, 0.0);  // has no elements
  EXPECT_EQ(r.e_impacts, std::vector<double>{r.e_n});
  EXPECT_FALSE(r.history.time.empty());
  EXPECT_EQ(r.suspect, "");
}

// output.times counts from the release at impact.gap, as in the axisymmetric model. Half a Hertz
// contact time after the first contact (gap / v_n later) the sphere's centre has slid by v_t t less
// what friction took (mu (1 + e_n) v_n at most, over the contact), has come down by at least
// Hertz's delta_max (this coarse mesh, a / h = 0.75, is softer than Hertz), and the lowest node is
// in the flat by the penalty's penetration, near the run's deepest.
TEST(HexImpact, FieldSnapshotsAreTakenFromTheRelease) {
  ImpactConfig c = test::sliding_on_rigid_flat();
  const double theta = c.impact.angle.radians;
  const double v_n = normal_velocity(c);
  const double v_t = c.impact.velocity * std::sin(theta);
  const HertzReference hertz = hertz_reference(c.sphere.radius, contact_effective_modulus(c),
                                               c.sphere.material.density, v_n);
  const double deepest = c.impact.gap / v_n + 0.5 * hertz.contact_time;
  c.output.field_times = {deepest};
  int calls = 0;
  double lowest = 0.0;
  SimulationControl control;
  control.on_hex_fields = [&](double t, const HexFieldSnapshot& f) {
    ++calls;
    EXPECT_GE(t, deepest);
    EXPECT_LT(t - deepest, 1e-3 * hertz.contact_time);  // the first step at or after it
    const auto nn = static_cast<std::size_t>(f.mesh.num_nodes());
    ASSERT_EQ(f.displacement.size(), 3 * nn);
    ASSERT_EQ(f.velocity.size(), 3 * nn);
    ASSERT_EQ(f.von_mises.size(), static_cast<std::size_t>(f.mesh.num_elements()));
    // The node at the sphere's centre (which the spin does not move) and its lowest node.
    std::size_t centre = 0;
    std::size_t bottom = 0;
    auto from_centre = [&](std::size_t n) {
      return std::hypot(f.mesh.x[n] - f.displacement[3 * n],
                        f.mesh.y[n] - f.displacement[3 * n + 1],
                        f.mesh.z[n] - f.displacement[3 * n + 2] - c.sphere.radius);
    };
    for (std::size_t n = 0; n < nn; ++n) {
      if (from_centre(n) < from_centre(centre)) centre = n;
      if (f.mesh.node_body[n] == Body::kSphere && f.mesh.z[n] < f.mesh.z[bottom]) bottom = n;
    }
    const double slid =
        f.displacement[3 * centre] / (v_t * (t - deepest + 0.5 * hertz.contact_time));
    EXPECT_LE(slid, 1.0);
    EXPECT_GT(slid, 1.0 - c.contact.friction * 2.0 / std::tan(theta));
    EXPECT_GT(-f.displacement[3 * centre + 2] / hertz.max_overlap, 1.0);
    EXPECT_LT(-f.displacement[3 * centre + 2] / hertz.max_overlap, 1.5);
    lowest = f.mesh.z[bottom];
    EXPECT_EQ(*std::max_element(f.plastic_strain.begin(), f.plastic_strain.end()), 0.0);
    EXPECT_GT(*std::max_element(f.von_mises.begin(), f.von_mises.end()), 0.0);
  };
  const ImpactResult r = simulate(c, control);
  ASSERT_EQ(r.status, RunStatus::kSeparated);
  EXPECT_EQ(calls, 1);
  EXPECT_GT(r.end_time, deepest);
  // The deepest penetration is the contact points' (3 x 3 on each of the sphere's faces); the
  // lowest node, a vertex of the faceted surface, stands out of its faces' points by at most
  // the sphere's sag over the distance to the nearest one, (sqrt(2) h / 6)^2 / (2 R).
  const double vertex = 2.0 * std::pow(c.mesh.h_min / 6.0, 2) / (2.0 * c.sphere.radius);
  EXPECT_LE(-lowest, r.penetration_max + vertex);
  EXPECT_GT(-lowest, 0.8 * r.penetration_max);
}

// A normal elastic impact: the peak force and the contact time of Hertz (Johnson 1985,
// section 11.4) at R/h = 58 (a / h = 2.5), the 3-D model's whole sphere (twice the half model).
TEST(HexImpact, NormalElasticImpactFollowsHertz) {
  ImpactConfig c = rigid_flat(1.0, 0.6e-3);
  c.mesh.growth = 1.3;  // a coarser far field: the contact's resolution is what Hertz tests
  const ImpactResult r = simulate(c);
  ASSERT_EQ(r.status, RunStatus::kSeparated);
  const HertzReference h = hertz_reference(c.sphere.radius, contact_effective_modulus(c),
                                           c.sphere.material.density, c.impact.velocity);
  EXPECT_NEAR(r.F_max / h.max_force, 1.0, 0.02);
  EXPECT_NEAR(r.t_contact / h.contact_time, 1.0, 0.05);
  EXPECT_GT(r.e_n, 0.998);
  EXPECT_TRUE(std::isnan(r.e_t));
  // The mesh is mirror-symmetric about x = 0, but round-off in the assembly order leaves a spin:
  // measured 0.0067 rad/s at R/h = 47 (omega R / v = 2e-4); bound it well below any oblique one.
  EXPECT_LT(std::abs(r.omega) * c.sphere.radius / c.impact.velocity, 1e-3);
  EXPECT_LT(r.energy_balance_error, 5e-3);
}

// The 3-D run of `c` and its axisymmetric counterpart at h = 0.25 mm, both separated.
std::pair<ImpactResult, ImpactResult> three_d_and_axisymmetric(const ImpactConfig& c) {
  const ImpactResult three_d = simulate(c);
  ImpactConfig axi = c;
  axi.solver.model = SolverModel::kAxisymmetric;
  axi.mesh.h_min = 0.25e-3;
  const ImpactResult axisymmetric = simulate(axi);
  EXPECT_EQ(three_d.status, RunStatus::kSeparated);
  EXPECT_EQ(axisymmetric.status, RunStatus::kSeparated);
  return {three_d, axisymmetric};
}

// An elastic-plastic normal impact through simulate(): the 3-D model's e against the
// axisymmetric solver's (both on the rigid flat, the sphere yielding).
TEST(HexImpact, ElasticPlasticNormalImpactMatchesTheAxisymmetricSolver) {
  ImpactConfig c = rigid_flat(5.0, 1e-3);
  c.sphere.material.yield_stress = 500e6;
  const auto [three_d, axisymmetric] = three_d_and_axisymmetric(c);
  // R/h = 35: 0.4 % below the axisymmetric e at h = 0.25 mm (1.4 % with 0.4.0's hourglass
  // default; docs/theory/solver3d.md has the convergence of both).
  EXPECT_NEAR(three_d.e / axisymmetric.e, 1.0, 0.01);
  EXPECT_EQ(three_d.e_n, three_d.e);
  EXPECT_EQ(axisymmetric.e_n, axisymmetric.e);
  EXPECT_GT(three_d.plastic_strain_max, 0.05);
  EXPECT_LT(three_d.energy_balance_error, 5e-3);
}

// The paper's pair (the elastic sphere on the steel flat that yields), the 3-D model against the
// axisymmetric one at h = 0.25 mm. 5 m/s at h = 0.5 mm: +0.89 % (+2.16 % at 1 mm, where the
// contact points of 0.9.0 raise the coarse mesh's e by 0.4 %: the 3-D e converges from above,
// and the two meshes extrapolate to -0.4 %); 30 m/s at h = 1 mm: within 2 %. The finer 3-D
// meshes at 1, 5 and 30 m/s and the command that reruns them
// (studies/oblique/normal_3d_vs_axisymmetric.toml) are in solver3d.md.
TEST(HexImpact, ThePapersPairMatchesTheAxisymmetricSolver) {
  struct Case {
    double velocity;  // [m/s]
    double h_min;     // [m]
    double bound;     // on |e_3d / e_axisymmetric - 1| [-]
  };
  for (const Case k : {Case{5.0, 0.5e-3, 0.01}, Case{30.0, 1e-3, 0.02}}) {
    SCOPED_TRACE(k.velocity);
    ImpactConfig c;
    c.impact.velocity = k.velocity;
    c.solver.model = SolverModel::kThreeD;
    c.mesh.h_min = k.h_min;
    c.mesh.contact_elements = 0.0;
    validate(c);
    const auto [three_d, axisymmetric] = three_d_and_axisymmetric(c);
    EXPECT_NEAR(three_d.e / axisymmetric.e, 1.0, k.bound);
    EXPECT_LT(three_d.energy_balance_error, 5e-3);
    // The quality guards apply to 3-D runs: h = 1 mm leaves hourglass energy of about 1 % of
    // E0, above the 0.5 % guard; h = 0.5 mm about 0.3 %, under it.
    if (k.h_min > 0.75e-3) {
      EXPECT_EQ(three_d.suspect.rfind("hourglass energy", 0), 0u) << three_d.suspect;
    } else {
      EXPECT_EQ(three_d.suspect, "");
    }
    EXPECT_EQ(axisymmetric.suspect, "");
  }
}

// The same identity on the deformable flat (the paper's steel, elastic): the impulses on the
// sphere obey Coulomb whatever the flat does. 10 m/s (v_n = 5 m/s) gives a / h = 2.5 at
// h = 1.5 mm; the normal force is Hertz's with both bodies' compliance (like materials: friction
// does not change the pressure, Johnson 1985 section 7.1), within 5 % at this coarse mesh.
TEST(HexImpact, SlidingOnTheDeformableFlatObeysTheIdentity) {
  const ImpactConfig c = test::sliding_on_elastic_flat(0.1, 1.5e-3);
  ASSERT_TRUE(uses_3d_model(c));
  const ImpactResult r = simulate(c);
  ASSERT_EQ(r.status, RunStatus::kSeparated);
  const double theta = c.impact.angle.radians;
  const double v_n = c.impact.velocity * std::cos(theta);
  const double v_t = c.impact.velocity * std::sin(theta);
  // Elastic: 0.9997 at this mesh (0.11.0; 1.0026 with the faceted master before the spline
  // surface, friction acting along facets that the penetration tilts; solver3d.md).
  EXPECT_NEAR(r.e_n, 1.0, 5e-3);
  // The identity written out (rigid_body_rebound takes e_n <= 1 only).
  const double mu = c.contact.friction;
  ASSERT_GT(std::tan(theta), restitution::sliding_threshold({.normal_restitution = 1.0,
                                                             .friction = mu,
                                                             .tangential_restitution = 0.0,
                                                             .gyration = 0.4}));
  EXPECT_NEAR(r.e_t, 1.0 - mu * (1.0 + r.e_n) * v_n / v_t, 1e-3);
  EXPECT_NEAR(r.omega * c.sphere.radius / (2.5 * mu * (1.0 + r.e_n) * v_n), 1.0, 0.01);
  const HertzReference h = hertz_reference(c.sphere.radius, contact_effective_modulus(c),
                                           c.sphere.material.density, v_n);
  EXPECT_NEAR(r.F_max / h.max_force, 1.0, 0.05);
  EXPECT_LT(r.energy_balance_error, 5e-3);
}

// Frictionless sliding over the deformable flat at h = 1 mm: nothing acts along the surface, so
// e_t = 1 and no spin, and the energy stays balanced. With solver.hourglass_3d = 0.05 the moving
// contact pumps energy into the flat's hourglass modes: the balance was off by 1.8 % of E0,
// e_n 1.019, e_t 0.989 (docs/theory/solver3d.md).
TEST(HexImpact, FrictionlessSlidingOnTheDeformableFlatKeepsItsEnergy) {
  const ImpactConfig c = test::sliding_on_elastic_flat(0.0, 1e-3);
  const ImpactResult r = simulate(c);
  ASSERT_EQ(r.status, RunStatus::kSeparated);
  EXPECT_LT(r.energy_balance_error, 1e-3);  // measured 1.1e-4
  EXPECT_NEAR(r.e_t, 1.0, 1.5e-3);          // 1.0005
  EXPECT_NEAR(r.e_n, 0.998, 3e-3);          // 0.9982: the flat's waves keep a little
  EXPECT_LT(std::abs(r.omega) * c.sphere.radius, 2e-3 * c.impact.velocity);  // 1.2e-3
  EXPECT_LT(r.energy_hourglass, 1e-4 * r.energy_initial);
}

}  // namespace
}  // namespace corlab::fem
