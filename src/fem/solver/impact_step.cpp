// One central-difference step: kinematics, then element and contact forces.
#include "fem/solver/impact_step.hpp"

#include <algorithm>

#include "corlab/fem/contact_search.hpp"
#include "corlab/fem/penalty_contact.hpp"

namespace corlab::fem::solver {
namespace {

/// Node-to-segment penalty contact at x^{n+1}: forces into fr/fz, the stored penalty energy, the
/// total force on the sphere and the deepest penetration.
bool apply_contact(const ImpactModel& m, ImpactState& s, double& force, double& energy) {
  bool penetrating = false;
  force = 0.0;
  energy = 0.0;
  for (std::size_t k = 0; k < m.slaves.size(); ++k) {
    const int i = m.slaves[k];
    const ContactCandidate c =
        find_contact(s.r.data(), s.z.data(), m.masters, s.r[i], s.z[i], s.cursor[k]);
    s.cursor[k] = c.segment;
    if (!c.active) continue;
    const int a = m.masters[c.segment];
    const int b = m.masters[c.segment + 1];
    energy += penalty_force(c.projection, m.penalty[k], s.fr[i], s.fz[i], s.fr[a], s.fz[a], s.fr[b],
                            s.fz[b]);
    force += -m.penalty[k] * c.projection.gap * c.projection.nz;
    s.penetration_max = std::max(s.penetration_max, -c.projection.gap);
    penetrating = true;
  }
  return penetrating;
}

}  // namespace

NodeSums move_nodes(const ImpactModel& m, ImpactState& s) {
  const double dt_avg = 0.5 * (s.dt_prev + s.dt);
  const NodeSums ns =
      node_update(m.n_nodes, s.dt, dt_avg, s.r.data(), s.z.data(), s.vr.data(), s.vz.data(),
                  s.fr.data(), s.fz.data(), m.mass.data(), m.inv_mass.data(), m.free_r.data(),
                  m.free_z.data(), m.is_sphere.data());
  s.sphere_velocity = ns.p_sphere / m.sphere_mass;
  s.sphere_com_z = ns.mz_sphere / m.sphere_mass;
  return ns;
}

ForceReport compute_forces(const ImpactModel& m, ImpactState& s) {
  ForceReport rep;
  ElementSums& sums = rep.elements;
  element_loop(m.sphere, s.elements, 0, m.n_sphere_elements, s.r.data(), s.z.data(), s.vr.data(),
               s.vz.data(), s.fr.data(), s.fz.data(), s.dt, sums);
  element_loop(m.substrate, s.elements, m.n_sphere_elements, m.n_elements, s.r.data(), s.z.data(),
               s.vr.data(), s.vz.data(), s.fr.data(), s.fz.data(), s.dt, sums);
  if (sums.bad_element >= 0) rep.inverted_element = m.original_element[sums.bad_element];
  s.energy.internal += sums.internal_work;
  s.energy.plastic += sums.plastic_work;
  s.energy.hourglass += sums.hourglass_work;
  s.energy.viscous += sums.viscous_work;
  s.eps_p_max = std::max(s.eps_p_max, sums.eps_p_max);

  double force = 0.0;
  rep.penetrating = apply_contact(m, s, force, s.energy.contact);
  const double indentation = m.z_com_start - s.sphere_com_z;
  s.hysteresis += 0.5 * (s.force + force) * (indentation - s.indentation);
  s.force = force;
  s.indentation = indentation;
  s.force_max = std::max(s.force_max, force);
  s.indentation_max = std::max(s.indentation_max, indentation);

  s.t += s.dt;
  ++s.step;
  s.dt_prev = s.dt;
  s.dt = m.safety_factor * sums.dt_min;
  return rep;
}

}  // namespace corlab::fem::solver
