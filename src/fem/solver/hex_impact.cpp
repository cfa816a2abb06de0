// The 3-D explicit impact solver (hex_model.hpp): its model and state; the time loop, its
// bookkeeping and the result are the axisymmetric model's (time_loop.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "corlab/core/error.hpp"
#include "corlab/core/units.hpp"
#include "corlab/fem/kernels/hex8.hpp"
#include "corlab/fem/kernels/j2_plasticity.hpp"
#include "corlab/fem/kernels/penalty_contact.hpp"
#include "corlab/fem/kernels/rigid_body_mass.hpp"
#include "corlab/fem/kernels/stable_time_step.hpp"
#include "corlab/fem/kernels/sym_tensor3.hpp"
#include "corlab/fem/mesh/contact_estimate.hpp"
#include "corlab/fem/mesh/hex_mesh_generator.hpp"
#include "corlab/fem/mesh/hex_resolution.hpp"
#include "corlab/fem/solver/run_quality.hpp"
#include "fem/solver/hex_element_loop.hpp"
#include "fem/solver/hex_model.hpp"
#include "fem/solver/time_loop.hpp"

namespace corlab::fem::hex_solver {
namespace {

struct Corners {
  double x[8];
  double y[8];
  double z[8];
};

Corners corners(const std::array<int, 8>& hex, const Vec& x, const Vec& y, const Vec& z) {
  Corners c;
  for (int i = 0; i < 8; ++i) {
    const auto n = static_cast<std::size_t>(hex[static_cast<std::size_t>(i)]);
    c.x[i] = x[n];
    c.y[i] = y[n];
    c.z[i] = z[n];
  }
  return c;
}

// Lumped masses (an eighth of each element's to each node) and the smallest element step [s].
double lump_masses(HexModel& m) {
  m.mass.assign(static_cast<std::size_t>(m.mesh.num_nodes()), 0.0);
  double dt_critical = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < m.mesh.hexes.size(); ++e) {
    const auto& hex = m.mesh.hexes[e];
    const BodyMaterial& body = m.bodies[static_cast<std::size_t>(m.mesh.element_body[e])];
    const Corners c = corners(hex, m.mesh.x, m.mesh.y, m.mesh.z);
    const Hex8Geometry g = hex8_geometry(c.x, c.y, c.z);
    for (const int n : hex) m.mass[static_cast<std::size_t>(n)] += 0.125 * body.density * g.volume;
    dt_critical = std::min(
        dt_critical, element_stable_time_step(hex8_characteristic_length(g), body.wave_speed, 0.0));
  }
  return dt_critical;
}

// The sphere's lumped masses rescaled (rigid_body_mass.hpp) to the half sphere's mass
// rho 2/3 pi R^3 [kg] and its moment 2/5 m R^2 [kg m^2] about the spin axis, the y axis through
// the masses' centroid (its centre by the mesh's symmetry).
void give_the_sphere_its_rigid_body_inertia(HexModel& m, const ImpactConfig& config) {
  double mass = 0.0;
  double cx = 0.0;
  double cz = 0.0;
  for (std::size_t n = 0; n < m.mass.size(); ++n) {
    if (m.mesh.node_body[n] != Body::kSphere) continue;
    mass += m.mass[n];
    cx += m.mass[n] * m.mesh.x[n];
    cz += m.mass[n] * m.mesh.z[n];
  }
  cx /= mass;
  cz /= mass;
  auto distance2 = [&](std::size_t n) {
    const double dx = m.mesh.x[n] - cx;
    const double dz = m.mesh.z[n] - cz;
    return dx * dx + dz * dz;
  };
  MassMoments lumped;
  for (std::size_t n = 0; n < m.mass.size(); ++n) {
    if (m.mesh.node_body[n] != Body::kSphere) continue;
    const double d2 = distance2(n);
    lumped.m0 += m.mass[n];
    lumped.m2 += m.mass[n] * d2;
    lumped.m4 += m.mass[n] * d2 * d2;
  }
  const double radius = config.sphere.radius;
  const double target = 0.5 * sphere_mass(radius, config.sphere.material.density);  // half model
  const MassRescaling r = rigid_body_rescaling(lumped, target, 0.4 * target * radius * radius);
  for (std::size_t n = 0; n < m.mass.size(); ++n) {
    if (m.mesh.node_body[n] != Body::kSphere) continue;
    const double factor = r.factor(distance2(n));
    // The default meshes need 1.003-1.033; a factor far from 1 is a mesh that is not this sphere.
    if (!(factor > 0.5 && factor < 2.0)) {
      throw InputError(fmt::format(
          "sphere mesh: its lumped mass and moment of inertia are {:.3g} and {:.3g} of a sphere "
          "of sphere.radius = {} m; must be within a factor of 2 (is the mesh this sphere?)",
          lumped.m0 / target, lumped.m2 / (0.4 * target * radius * radius), radius));
    }
    m.mass[n] *= factor;
  }
}

// Each slave's penalty: the two-mass spring at the stability limit, against the face below it
// on the flat (its corners' mean mass) or the rigid flat.
void set_penalties(HexModel& m, double scale, double dt_critical) {
  for (const int s : m.mesh.sphere_surface_nodes) {
    const auto i = static_cast<std::size_t>(s);
    double master = std::numeric_limits<double>::infinity();
    if (m.contact == solver::ContactKind::kBlockSurface) {
      const auto& face = m.mesh.top_faces[face_under(m.mesh, m.mesh.x[i], m.mesh.y[i])];
      master = 0.0;
      for (const int n : face) master += 0.25 * m.mass[static_cast<std::size_t>(n)];
    }
    m.penalty.push_back(penalty_stiffness(scale, m.mass[i], master, dt_critical));
  }
}

// The element pass's view of the mesh: node indices per corner and the runs of each body.
void index_elements(HexModel& m) {
  const std::size_t ne = m.mesh.hexes.size();
  for (std::size_t i = 0; i < 8; ++i) {
    m.corner[i].resize(ne);
    for (std::size_t e = 0; e < ne; ++e) m.corner[i][e] = m.mesh.hexes[e][i];
  }
  for (std::size_t e = 0; e < ne; ++e) {
    const Body b = m.mesh.element_body[e];
    if (m.runs.empty() || m.runs.back().body != b) m.runs.push_back({e, e, b});
    m.runs.back().end = e + 1;
  }
}

// The run's constants (RunConstants): the clock starts at the release, as the axisymmetric
// model's; the stop rule reads the normal approach speed.
void set_time_scales(const ImpactConfig& config, double dt_critical, HexModel& m) {
  m.extensive = 2.0;  // the half model y >= 0
  m.simd = simd_level();
  m.safety_factor = config.solver.safety_factor;
  m.dt_initial = config.solver.safety_factor * dt_critical;
  m.max_steps = config.solver.max_steps;
  m.t_wave = 4.0 * config.sphere.radius / m.bodies[0].wave_speed;
  const HertzReference hertz =
      hertz_reference(config.sphere.radius, contact_effective_modulus(config),
                      config.sphere.material.density, m.velocity);
  m.t_start = contact_start_time(config);
  m.t_max = config.solver.t_max > 0.0 ? config.solver.t_max : m.t_start + 20.0 * hertz.contact_time;
  m.t_expected = m.t_start + 1.5 * hertz.contact_time;
  const double v0 = config.impact.velocity;
  m.energy_initial = 0.5 * m.sphere_mass * v0 * v0;
  m.energy_relative_initial = m.energy_initial;
  double mz = 0.0;
  for (std::size_t n = 0; n < m.sphere_nodes; ++n) mz += m.mass[n] * m.mesh.z[n];
  m.z_com_start = mz / m.sphere_mass;
  m.sphere_elements = 0;
  for (const HexElementRun& run : m.runs) {
    if (run.body == Body::kSphere) m.sphere_elements = std::max(m.sphere_elements, run.end);
  }
}

HexModel make_model(const ImpactConfig& config) {
  HexModel m;
  const double theta = config.impact.angle.radians;
  m.velocity = normal_velocity(config);
  m.v_tangent = config.impact.velocity * std::sin(theta);
  m.friction = config.contact.friction;
  const HexMeshOptions options = hex_mesh_options_for(config);
  m.h_contact = options.h_contact;
  m.mesh = build_hex_impact_mesh(config);
  m.contact = options.block ? solver::ContactKind::kBlockSurface : solver::ContactKind::kRigidPlane;
  for (const Body b : {Body::kSphere, Body::kSubstrate}) {
    const Material& mat = b == Body::kSphere ? config.sphere.material : config.substrate.material;
    m.bodies[static_cast<std::size_t>(b)] = body_material(mat);
  }
  const double dt_critical = lump_masses(m);
  give_the_sphere_its_rigid_body_inertia(m, config);
  const std::size_t nn = m.mass.size();
  m.inv_mass.resize(nn);
  for (std::size_t n = 0; n < nn; ++n) {
    m.inv_mass[n] = 1.0 / m.mass[n];
    if (m.mesh.node_body[n] == Body::kSphere) {
      m.sphere_mass += m.mass[n];
      m.sphere_nodes = n + 1;
    }
  }
  m.free_x.assign(nn, 1.0);
  m.free_y.assign(nn, 1.0);
  m.free_z.assign(nn, 1.0);
  for (const int n : m.mesh.symmetry_nodes) m.free_y[static_cast<std::size_t>(n)] = 0.0;
  m.dashpots = solver::hex_dashpots(config, m.mesh);
  for (const int n : m.mesh.base_nodes) {
    if (!m.dashpots.empty()) break;  // absorbing: the dashpots hold the base instead
    const auto i = static_cast<std::size_t>(n);
    m.free_x[i] = m.free_y[i] = m.free_z[i] = 0.0;
  }
  m.top_nodes = block_top_nodes(m.mesh);
  m.surface = make_master_surface(m.mesh);
  set_penalties(m, config.solver.penalty_scale, dt_critical);
  index_elements(m);
  set_time_scales(config, dt_critical, m);
  m.slave_points = make_slave_points(m, kContactPointsPerSide);
  m.solver = &config.solver;
  m.kinematic_friction = config.contact.enforcement == FrictionEnforcement::kKinematic;
  return m;
}

HexState initial_state(const HexModel& m) {
  HexState s;
  const std::size_t nn = m.mesh.x.size();
  s.node.resize(nn);
  for (std::size_t n = 0; n < nn; ++n) {
    const bool sphere = n < m.sphere_nodes;
    s.node[n] = {m.mesh.x[n], m.mesh.y[n],
                 m.mesh.z[n], sphere ? m.v_tangent : 0.0,
                 0.0,         sphere ? -m.velocity : 0.0};
  }
  s.nodal_force.assign(nn, NodeForce{0.0, 0.0, 0.0});
  const std::size_t ne = m.mesh.hexes.size();
  for (Vec& c : s.stress) c.assign(ne, 0.0);
  s.eps_p.assign(ne, 0.0);
  for (Vec& q : s.hourglass) q.assign(ne, 0.0);
  // Kinematic friction acts at the contact points, the tangential penalty at the slave nodes.
  const std::size_t carriers =
      m.kinematic_friction ? m.slave_points.size() : m.mesh.sphere_surface_nodes.size();
  s.traction.assign(carriers, {0.0, 0.0, 0.0});
  s.friction_link.assign(m.kinematic_friction ? carriers : 0, {});
  s.t = m.t_start;
  s.dt = m.dt_initial;
  s.sphere_velocity = -m.velocity;
  s.sphere_com_z = m.z_com_start;
  return s;
}

struct Motion {
  double vx = 0.0;  // c.o.m. [m/s]
  double vz = 0.0;
  double omega = 0.0;  // spin about +y [rad/s]
};

// The sphere's rigid-body motion at the end of the run.
Motion sphere_motion(const HexModel& m, const HexState& s) {
  Motion mo;
  double px = 0.0;
  double pz = 0.0;
  double cx = 0.0;
  double cz = 0.0;
  for (std::size_t n = 0; n < m.sphere_nodes; ++n) {
    const double mass = m.mass[n];
    px += mass * s.node[n].vx;
    pz += mass * s.node[n].vz;
    cx += mass * s.node[n].x;
    cz += mass * s.node[n].z;
  }
  mo.vx = px / m.sphere_mass;
  mo.vz = pz / m.sphere_mass;
  cx /= m.sphere_mass;
  cz /= m.sphere_mass;
  double momentum = 0.0;
  double inertia = 0.0;
  for (std::size_t n = 0; n < m.sphere_nodes; ++n) {
    const double dx = s.node[n].x - cx;
    const double dz = s.node[n].z - cz;
    momentum += m.mass[n] * (dz * (s.node[n].vx - mo.vx) - dx * (s.node[n].vz - mo.vz));
    inertia += m.mass[n] * (dx * dx + dz * dz);
  }
  mo.omega = momentum / inertia;
  return mo;
}

// The largest von Mises stress over the block's elements now [Pa] (0 on the rigid flat).
double substrate_von_mises_max(const HexModel& m, const HexState& s) {
  double vm = 0.0;
  for (std::size_t e = m.sphere_elements; e < s.eps_p.size(); ++e) {
    vm = std::max(vm, von_mises(SymTensor3{s.stress[0][e], s.stress[1][e], s.stress[2][e],
                                           s.stress[3][e], s.stress[4][e], s.stress[5][e]}));
  }
  return vm;
}

// The deepest point of the block's top below where it started [m] (0 on the rigid flat): the
// crater's depth, wherever the contact left it.
double crater_depth(const HexModel& m, const HexState& s) {
  double depth = 0.0;
  for (const int n : m.top_nodes) {
    const auto i = static_cast<std::size_t>(n);
    depth = std::max(depth, m.mesh.z[i] - s.node[i].z);
  }
  return depth;
}

// The fields now, for VTU output; t_release: the time from the release [s].
HexFieldSnapshot snapshot(const HexModel& m, const HexState& s, double t_release) {
  HexFieldSnapshot f;
  f.time = t_release;
  f.mesh = m.mesh;
  const std::size_t nn = s.node.size();
  f.displacement.reserve(3 * nn);
  f.velocity.reserve(3 * nn);
  for (std::size_t n = 0; n < nn; ++n) {
    const NodeKinematics& k = s.node[n];
    f.mesh.x[n] = k.x;
    f.mesh.y[n] = k.y;
    f.mesh.z[n] = k.z;
    f.displacement.insert(f.displacement.end(),
                          {k.x - m.mesh.x[n], k.y - m.mesh.y[n], k.z - m.mesh.z[n]});
    f.velocity.insert(f.velocity.end(), {k.vx, k.vy, k.vz});
  }
  const std::size_t ne = s.eps_p.size();
  f.von_mises.resize(ne);
  f.pressure.resize(ne);
  f.plastic_strain = s.eps_p;
  for (std::size_t e = 0; e < ne; ++e) {
    const SymTensor3 st{s.stress[0][e], s.stress[1][e], s.stress[2][e],
                        s.stress[3][e], s.stress[4][e], s.stress[5][e]};
    f.von_mises[e] = von_mises(st);
    f.pressure[e] = -trace(st) / 3.0;
  }
  return f;
}

// The 3-D model's own fields of the result: the oblique rebound (e_t, spin, angle), the crater,
// the block's stress, the quality guards.
void finish_oblique(const HexModel& m, const HexState& s, ImpactResult& r) {
  const Motion mo = sphere_motion(m, s);
  if (r.separated) {
    // e_t of a normal impact is not applicable (NaN, results.csv's `nan`).
    r.e_t = m.v_tangent > 0.0 ? mo.vx / m.v_tangent : std::numeric_limits<double>::quiet_NaN();
    r.omega = mo.omega;
    r.rebound_angle = std::atan2(mo.vx, mo.vz) / units::kDegree;
  }
  r.crater_depth = crater_depth(m, s);
  r.substrate_von_mises_max = substrate_von_mises_max(m, s);
  if (r.separated) r.e_impacts = {r.e};
  if (r.status == RunStatus::kSeparated) r.suspect = suspect_reason(r);
}

}  // namespace

