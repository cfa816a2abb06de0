// ImpactModel: the constant data of one run, and the initial state.
// SPDX-License-Identifier: BSD-3-Clause
#include "fem/solver/impact_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "corlab/core/error.hpp"
#include "corlab/core/units.hpp"
#include "corlab/fem/kernels/axisym_quad4.hpp"
#include "corlab/fem/kernels/penalty_contact.hpp"
#include "corlab/fem/kernels/stable_time_step.hpp"
#include "corlab/fem/mesh/contact_estimate.hpp"
#include "corlab/fem/solver/contact_search.hpp"
#include "fem/solver/impact_state.hpp"
#include "fem/solver/subcycling_levels.hpp"

namespace corlab::fem::solver {
namespace {

constexpr double kTwoPi = 2.0 * units::kPi;
/// Default hard stop when solver.t_max = 0, in Hertz contact times after the start [-].
constexpr double kDefaultDurationInContactTimes = 20.0;
/// Expected end (for the progress estimate only), in Hertz contact times [-].
constexpr double kExpectedDurationInContactTimes = 1.3;
/// Sphere wave transits in the shortest separation window [-].
constexpr double kWaveTransits = 4.0;
/// Surface nodes within this many predicted contact radii of the axis are contact nodes for
/// mass scaling (the prediction is already the larger of the Hertz and plastic estimates,
/// contact_estimate.hpp; 1.5 is margin; a slave beyond keeps a stable, maybe softer penalty) [-].
constexpr double kScaledContactRadii = 1.5;
/// Bisection steps for the step floor's ratio (2^-30 of its range) [-].
constexpr int kFloorBisections = 30;

BodyParams body_params(const Material& m, const SolverConfig& s) {
  BodyParams p;
  p.material = material_point(m);
  p.density = m.density;
  p.wave_speed = m.dilatational_wave_speed();
  p.hourglass = s.hourglass;
  p.b1 = s.bulk_viscosity_linear;
  p.b2 = s.bulk_viscosity_quadratic;
  return p;
}

void check_node_set(const std::vector<int>& set, const char* name, int nn) {
  for (int n : set) {
    if (n < 0 || n >= nn) throw_invalid(name, n, fmt::format("a node index in [0, {})", nn));
  }
}

void check_mesh(const Mesh& mesh, ContactKind contact) {
  const int nn = mesh.num_nodes();
  const int ne = mesh.num_elements();
  if (nn == 0 || ne == 0) throw_invalid("mesh", "empty", "at least one element per body");
  if (static_cast<int>(mesh.z.size()) != nn || static_cast<int>(mesh.node_body.size()) != nn ||
      static_cast<int>(mesh.element_body.size()) != ne) {
    throw_invalid("mesh", "inconsistent array sizes", "r, z, node_body of nnode entries");
  }
  for (const auto& q : mesh.quads) {
    for (int n : q) {
      if (n < 0 || n >= nn) throw_invalid("mesh element node", n, fmt::format("in [0, {})", nn));
    }
  }
  check_node_set(mesh.axis_nodes, "mesh.axis_nodes", nn);
  check_node_set(mesh.base_nodes, "mesh.base_nodes", nn);
  check_node_set(mesh.sphere_surface_nodes, "mesh.sphere_surface_nodes", nn);
  check_node_set(mesh.substrate_surface_nodes, "mesh.substrate_surface_nodes", nn);
  if (mesh.sphere_surface_nodes.empty()) {
    throw_invalid("mesh.sphere_surface_nodes", "empty", "the contact slave nodes");
  }
  if (contact == ContactKind::kSegments && mesh.substrate_surface_nodes.size() < 2) {
    throw_invalid("mesh.substrate_surface_nodes", "fewer than 2", "the contact master surface");
  }
}

/// Nodal positions, free flags and body flags; the sphere starts translated down by the gap.
void set_nodes(const ImpactConfig& config, const Mesh& mesh, ImpactModel& m) {
  const int nn = m.n_nodes;
  m.r0 = mesh.r;
  m.z0 = mesh.z;
  m.free_r.assign(nn, 1.0);
  m.free_z.assign(nn, 1.0);
  m.is_sphere.assign(nn, 0.0);
  for (int i = 0; i < nn; ++i) {
    if (mesh.node_body[i] == Body::kSphere) {
      m.is_sphere[i] = 1.0;
      m.z0[i] -= config.impact.gap;
    }
  }
  for (int i : mesh.axis_nodes) m.free_r[i] = 0.0;
  if (absorbing_boundary(config)) return;  // the dashpots hold the base instead
  for (int i : mesh.base_nodes) {
    m.free_r[i] = 0.0;
    m.free_z[i] = 0.0;
  }
}

/// The absorbing far boundary's dashpots, each at its element's impedance (mass scaling raises
/// an element's rho c by its step scale).
void set_dashpots(const ImpactConfig& config, const Mesh& mesh, ImpactModel& m) {
  if (!absorbing_boundary(config)) return;
  std::vector<double> scale(static_cast<std::size_t>(m.n_elements), 1.0);
  for (int e = 0; e < m.n_elements; ++e)
    scale[static_cast<std::size_t>(m.elements.mesh_index[e])] = m.elements.step_scale[e];
  m.dashpots = axisymmetric_dashpots(config, mesh, scale);
}

/// Elements sorted by body (sphere first), so that each body's loop runs over one range.
void sort_elements(const Mesh& mesh, ImpactModel& m) {
  m.elements = ElementConstants{};
  for (const Body want : {Body::kSphere, Body::kSubstrate}) {
    for (int e = 0; e < m.n_elements; ++e) {
      if (mesh.element_body[e] == want) m.elements.push_back(mesh.quads[e], e);
    }
    if (want == Body::kSphere) m.n_sphere_elements = m.elements.size();
  }
}

/// Physical mass [kg] and stable step [s] of each element at the start.
struct ElementMasses {
  std::vector<double> mass;
  std::vector<double> step;
  std::vector<char> at_contact;  ///< 1 for the elements of contact_zone_elements()
  double sphere_mass = 0.0;      ///< [kg]
  double step_min = 0.0;         ///< [s]
  double step_floor = 0.0;       ///< steps below it are raised to it (step_floor()) [s]
};

ElementMasses element_masses(const ImpactModel& m) {
  ElementMasses em;
  em.mass.resize(m.n_elements);
  em.step.resize(m.n_elements);
  em.step_min = std::numeric_limits<double>::infinity();
  for (int e = 0; e < m.n_elements; ++e) {
    const Quad4Geometry g = initial_geometry(m, e);
    if (!(g.area > 0.0 && g.omega > 0.0)) {
      throw_invalid("mesh element", m.elements.mesh_index[e],
                    "counter-clockwise with positive area and volume");
    }
    const BodyParams& p = m.body_of(e);
    em.mass[e] = p.density * kTwoPi * g.omega;
    em.step[e] = physical_element_step(m, e);
    em.step_min = std::min(em.step_min, em.step[e]);
    if (e < m.n_sphere_elements) em.sphere_mass += em.mass[e];
  }
  em.step_floor = em.step_min;
  return em;
}

/// Reference pressure of the mass-scaling bound [Pa]: the smaller of the Hertz p0 at the impact
/// speed and the yield stresses (the stress scale the contact zone's inertia competes with).
double reference_pressure(const ImpactConfig& config) {
  double p = hertz_max_pressure(hertz_reference(config));
  for (const auto& sy :
       {config.sphere.material.yield_stress, config.substrate.material.yield_stress}) {
    if (sy) p = std::min(p, *sy);
    if (rigid_target(config)) break;  // the rigid flat has no yield stress
  }
  return p;
}

/// Elements with a node on either contact surface within kScaledContactRadii predicted contact
/// radii of the axis: mass scaling raises their density by the full F^2, so that the contact
/// nodes take the physical penalty stiffness at the scaled step.
std::vector<char> contact_zone_elements(const ImpactConfig& config, const ImpactModel& m) {
  const double r_zone = kScaledContactRadii * predicted_contact_radius(config);
  std::vector<char> zone_node(m.n_nodes, 0);
  for (const auto* set : {&m.slaves, &m.masters}) {
    for (int i : *set) zone_node[i] = m.r0[i] <= r_zone ? 1 : 0;
  }
  std::vector<char> at(m.n_elements, 0);
  for (int e = 0; e < m.n_elements; ++e) {
    for (int n : m.elements.nodes(e)) at[e] = static_cast<char>(at[e] | zone_node[n]);
  }
  return at;
}

/// Step scale of element e for the factor f: f at the contact, else what raises its stable step
/// to f x the floor (1 if it is already longer); elements below the floor reach it first [-].
double element_step_scale(const ElementMasses& em, std::size_t e, double f) {
  if (em.at_contact[e] == 0) return std::max(1.0, f * em.step_floor / em.step[e]);
  return f * std::max(1.0, em.step_floor / em.step[e]);
}

/// Mass added by the factor f [kg].
double added_mass(const ElementMasses& em, double f) {
  double added = 0.0;
  for (std::size_t e = 0; e < em.mass.size(); ++e) {
    const double s = element_step_scale(em, e, f);
    added += (s * s - 1.0) * em.mass[e];
  }
  return added;
}

/// Stable step [s] of an h x h square of either body at the contact (h: contact_element_size),
/// the smaller of the two: what the contact zone's elements themselves allow.
double contact_square_step(const ImpactModel& m) {
  const double h = contact_element_size(m);
  double step = m.sphere.stable_step_at_rest(h / std::sqrt(2.0));
  if (m.contact == ContactKind::kSegments) {
    step = std::min(step, m.substrate.stable_step_at_rest(h / std::sqrt(2.0)));
  }
  return step;
}

/// The step floor [s] (docs/theory/solver.md section 12, "Step floor"): the elements whose stable
/// step is below the contact's own h-squares' (the axis column, whose hoop stiffness shortens
/// it by up to sqrt(2/3), and distorted elements of the sphere's core) get their density raised
/// to reach it, mass scaling below a target step as ABAQUS/Explicit's BELOW MIN does. Bounded so
/// that the contact's physical penalty keeps within the stability budget at the longer step,
/// (1 + penalty_scale x ratio^2) safety_factor^2 <= 1, and so that the added mass stays within
/// kMaxAddedMassFraction of the sphere's (bisection on the ratio); none with mass scaling off.
double step_floor(const SolverConfig& sc, const ImpactModel& m, const ElementMasses& em) {
  if (sc.mass_scaling_max <= 1.0) return em.step_min;
  const double budget = 1.0 / (sc.safety_factor * sc.safety_factor) - 1.0;
  const double stable_ratio = std::sqrt(budget / sc.penalty_scale);
  const double ratio = std::min(contact_square_step(m) / em.step_min, stable_ratio);
  if (!(ratio > 1.0)) return em.step_min;
  const double limit = kMaxAddedMassFraction * em.sphere_mass;
  ElementMasses trial = em;
  const auto fits = [&](double r) {
    trial.step_floor = r * em.step_min;
    return added_mass(trial, 1.0) <= limit;
  };
  if (fits(ratio)) return ratio * em.step_min;
  double lo = 1.0;  // fits
  double hi = ratio;
  for (int k = 0; k < kFloorBisections; ++k) {
    const double mid = 0.5 * (lo + hi);
    if (fits(mid)) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return lo * em.step_min;
}

/// The mass-scaling factor F (a power of two, 1 = none): the largest <= solver.mass_scaling_max
/// whose added inertia (F^2 - 1) rho v^2 / p_ref is <= solver.mass_scaling_inertia and whose
/// added mass is <= kMaxAddedMassFraction of the sphere's.
double mass_scaling_factor(const ImpactConfig& config, const ElementMasses& em) {
  const SolverConfig& sc = config.solver;
  if (sc.mass_scaling_max < 2.0) return 1.0;
  const double rho = rigid_target(config) ? config.sphere.material.density
                                          : std::max(config.sphere.material.density,
                                                     config.substrate.material.density);
  const double v = config.impact.velocity;
  const double inertia = rho * v * v / reference_pressure(config);
  double f = std::exp2(std::floor(std::log2(sc.mass_scaling_max)));
  for (; f >= 2.0; f *= 0.5) {
    if ((f * f - 1.0) * inertia <= sc.mass_scaling_inertia &&
        added_mass(em, f) <= kMaxAddedMassFraction * em.sphere_mass) {
      return f;
    }
  }
  return 1.0;
}

/// Lumped masses (rho V / 4 per node, V = 2 pi Omega exact, rho scaled by step_scale^2) and the
/// initial stable step (docs/theory/solver.md section 12).
void set_masses(const ImpactConfig& config, ImpactModel& m) {
  ElementMasses em = element_masses(m);
  em.at_contact = contact_zone_elements(config, m);
  em.step_floor = step_floor(config.solver, m, em);
  MassScaling& ms = m.scaling;
  ms.dt_critical_physical = em.step_min;
  ms.step_floor_scale = em.step_floor / em.step_min;
  ms.factor = mass_scaling_factor(config, em);
  ms.sphere_mass_physical = em.sphere_mass;
  ms.physical_mass.assign(m.n_nodes, 0.0);
  ms.added_mass = added_mass(em, ms.factor);
  m.mass.assign(m.n_nodes, 0.0);
  m.dt_critical = std::numeric_limits<double>::infinity();
  for (int e = 0; e < m.n_elements; ++e) {
    for (int n : m.elements.nodes(e)) ms.physical_mass[n] += em.mass[e] / 4.0;
    const double s = element_step_scale(em, static_cast<std::size_t>(e), ms.factor);
    m.elements.step_scale[e] = s;
    for (int n : m.elements.nodes(e)) m.mass[n] += s * s * em.mass[e] / 4.0;
    m.dt_critical = std::min(m.dt_critical, s * em.step[e]);
  }
  m.inv_mass.assign(m.n_nodes, 0.0);
  m.sphere_mass = 0.0;
  for (int i = 0; i < m.n_nodes; ++i) {
    if (!(m.mass[i] > 0.0)) throw_invalid("mesh node", i, "part of at least one element");
    m.inv_mass[i] = 1.0 / m.mass[i];
    m.sphere_mass += m.mass[i] * m.is_sphere[i];
  }
}

/// The master masses [kg] a slave's penalty is sized with: interpolated at its projection on the
/// substrate surface, from the scaled and the physical masses; infinite for the rigid flat.
struct MasterMass {
  double scaled = std::numeric_limits<double>::infinity();
  double physical = std::numeric_limits<double>::infinity();
};

MasterMass master_mass(const ImpactModel& m, int slave) {
  if (m.contact == ContactKind::kRigidPlane) return {};
  const int seg = initial_segment(m.r0.data(), m.masters, m.r0[slave]);
  const int a = m.masters[seg];
  const int b = m.masters[seg + 1];
  const double xi = std::clamp((m.r0[slave] - m.r0[a]) / (m.r0[b] - m.r0[a]), 0.0, 1.0);
  const MassScaling& ms = m.scaling;
  return {(1.0 - xi) * m.mass[a] + xi * m.mass[b],
          (1.0 - xi) * ms.physical_mass[a] + xi * ms.physical_mass[b]};
}

/// Penalty stiffness per slave, sized from the critical step itself (not from dt), so that the
/// contact stiffness (and so the penetration and e) does not change with the safety factor.
void set_penalties(const SolverConfig& sc, ImpactModel& m) {
  m.penalty.assign(m.slaves.size(), 0.0);
  for (std::size_t s = 0; s < m.slaves.size(); ++s) {
    const int i = m.slaves[s];
    const MasterMass mm = master_mass(m, i);
    // The physical penalty (mass scaling leaves the contact stiffness, and so e, as it was:
    // an unscaled penalty 1/3 softer moves e by 0.4 % at 0.1 m/s), capped where the node's mass
    // was scaled less than the step (away from the contact) so that it stays stable.
    // The cap allows the step floor's share (step_floor): the physical penalty of an unscaled
    // node at the longer step.
    const MassScaling& ms = m.scaling;
    m.penalty[s] = std::min(penalty_stiffness(sc.penalty_scale, ms.physical_mass[i], mm.physical,
                                              ms.dt_critical_physical),
                            penalty_stiffness(sc.penalty_scale, m.mass[i], mm.scaled,
                                              m.dt_critical / ms.step_floor_scale));
  }
}

/// A free second sphere: its mass and c.o.m. height, the relative motion's initial energy
/// 1/2 m* v0^2, and the separation window long enough for its waves too.
void set_free_target(const ImpactConfig& config, ImpactModel& m) {
  double mass = 0.0;
  double mz = 0.0;
  for (int i = 0; i < m.n_nodes; ++i) {
    mass += m.mass[i] * (1.0 - m.is_sphere[i]);
    mz += m.mass[i] * m.z0[i] * (1.0 - m.is_sphere[i]);
  }
  m.target_mass = mass;
  m.z_com_target_start = mz / mass;
  const double reduced = m.sphere_mass * mass / (m.sphere_mass + mass);
  m.energy_relative_initial = 0.5 * reduced * m.velocity * m.velocity;
  m.t_wave = std::max(m.t_wave, kWaveTransits * config.substrate.radius / m.substrate.wave_speed);
}

void set_time_scales(const ImpactConfig& config, ImpactModel& m) {
  const SolverConfig& sc = config.solver;
  m.velocity = config.impact.velocity;
  m.safety_factor = sc.safety_factor;
  m.dt_initial = sc.safety_factor * m.dt_critical;
  m.t_start = contact_start_time(config);
  const double t_hertz = hertz_reference(config).contact_time;
  m.t_max = sc.t_max > 0.0 ? sc.t_max : m.t_start + kDefaultDurationInContactTimes * t_hertz;
  m.t_wave = kWaveTransits * config.sphere.radius / m.sphere.wave_speed;
  m.t_expected = m.t_start + kExpectedDurationInContactTimes * t_hertz + m.t_wave;
  m.energy_initial = 0.5 * m.sphere_mass * m.velocity * m.velocity;
  m.energy_relative_initial = m.energy_initial;
  double mz = 0.0;
  for (int i = 0; i < m.n_nodes; ++i) mz += m.mass[i] * m.z0[i] * m.is_sphere[i];
  m.z_com_start = mz / m.sphere_mass;
  if (m.free_target) set_free_target(config, m);
  m.max_steps = sc.max_steps;
}

}  // namespace

Quad4Geometry initial_geometry(const ImpactModel& m, int e) {
  const std::array<int, 4> nd = m.elements.nodes(e);
  double xr[4], xz[4];
  for (int i = 0; i < 4; ++i) {
    xr[i] = m.r0[nd[i]];
    xz[i] = m.z0[nd[i]];
  }
  return quad4_geometry(xr, xz);
}

double contact_element_size(const ImpactModel& m) {
  const std::vector<int>& surface = m.contact == ContactKind::kSegments ? m.masters : m.slaves;
  const int a = surface[0];
  const int b = surface[1];
  return std::hypot(m.r0[b] - m.r0[a], m.z0[b] - m.z0[a]);
}

double physical_element_step(const ImpactModel& m, int e) {
  return m.body_of(e).stable_step_at_rest(characteristic_length(initial_geometry(m, e)));
}

ImpactModel make_impact_model(const ImpactConfig& config, const Mesh& mesh) {
  ImpactModel m;
  m.contact = rigid_target(config) ? ContactKind::kRigidPlane : ContactKind::kSegments;
  m.free_target = sphere_target(config);
  check_mesh(mesh, m.contact);
  m.n_nodes = mesh.num_nodes();
  m.n_elements = mesh.num_elements();
  m.sphere = body_params(config.sphere.material, config.solver);
  m.substrate = body_params(config.substrate.material, config.solver);
  set_nodes(config, mesh, m);
  sort_elements(mesh, m);
  m.slaves = mesh.sphere_surface_nodes;
  m.masters = mesh.substrate_surface_nodes;
  set_masses(config, m);
  set_dashpots(config, mesh, m);
  set_penalties(config.solver, m);
  set_levels(config.solver, m);
  set_time_scales(config, m);
  m.simd = simd_level();
  return m;
}

/// Subcycling state: each element's last positions (the start) and viscous stress (none).
void init_subcycling(const ImpactModel& m, ImpactState& s) {
  ElementState& es = s.elements;
  const auto ne = static_cast<std::size_t>(m.n_elements);
  es.bv.assign(ne, 0.0);
  for (int i = 0; i < 4; ++i) {
    es.r_prev[i].resize(ne);
    es.z_prev[i].resize(ne);
    for (std::size_t e = 0; e < ne; ++e) {
      es.r_prev[i][e] = m.r0[m.elements.corner[i][e]];
      es.z_prev[i][e] = m.z0[m.elements.corner[i][e]];
    }
  }
  s.level_dt_min.fill(std::numeric_limits<double>::infinity());
  s.transit.reset(m.levels, s.vr.data(), s.vz.data());
}

ImpactState make_initial_state(const ImpactModel& m) {
  ImpactState s;
  s.r = m.r0;
  s.z = m.z0;
  s.vr.assign(m.n_nodes, 0.0);
  s.vz.assign(m.n_nodes, 0.0);
  for (int i = 0; i < m.n_nodes; ++i) {
    if (m.is_sphere[i] != 0.0) s.vz[i] = -m.velocity;
  }
  s.fr.assign(m.n_nodes, 0.0);
  s.fz.assign(m.n_nodes, 0.0);
  s.elements.resize(static_cast<std::size_t>(m.n_elements));
  s.cursor.assign(m.slaves.size(), 0);
  if (m.contact == ContactKind::kSegments) {
    for (std::size_t k = 0; k < m.slaves.size(); ++k) {
      s.cursor[k] = initial_segment(m.r0.data(), m.masters, m.r0[m.slaves[k]]);
    }
  }
  s.t = m.t_start;
  s.dt = m.dt_initial;
  s.sphere_velocity = -m.velocity;
  s.target_com_z = m.z_com_target_start;
  if (m.levels.max_level > 0) init_subcycling(m, s);
  return s;
}

}  // namespace corlab::fem::solver
