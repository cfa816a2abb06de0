// The 3-D explicit impact solver (hex_impact.hpp): model, element update, time loop.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/hex_impact.hpp"

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
#include "corlab/fem/kernels/stable_time_step.hpp"
#include "corlab/fem/kernels/sym_tensor3.hpp"
#include "corlab/fem/mesh/contact_estimate.hpp"
#include "corlab/fem/mesh/hex_mesh_generator.hpp"
#include "corlab/fem/solver/separation_rule.hpp"
#include "fem/solver/hex_element_loop.hpp"
#include "fem/solver/hex_model.hpp"

namespace corlab::fem {
namespace hex_solver {
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

// Each slave's penalty: the two-mass spring at the stability limit, against the face below it
// on the flat (its corners' mean mass) or the rigid flat.
void set_penalties(HexModel& m, double scale, double dt_critical) {
  for (const int s : m.mesh.sphere_surface_nodes) {
    const auto i = static_cast<std::size_t>(s);
    double master = std::numeric_limits<double>::infinity();
    if (m.deformable_target) {
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

HexModel make_model(const ImpactConfig& config) {
  HexModel m;
  const double theta = config.impact.angle * units::kPi / 180.0;
  m.v_normal = normal_velocity(config);
  m.v_tangent = config.impact.velocity * std::sin(theta);
  m.friction = config.contact.friction;
  const HexMeshOptions options = hex_mesh_options_for(config);
  m.h_contact = options.h_contact;
  m.mesh = build_hex_impact_mesh(config);
  m.deformable_target = options.block;
  for (const Body b : {Body::kSphere, Body::kSubstrate}) {
    const Material& mat = b == Body::kSphere ? config.sphere.material : config.substrate.material;
    BodyMaterial& body = m.bodies[static_cast<std::size_t>(b)];
    body.material = J2Plasticity::from(mat);
    body.density = mat.density;
    body.wave_speed = mat.dilatational_wave_speed();
  }
  const double dt_critical = lump_masses(m);
  const std::size_t nn = m.mass.size();
  m.inv_mass.resize(nn);
  for (std::size_t n = 0; n < nn; ++n) {
    m.inv_mass[n] = 1.0 / m.mass[n];
    if (m.mesh.node_body[n] == Body::kSphere) {
      m.total_mass += m.mass[n];
      m.sphere_nodes = n + 1;
    }
  }
  m.free_x.assign(nn, 1.0);
  m.free_y.assign(nn, 1.0);
  m.free_z.assign(nn, 1.0);
  for (const int n : m.mesh.symmetry_nodes) m.free_y[static_cast<std::size_t>(n)] = 0.0;
  for (const int n : m.mesh.base_nodes) {
    const auto i = static_cast<std::size_t>(n);
    m.free_x[i] = m.free_y[i] = m.free_z[i] = 0.0;
  }
  m.top_nodes = block_top_nodes(m.mesh);
  set_penalties(m, config.solver.penalty_scale, dt_critical);
  index_elements(m);
  m.simd = simd_level();
  m.dt_initial = config.solver.safety_factor * dt_critical;
  m.t_wave = 4.0 * config.sphere.radius / m.bodies[0].wave_speed;
  const HertzReference hertz =
      hertz_reference(config.sphere.radius, contact_effective_modulus(config),
                      config.sphere.material.density, m.v_normal);
  // The loop's clock starts at the first contact; solver.t_max counts from the release.
  m.t_start = contact_start_time(config);
  m.t_max = config.solver.t_max > 0.0 ? config.solver.t_max - m.t_start : 20.0 * hertz.contact_time;
  m.t_expected = 1.5 * hertz.contact_time;
  m.solver = &config.solver;
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
                 0.0,         sphere ? -m.v_normal : 0.0};
  }
  s.force.assign(nn, NodeForce{0.0, 0.0, 0.0});
  const std::size_t ne = m.mesh.hexes.size();
  for (Vec& c : s.stress) c.assign(ne, 0.0);
  s.eps_p.assign(ne, 0.0);
  for (Vec& q : s.hourglass) q.assign(ne, 0.0);
  s.traction.assign(m.mesh.sphere_surface_nodes.size(), {0.0, 0.0, 0.0});
  s.dt = m.dt_initial;
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
  mo.vx = px / m.total_mass;
  mo.vz = pz / m.total_mass;
  cx /= m.total_mass;
  cz /= m.total_mass;
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

// Advances positions by dt with the current velocities and assembles the forces there. Returns
// the next stable step (0: an element inverted).
double step_forces(const HexModel& m, HexState& s, double dt, bool& penetrating) {
  for (std::size_t n = 0; n < s.node.size(); ++n) {
    s.node[n].x += dt * s.node[n].vx;
    s.node[n].y += dt * s.node[n].vy;
    s.node[n].z += dt * s.node[n].vz;
    s.force[n].x = 0.0;
    s.force[n].y = 0.0;
    s.force[n].z = 0.0;
  }
  const HexElementSums sums = hex_element_pass(m.simd, m, s, dt);
  if (sums.inverted) return 0.0;
  s.w_internal += sums.internal_work;
  s.w_plastic += sums.plastic_work;
  s.w_hourglass += sums.hourglass_work;
  s.w_viscous += sums.viscous_work;
  s.eps_p_max = std::max(s.eps_p_max, sums.eps_p_max);
  penetrating = contact_forces(m, s, dt);
  return m.solver->safety_factor * sums.dt_min;
}

// What the stop rule and the energy balance need of the velocities after an update.
struct VelocitySums {
  double kinetic = 0.0;  // both bodies [J], half model
  double vz = 0.0;       // the sphere's c.o.m. normal velocity [m/s]
};

// v^{n+1/2} = v^{n-1/2} + dt_avg f / m, the symmetry plane's v_y held at zero; the kinetic
// energy and the sphere's momentum in the same pass.
VelocitySums update_velocities(const HexModel& m, HexState& s, double dt_avg) {
  VelocitySums sums;
  double pz = 0.0;
  for (std::size_t n = 0; n < s.node.size(); ++n) {
    s.node[n].vx = m.free_x[n] * (s.node[n].vx + dt_avg * s.force[n].x * m.inv_mass[n]);
    s.node[n].vy = m.free_y[n] * (s.node[n].vy + dt_avg * s.force[n].y * m.inv_mass[n]);
    s.node[n].vz = m.free_z[n] * (s.node[n].vz + dt_avg * s.force[n].z * m.inv_mass[n]);
    const double mass = m.mass[n];
    sums.kinetic +=
        0.5 * mass *
        (s.node[n].vx * s.node[n].vx + s.node[n].vy * s.node[n].vy + s.node[n].vz * s.node[n].vz);
    if (n < m.sphere_nodes) pz += mass * s.node[n].vz;
  }
  sums.vz = pz / m.total_mass;
  return sums;
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

// Calls on_hex_fields at each output.times that the clock has passed.
class FieldTimes {
 public:
  FieldTimes(const ImpactConfig& config, const SimulationControl& control)
      : times_(config.output.field_times), on_fields_(control.on_hex_fields) {
    std::sort(times_.begin(), times_.end());
  }
  void poll(const HexModel& m, const HexState& s) {
    const double t = m.t_start + s.t;
    while (next_ < times_.size() && t >= times_[next_]) {
      if (on_fields_) on_fields_(t, snapshot(m, s, t));
      ++next_;
    }
  }

 private:
  std::vector<double> times_;
  const std::function<void(double, const HexFieldSnapshot&)>& on_fields_;
  std::size_t next_ = 0;
};

void finish(const HexModel& m, const HexState& s, HexImpactResult& r) {
  const Motion mo = sphere_motion(m, s);
  r.vx_final = mo.vx;
  r.vz_final = mo.vz;
  r.omega = mo.omega;
  r.e_n = mo.vz / m.v_normal;
  r.e_t = m.v_tangent > 0.0 ? mo.vx / m.v_tangent : std::numeric_limits<double>::quiet_NaN();
  r.rebound_angle = std::atan2(mo.vx, mo.vz) * 180.0 / units::kPi;
  r.energy_friction = 2.0 * s.w_friction;
  r.energy_dissipated_plastic = 2.0 * s.w_plastic;
  r.energy_hourglass = 2.0 * s.w_hourglass;
  r.energy_viscous = 2.0 * s.w_viscous;
  r.end_time = m.t_start + s.t;
  r.plastic_strain_max = s.eps_p_max;
  r.penetration_max = s.penetration_max;
  r.steps = s.steps;
}

}  // namespace

RunCost estimate_hex_run_cost(const ImpactConfig& config) {
  const HexModel m = make_model(config);
  RunCost cost;
  cost.elements = m.mesh.num_elements();
  cost.time_step = m.dt_initial;
  cost.expected_steps = m.t_expected / m.dt_initial;
  return cost;
}

HexImpactResult run_hex_impact(const ImpactConfig& config, const SimulationControl& control) {
  const auto start = std::chrono::steady_clock::now();
  const HexModel m = make_model(config);
  HexState s = initial_state(m);
  HexImpactResult r;
  r.elements = m.mesh.num_elements();
  r.nodes = m.mesh.num_nodes();
  r.h_contact = m.h_contact;
  r.simd = std::string(to_string(m.simd));
  r.time_step = m.dt_initial;
  const double v0 = config.impact.velocity;
  const double energy0 = 0.5 * m.total_mass * v0 * v0;
  r.energy_initial = 2.0 * energy0;
  SeparationRule rule(m.t_wave, m.v_normal);
  FieldTimes fields(config, control);
  fields.poll(m, s);  // times before the first contact: the state at contact stands for them
  double dt_prev = 0.0;
  while (true) {
    const double dt = s.dt;
    bool penetrating = false;
    const double dt_next = step_forces(m, s, dt, penetrating);
    s.t += dt;
    ++s.steps;
    if (!(dt_next > 0.0)) {
      r.status = RunStatus::kElementInverted;
      break;
    }
    const VelocitySums mo = update_velocities(m, s, 0.5 * (dt + dt_next));
    s.dt = dt_next;
    r.F_max = std::max(r.F_max, 2.0 * s.normal_force);
    const double balance = mo.kinetic + s.w_internal + s.w_hourglass + s.w_viscous + s.e_contact +
                           s.w_friction - energy0;
    if (!std::isfinite(balance)) {
      r.status = RunStatus::kNonFinite;
      break;
    }
    r.energy_balance_error = std::max(r.energy_balance_error, std::abs(balance) / energy0);
    fields.poll(m, s);
    rule.accumulate(mo.kinetic, dt);
    const auto decision = rule.update(s.t, dt_prev, penetrating, mo.vz);
    dt_prev = dt;
    if (decision == SeparationRule::Decision::kRebound) {
      r.status = RunStatus::kSeparated;
      break;
    }
    if (decision == SeparationRule::Decision::kNoRebound || s.t > m.t_max) {
      r.status = RunStatus::kNotSeparated;
      break;
    }
    if (s.steps >= config.solver.max_steps) {
      r.status = RunStatus::kStepBudgetExceeded;
      break;
    }
    if ((s.steps & 255) == 0) {
      if (control.cancel != nullptr && control.cancel->load()) {
        r.status = RunStatus::kCancelled;
        break;
      }
      if (control.progress) control.progress(std::min(0.99, s.t / m.t_expected));
    }
  }
  r.t_contact = rule.contact_time();
  finish(m, s, r);
  if (control.progress) control.progress(1.0);
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace hex_solver

HexImpactResult simulate_hex_impact(const ImpactConfig& config, const SimulationControl& control) {
  return hex_solver::run_hex_impact(config, control);
}

}  // namespace corlab::fem