RunCost estimate_hex_run_cost(const ImpactConfig& config) {
  const HexModel m = make_model(config);
  RunCost cost;
  cost.elements = m.mesh.num_elements();
  cost.time_step = m.dt_initial;
  cost.expected_steps = (m.t_expected - m.t_start) / m.dt_initial;
  return cost;
}

ImpactResult run_hex_impact(const ImpactConfig& config, const SimulationControl& control) {
  const auto wall_start = std::chrono::steady_clock::now();
  const HexModel m = make_model(config);
  HexState s = initial_state(m);
  ImpactResult res;
  res.elements = m.mesh.num_elements();
  res.nodes = m.mesh.num_nodes();
  res.h_contact = m.h_contact;
  const HexResolution resolution = hex_resolution(config);
  res.mesh_choice = resolution.model_choice ? "model" : "keys";
  res.mesh_reason = resolution.reason;
  res.simd = std::string(to_string(m.simd));
  res.time_step = m.dt_initial;
  res.energy_initial = m.extensive * m.energy_initial;
  solver::TimeLoop<HexModel, HexState> loop(config, control, m, s, res.history, [&](double t) {
    if (control.on_hex_fields) control.on_hex_fields(t, snapshot(m, s, t));
  });
  const RunStatus status = loop.run();
  solver::finish_run(m, s, loop, status, res);
  finish_oblique(m, s, res);
  solver::close_run(s, wall_start, control, res);
  return res;
}

}  // namespace corlab::fem::hex_solver
