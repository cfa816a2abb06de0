// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The 3-D model's test cases, shared by the tests that run them: the paper's 35 mm steel sphere,
// elastic, sliding at 60 deg from the normal (tan 60 deg is above the rigid-body sliding
// threshold for mu = 0.1), coarse meshes.
#include "corlab/fem/config/impact_config.hpp"

namespace corlab::test {

/// On the rigid flat at 1 m/s, mu = 0.1, h = 1.5 mm (7,542 elements).
inline fem::ImpactConfig sliding_on_rigid_flat() {
  fem::ImpactConfig c;
  c.substrate.shape = fem::SubstrateShape::kRigid;
  c.sphere.material.yield_stress.reset();
  c.impact.velocity = 1.0;
  c.solver.model = fem::SolverModel::kThreeD;
  c.impact.angle = fem::PlaneAngle::degrees(60.0);
  c.contact.friction = 0.1;
  c.mesh.h_min = 1.5e-3;
  c.mesh.contact_elements = 0.0;
  fem::validate(c);
  return c;
}

/// On the deformable flat of the same elastic steel at 10 m/s (v_n = 5 m/s), friction mu [-],
/// element size h [m] at the contact.
inline fem::ImpactConfig sliding_on_elastic_flat(double mu, double h) {
  fem::ImpactConfig c;
  c.sphere.material.yield_stress.reset();
  c.substrate.material.yield_stress.reset();
  c.impact.velocity = 10.0;
  c.solver.model = fem::SolverModel::kThreeD;
  c.impact.angle = fem::PlaneAngle::degrees(60.0);
  c.contact.friction = mu;
  c.mesh.h_min = h;
  c.mesh.contact_elements = 0.0;
  fem::validate(c);
  return c;
}

}  // namespace corlab::test
