// Explicit central-difference integration of the sphere-on-substrate impact (assembly and loop).
// Kernels: axisym_quad4.hpp, j2_plasticity.hpp, objective_rate.hpp, hourglass.hpp,
// bulk_viscosity.hpp, penalty_contact.hpp, stable_time_step.hpp. Theory: docs/theory/solver.md.
#include "corlab/fem/explicit_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "corlab/core/error.hpp"
#include "corlab/core/units.hpp"
#include "corlab/fem/axisym_quad4.hpp"
#include "corlab/fem/bulk_viscosity.hpp"
#include "corlab/fem/contact_estimate.hpp"
#include "corlab/fem/field_snapshot.hpp"
#include "corlab/fem/hourglass.hpp"
#include "corlab/fem/j2_plasticity.hpp"
#include "corlab/fem/objective_rate.hpp"
#include "corlab/fem/penalty_contact.hpp"
#include "corlab/fem/stable_time_step.hpp"

namespace corlab::fem {

namespace {

constexpr double kTwoPi = 2.0 * units::kPi;

// Hot loops are compiled for AVX-512 (x86-64-v4), AVX2 (v3) and the baseline; the dynamic loader
// picks the best the CPU has (GCC function multiversioning). Elsewhere: the baseline only.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && __GNUC__ >= 12
#define CORLAB_SIMD_CLONES [[gnu::target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")]]
#else
#define CORLAB_SIMD_CLONES
#endif

// Constant per-body parameters of the element loop.
struct BodyParams {
  J2Plasticity material;
  double density = 0.0;     // [kg/m^3]
  double wave_speed = 0.0;  // c_d [m/s]
  double hourglass = 0.0;   // kappa [-]
  double b1 = 0.0;
  double b2 = 0.0;
};

// Structure-of-arrays element state, elements of one body contiguous.
struct ElementState {
  std::vector<std::array<int, 4>> nodes;
  std::vector<double> srr, szz, stt, srz;  // Cauchy stress [Pa]
  std::vector<double> eps_p;               // equivalent plastic strain [-]
  std::vector<double> qr, qz;              // hourglass generalised forces [N]
  void resize(std::size_t n) {
    nodes.resize(n);
    for (auto* v : {&srr, &szz, &stt, &srz, &eps_p, &qr, &qz}) v->assign(n, 0.0);
  }
};

// Per-step sums returned by the element loop.
struct ElementSums {
  double internal_work = 0.0;
  double plastic_work = 0.0;
  double hourglass_work = 0.0;
  double viscous_work = 0.0;
  double eps_p_max = 0.0;
  double dt_min = std::numeric_limits<double>::infinity();
  double omega_min = std::numeric_limits<double>::infinity();  // smallest volume or area
  int bad_element = -1;  // first element of the block holding an inverted element
};

// Elements per block of the element loop: gathered into lane arrays, computed lane-parallel
// (the pure kernels, inlined, vectorised across elements), then scattered.
constexpr int kBlock = 16;

// The lane-parallel part of one block of nb <= kBlock elements: stress update at the mid-step
// geometry x^{n+1/2}, internal + hourglass forces at x^{n+1}, stable step. f_r/f_z receive f_int.
[[gnu::always_inline]] inline void element_block(const BodyParams& p,
                                                 int nb,
                                                 const double* __restrict xr,
                                                 const double* __restrict xz,
                                                 const double* __restrict ur,
                                                 const double* __restrict uz,
                                                 double* __restrict srr,
                                                 double* __restrict szz,
                                                 double* __restrict stt,
                                                 double* __restrict srz,
                                                 double* __restrict eps_p,
                                                 double* __restrict qr,
                                                 double* __restrict qz,
                                                 double* __restrict f_r,
                                                 double* __restrict f_z,
                                                 double dt,
                                                 ElementSums& sums) {
  const J2Plasticity mat = p.material;
  const double shear = mat.shear_modulus;
  const double rho = p.density;
  const double c = p.wave_speed;
  const double kappa = p.hourglass;
  const double b1 = p.b1;
  const double b2 = p.b2;
  // Per-lane results (no reductions inside the loop, so it vectorises without reassociation).
  alignas(64) double w_int[kBlock], w_p[kBlock], w_hg[kBlock], w_v[kBlock];
  alignas(64) double dt_lane[kBlock], eps_lane[kBlock], omega_lane[kBlock];
#pragma GCC ivdep
  for (int l = 0; l < nb; ++l) {
    double r[4], z[4], vr[4], vz[4], mr[4], mz[4];
#pragma GCC unroll 4
    for (int i = 0; i < 4; ++i) {
      r[i] = xr[i * kBlock + l];
      z[i] = xz[i * kBlock + l];
      vr[i] = ur[i * kBlock + l];
      vz[i] = uz[i * kBlock + l];
      mr[i] = r[i] - 0.5 * dt * vr[i];
      mz[i] = z[i] - 0.5 * dt * vz[i];
    }
    // Rates at the mid-step configuration; objective (Hughes-Winget) stress update.
    const Quad4Geometry gm = quad4_geometry(mr, mz);
    const StrainRate rate = quad4_strain_rate(gm, vr, vz);
    AxisymTensor s{srr[l], szz[l], stt[l], srz[l]};
    rotate_hughes_winget(s, rate.spin * dt);
    const AxisymTensor s_old = s;
    const AxisymTensor de{rate.d.rr * dt, rate.d.zz * dt, rate.d.tt * dt, rate.d.rz * dt};
    const double vol_mid = kTwoPi * gm.omega;
    J2Plasticity::State state{eps_p[l]};
    const J2Plasticity::Increment inc = mat.update(s, state, de);
    eps_p[l] = state.eps_p;
    w_p[l] = vol_mid * inc.plastic_work;
    eps_lane[l] = state.eps_p;
    w_int[l] = 0.5 * vol_mid * (contract(s_old, de) + contract(s, de));
    srr[l] = s.rr;
    szz[l] = s.zz;
    stt[l] = s.tt;
    srz[l] = s.rz;
    // Forces and stable step at x^{n+1}.
    const Quad4Geometry g = quad4_geometry(r, z);
    omega_lane[l] = std::min(g.omega, g.area);
    const double length = characteristic_length(g);
    const double evol = trace(rate.d);
    const double s_bv = bulk_viscous_stress(evol, rho, c, length, b1, b2);
    w_v[l] = vol_mid * s_bv * evol * dt;
    s.rr += s_bv;
    s.zz += s_bv;
    s.tt += s_bv;
    double fr[4], fz[4];
    quad4_internal_forces(g, s, fr, fz);
    double gamma[4];
    hourglass_shape(g, r, z, gamma);
    const double k_hg =
        hourglass_stiffness(kappa, shear, kTwoPi * g.omega, quad4_gradient_norm2(g));
    double q_r = qr[l];
    double q_z = qz[l];
    w_hg[l] = hourglass_update(gamma, vr, vz, k_hg, dt, q_r, q_z, fr, fz);
    qr[l] = q_r;
    qz[l] = q_z;
#pragma GCC unroll 4
    for (int i = 0; i < 4; ++i) {
      f_r[i * kBlock + l] = fr[i];
      f_z[i * kBlock + l] = fz[i];
    }
    const double xi = bulk_viscous_damping_ratio(evol, c, length, b1, b2);
    dt_lane[l] = element_stable_time_step(length, c, xi);
  }
  for (int l = 0; l < nb; ++l) {
    sums.internal_work += w_int[l];
    sums.plastic_work += w_p[l];
    sums.hourglass_work += w_hg[l];
    sums.viscous_work += w_v[l];
    sums.dt_min = std::min(sums.dt_min, dt_lane[l]);
    sums.eps_p_max = std::max(sums.eps_p_max, eps_lane[l]);
    sums.omega_min = std::min(sums.omega_min, omega_lane[l]);
  }
}

// One pass over the elements [begin, end) of one body; fr/fz (nodal) receive -f_int. Compiled
// for AVX-512, AVX2 and the baseline (the block kernel is inlined into each); the loader picks
// the best the CPU has.
CORLAB_SIMD_CLONES void element_loop(const BodyParams& p,
                                     ElementState& es,
                                     int begin,
                                     int end,
                                     const double* __restrict r,
                                     const double* __restrict z,
                                     const double* __restrict vr,
                                     const double* __restrict vz,
                                     double* __restrict fr_out,
                                     double* __restrict fz_out,
                                     double dt,
                                     ElementSums& sums) {
  alignas(64) double xr[4][kBlock], xz[4][kBlock], ur[4][kBlock], uz[4][kBlock];
  alignas(64) double f_r[4][kBlock], f_z[4][kBlock];
  for (int e0 = begin; e0 < end; e0 += kBlock) {
    const int nb = std::min(kBlock, end - e0);
    const std::array<int, 4>* nd = es.nodes.data() + e0;
    for (int l = 0; l < nb; ++l) {
#pragma GCC unroll 4
      for (int i = 0; i < 4; ++i) {
        const int n = nd[l][i];
        xr[i][l] = r[n];
        xz[i][l] = z[n];
        ur[i][l] = vr[n];
        uz[i][l] = vz[n];
      }
    }
    const double omega_before = sums.omega_min;
    element_block(p, nb, &xr[0][0], &xz[0][0], &ur[0][0], &uz[0][0], es.srr.data() + e0,
                  es.szz.data() + e0, es.stt.data() + e0, es.srz.data() + e0, es.eps_p.data() + e0,
                  es.qr.data() + e0, es.qz.data() + e0, &f_r[0][0], &f_z[0][0], dt, sums);
    if (!(sums.omega_min > 0.0) && omega_before > 0.0) sums.bad_element = e0;
    for (int l = 0; l < nb; ++l) {
#pragma GCC unroll 4
      for (int i = 0; i < 4; ++i) {
        const int n = nd[l][i];
        fr_out[n] -= f_r[i][l];
        fz_out[n] -= f_z[i][l];
      }
    }
  }
}

// Sums of the nodal update.
struct NodeSums {
  double ke = 0.0;         // kinetic energy at t^n, product form [J]
  double ke_sphere = 0.0;  // same, sphere nodes only [J]
  double p_sphere = 0.0;   // sphere z-momentum at t^{n+1/2} [kg m/s]
  double mz_sphere = 0.0;  // sum of m z over the sphere at t^{n+1} [kg m]
};

// Central-difference nodal update: v^{n+1/2} = (v^{n-1/2} + dt_avg f/m) x free, x^{n+1} = x^n +
// dt v^{n+1/2}, forces zeroed for the next assembly. Vectorised (simd reductions), cloned.
CORLAB_SIMD_CLONES NodeSums node_update(int nn,
                                        double dt,
                                        double dt_avg,
                                        double* __restrict pr,
                                        double* __restrict pz,
                                        double* __restrict pvr,
                                        double* __restrict pvz,
                                        double* __restrict pfr,
                                        double* __restrict pfz,
                                        const double* __restrict pm,
                                        const double* __restrict pim,
                                        const double* __restrict pfree_r,
                                        const double* __restrict pfree_z,
                                        const double* __restrict psph) {
  double ke = 0.0, ke_sphere = 0.0, p_sphere = 0.0, mz_sphere = 0.0;
#pragma omp simd reduction(+ : ke, ke_sphere, p_sphere, mz_sphere)
  for (int i = 0; i < nn; ++i) {
    const double vr_new = (pvr[i] + dt_avg * pfr[i] * pim[i]) * pfree_r[i];
    const double vz_new = (pvz[i] + dt_avg * pfz[i] * pim[i]) * pfree_z[i];
    const double k_i = 0.5 * pm[i] * (pvr[i] * vr_new + pvz[i] * vz_new);
    ke += k_i;
    ke_sphere += k_i * psph[i];
    p_sphere += pm[i] * vz_new * psph[i];
    pvr[i] = vr_new;
    pvz[i] = vz_new;
    pr[i] += dt * vr_new;
    const double z_new = pz[i] + dt * vz_new;
    pz[i] = z_new;
    mz_sphere += pm[i] * z_new * psph[i];
    pfr[i] = 0.0;
    pfz[i] = 0.0;
  }
  return NodeSums{ke, ke_sphere, p_sphere, mz_sphere};
}

BodyParams body_params(const Material& m, const SolverConfig& s) {
  BodyParams p;
  p.material = J2Plasticity::from(m);
  p.density = m.density;
  p.wave_speed = m.dilatational_wave_speed();
  p.hourglass = s.hourglass;
  p.b1 = s.bulk_viscosity_linear;
  p.b2 = s.bulk_viscosity_quadratic;
  return p;
}

void check_mesh(const Mesh& mesh) {
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
  auto check_set = [&](const std::vector<int>& set, const char* name) {
    for (int n : set) {
      if (n < 0 || n >= nn) throw_invalid(name, n, fmt::format("a node index in [0, {})", nn));
    }
  };
  check_set(mesh.axis_nodes, "mesh.axis_nodes");
  check_set(mesh.base_nodes, "mesh.base_nodes");
  check_set(mesh.sphere_surface_nodes, "mesh.sphere_surface_nodes");
  check_set(mesh.substrate_surface_nodes, "mesh.substrate_surface_nodes");
  if (mesh.sphere_surface_nodes.empty()) {
    throw_invalid("mesh.sphere_surface_nodes", "empty", "the contact slave nodes");
  }
  if (mesh.substrate_surface_nodes.size() < 2) {
    throw_invalid("mesh.substrate_surface_nodes", "fewer than 2", "the contact master surface");
  }
}

}  // namespace

ImpactResult run_impact(const ImpactConfig& config,
                        const Mesh& mesh,
                        const SimulationControl& control) {
  validate(config);
  check_mesh(mesh);
  const auto wall_start = std::chrono::steady_clock::now();
  const int nn = mesh.num_nodes();
  const int ne = mesh.num_elements();
  const double v0 = config.impact.velocity;
  const double gap = config.impact.gap;
  const SolverConfig& sc = config.solver;

  // Nodal state (SoA). The sphere starts translated down by the gap: it just touches.
  std::vector<double> r(mesh.r), z(mesh.z), vr(nn, 0.0), vz(nn, 0.0);
  std::vector<double> fr(nn, 0.0), fz(nn, 0.0), mass(nn, 0.0), inv_mass(nn, 0.0);
  std::vector<double> free_r(nn, 1.0), free_z(nn, 1.0), is_sphere(nn, 0.0);
  for (int i = 0; i < nn; ++i) {
    if (mesh.node_body[i] == Body::kSphere) {
      is_sphere[i] = 1.0;
      z[i] -= gap;
      vz[i] = -v0;
    }
  }
  for (int i : mesh.axis_nodes) free_r[i] = 0.0;
  for (int i : mesh.base_nodes) {
    free_r[i] = 0.0;
    free_z[i] = 0.0;
    vz[i] = 0.0;
  }

  // Elements, sphere first (elastic or J2), then substrate.
  ElementState es;
  es.resize(static_cast<std::size_t>(ne));
  std::vector<int> original(static_cast<std::size_t>(ne));
  int n_sphere = 0;
  {
    int k = 0;
    for (int pass = 0; pass < 2; ++pass) {
      const Body want = pass == 0 ? Body::kSphere : Body::kSubstrate;
      for (int e = 0; e < ne; ++e) {
        if (mesh.element_body[e] != want) continue;
        es.nodes[k] = mesh.quads[e];
        original[k] = e;
        ++k;
      }
      if (pass == 0) n_sphere = k;
    }
  }
  const BodyParams sphere_p = body_params(config.sphere.material, sc);
  const BodyParams substrate_p = body_params(config.substrate.material, sc);

  // Lumped masses (rho V / 4 per node, V = 2 pi Omega exact) and the initial stable step.
  double dt_crit = std::numeric_limits<double>::infinity();
  for (int e = 0; e < ne; ++e) {
    const auto& nd = es.nodes[e];
    double xr[4], xz[4];
#pragma GCC unroll 4
    for (int i = 0; i < 4; ++i) {
      xr[i] = r[nd[i]];
      xz[i] = z[nd[i]];
    }
    const Quad4Geometry g = quad4_geometry(xr, xz);
    if (!(g.area > 0.0 && g.omega > 0.0)) {
      throw_invalid("mesh element", original[e], "counter-clockwise with positive area and volume");
    }
    const BodyParams& p = e < n_sphere ? sphere_p : substrate_p;
    const double m = p.density * kTwoPi * g.omega / 4.0;
#pragma GCC unroll 4
    for (int i = 0; i < 4; ++i) mass[nd[i]] += m;
    dt_crit =
        std::min(dt_crit, element_stable_time_step(characteristic_length(g), p.wave_speed, p.b1));
  }
  double sphere_mass = 0.0;
  for (int i = 0; i < nn; ++i) {
    if (!(mass[i] > 0.0)) throw_invalid("mesh node", i, "part of at least one element");
    inv_mass[i] = 1.0 / mass[i];
    sphere_mass += mass[i] * is_sphere[i];
  }
  double dt = sc.safety_factor * dt_crit;
  // The penalty is sized from the critical step itself, not from dt: the contact stiffness (and so
  // the penetration and e) must not change when only the safety factor does.
  const double dt_crit_initial = dt_crit;
  const double dt_initial = dt;

  // Contact: slaves on master segments, per-slave cursor and penalty stiffness.
  const std::vector<int>& slaves = mesh.sphere_surface_nodes;
  const std::vector<int>& masters = mesh.substrate_surface_nodes;
  const double z_axis_surface = z[masters[0]];  // substrate surface on the axis, for the crater
  const int n_seg = static_cast<int>(masters.size()) - 1;
  const int n_slave = static_cast<int>(slaves.size());
  std::vector<int> cursor(static_cast<std::size_t>(n_slave), 0);
  std::vector<double> k_pen(static_cast<std::size_t>(n_slave), 0.0);
  for (int s = 0; s < n_slave; ++s) {
    const int i = slaves[s];
    int seg = 0;
    while (seg < n_seg - 1 && r[masters[seg + 1]] < r[i]) ++seg;
    cursor[s] = seg;
    const int a = masters[seg];
    const int b = masters[seg + 1];
    const double xi = std::clamp((r[i] - r[a]) / (r[b] - r[a]), 0.0, 1.0);
    const double m_master = (1.0 - xi) * mass[a] + xi * mass[b];
    k_pen[s] = penalty_stiffness(sc.penalty_scale, mass[i], m_master, dt_crit_initial);
  }

  // Time control.
  const double t_start = gap / v0;
  const double t_hertz = hertz_reference(config).contact_time;
  const double t_max = sc.t_max > 0.0 ? sc.t_max : t_start + 20.0 * t_hertz;
  const double t_wave = 4.0 * config.sphere.radius / sphere_p.wave_speed;
  std::vector<double> field_times = config.output.field_times;
  std::sort(field_times.begin(), field_times.end());
  std::size_t next_field = 0;

  ImpactResult res;
  res.elements = ne;
  res.nodes = nn;
  res.time_step = dt_initial;
  res.h_contact = std::hypot(r[masters[1]] - r[masters[0]], z[masters[1]] - z[masters[0]]);
  const double e0 = 0.5 * sphere_mass * v0 * v0;
  res.energy_initial = e0;
  ImpactHistory& h = res.history;

  // Running quantities.
  double t = t_start;
  double dt_prev = 0.0;  // first update is the half step v^{1/2} = v^0 + dt/2 a^0 (a^0 = 0)
  double w_int = 0.0, w_p = 0.0, w_hg = 0.0, w_visc = 0.0, e_contact = 0.0, eps_p_max = 0.0;
  double force = 0.0, delta = 0.0, hysteresis = 0.0, balance_max = 0.0;
  double z_com_start = 0.0;
  for (int i = 0; i < nn; ++i) z_com_start += mass[i] * z[i] * is_sphere[i];
  z_com_start /= sphere_mass;
  bool touched = false, in_contact = false;
  double t_first = t_start, t_last = t_start;
  // Separation window.
  bool separated = false;
  double window = 0.0, window_start = 0.0, window_v_ref = 0.0, window_ke_int = 0.0;
  double final_ke_avg = 0.0, v_com = -v0, v_com_prev = -v0;
  long long step = 0;
  const int every = config.output.history_every;
  const auto& cancel = control.cancel;

  auto snapshot = [&](double time) {
    FieldSnapshot f;
    f.time = time;
    f.mesh = mesh;
    f.mesh.r = r;
    f.mesh.z = z;
    f.displacement_r.resize(nn);
    f.displacement_z.resize(nn);
    for (int i = 0; i < nn; ++i) {
      f.displacement_r[i] = r[i] - mesh.r[i];
      f.displacement_z[i] = z[i] - mesh.z[i];
    }
    f.velocity_r = vr;
    f.velocity_z = vz;
    f.von_mises.assign(ne, 0.0);
    f.pressure.assign(ne, 0.0);
    f.plastic_strain.assign(ne, 0.0);
    for (int e = 0; e < ne; ++e) {
      const AxisymTensor s{es.srr[e], es.szz[e], es.stt[e], es.srz[e]};
      f.von_mises[original[e]] = von_mises(s);
      f.pressure[original[e]] = -trace(s) / 3.0;
      f.plastic_strain[original[e]] = es.eps_p[e];
    }
    control.on_fields(time, f);
  };

  const double t_expect = t_start + 1.3 * t_hertz + t_wave;  // for the progress estimate [s]
  // A run cancelled before it starts does no work (the loop polls only every 256 steps).
  if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) {
    throw std::runtime_error("interrupted");
  }
  while (true) {
    // 1. Nodes: v^{n+1/2}, x^{n+1}; kinetic energy at t^n (product form, exact for the scheme).
    const double dt_avg = 0.5 * (dt_prev + dt);
    const NodeSums ns =
        node_update(nn, dt, dt_avg, r.data(), z.data(), vr.data(), vz.data(), fr.data(), fz.data(),
                    mass.data(), inv_mass.data(), free_r.data(), free_z.data(), is_sphere.data());
    const double ke = ns.ke;
    const double ke_sphere = ns.ke_sphere;
    const double p_sphere = ns.p_sphere;
    const double mz_sphere = ns.mz_sphere;
    v_com_prev = v_com;
    v_com = p_sphere / sphere_mass;  // at t^{n+1/2}
    // Energy balance at t^n.
    const double total = ke + w_int + w_hg + w_visc + e_contact;
    const double balance = (total - e0) / e0;
    balance_max = std::max(balance_max, std::abs(balance));
    if (step % every == 0) {
      h.time.push_back(t);
      h.contact_force.push_back(force);
      h.indentation.push_back(delta);
      h.sphere_velocity.push_back(-0.5 * (v_com + v_com_prev));
      h.kinetic_energy.push_back(ke);
      h.strain_energy.push_back(w_int - w_p);
      h.plastic_dissipation.push_back(w_p);
      h.hourglass_energy.push_back(w_hg);
      h.viscous_dissipation.push_back(w_visc);
      h.contact_energy.push_back(e_contact);
      h.energy_balance_error.push_back(balance);
    }
    // Sphere kinetic energy over the separation window (time average).
    if (separated) window_ke_int += ke_sphere * dt_avg;

    // 2. Elements: stresses and internal forces at t^{n+1}, next stable step.
    ElementSums sums;
    element_loop(sphere_p, es, 0, n_sphere, r.data(), z.data(), vr.data(), vz.data(), fr.data(),
                 fz.data(), dt, sums);
    element_loop(substrate_p, es, n_sphere, ne, r.data(), z.data(), vr.data(), vz.data(), fr.data(),
                 fz.data(), dt, sums);
    if (sums.bad_element >= 0) {
      throw std::runtime_error(fmt::format("element {} inverted at t = {:.6g} s (step {})",
                                           original[sums.bad_element], t + dt, step));
    }
    w_int += sums.internal_work;
    w_p += sums.plastic_work;
    w_hg += sums.hourglass_work;
    w_visc += sums.viscous_work;
    eps_p_max = std::max(eps_p_max, sums.eps_p_max);

    // 3. Contact at x^{n+1}.
    double f_new = 0.0;
    e_contact = 0.0;
    bool penetrating = false;
    for (int s = 0; s < n_slave; ++s) {
      const int i = slaves[s];
      int seg = cursor[s];
      SegmentProjection p;
      while (true) {
        const int a = masters[seg];
        const int b = masters[seg + 1];
        p = project_on_segment(r[i], z[i], r[a], z[a], r[b], z[b]);
        if (p.xi < 0.0 && seg > 0) {
          const int a2 = masters[seg - 1];
          const SegmentProjection q = project_on_segment(r[i], z[i], r[a2], z[a2], r[a], z[a]);
          if (q.xi <= 1.0) {
            --seg;
            continue;
          }
        } else if (p.xi > 1.0 && seg < n_seg - 1) {
          const int b2 = masters[seg + 2];
          const SegmentProjection q = project_on_segment(r[i], z[i], r[b], z[b], r[b2], z[b2]);
          if (q.xi >= 0.0) {
            ++seg;
            continue;
          }
        }
        break;
      }
      cursor[s] = seg;
      if (p.gap >= 0.0 || (p.xi > 1.0 + 1e-9 && seg == n_seg - 1)) continue;
      p.xi = std::clamp(p.xi, 0.0, 1.0);
      const int a = masters[seg];
      const int b = masters[seg + 1];
      e_contact += penalty_force(p, k_pen[s], fr[i], fz[i], fr[a], fz[a], fr[b], fz[b]);
      f_new += -k_pen[s] * p.gap * p.nz;
      res.penetration_max = std::max(res.penetration_max, -p.gap);
      penetrating = true;
    }
    const double delta_new = z_com_start - mz_sphere / sphere_mass;
    hysteresis += 0.5 * (force + f_new) * (delta_new - delta);
    force = f_new;
    delta = delta_new;
    res.force_max = std::max(res.force_max, force);
    res.indentation_max = std::max(res.indentation_max, delta);

    // 4. Advance time; contact bookkeeping and the stop test.
    t += dt;
    ++step;
    dt_prev = dt;
    dt = sc.safety_factor * sums.dt_min;
    if (!(dt > 1e-6 * dt_initial)) {
      throw std::runtime_error(fmt::format("stable time step collapsed at t = {:.6g} s", t));
    }
    if (penetrating) {
      if (!touched) t_first = t - dt_prev;
      touched = true;
      in_contact = true;
      t_last = t;
      if (separated) separated = false;  // re-contact: the window starts again
    } else if (in_contact) {
      in_contact = false;
    }
    if (touched && !in_contact && !separated) {
      separated = true;
      window = std::max(0.1 * (t_last - t_first), t_wave);
      window_start = t;
      window_v_ref = v_com;
      window_ke_int = 0.0;
    } else if (separated && t - window_start >= window) {
      const double change = std::abs(v_com - window_v_ref);
      final_ke_avg = window_ke_int / (t - window_start);
      if (change < 1e-4 * std::max(std::abs(v_com), 1e-3 * v0)) break;
      window_start = t;
      window_v_ref = v_com;
      window_ke_int = 0.0;
    }
    while (next_field < field_times.size() && t >= field_times[next_field]) {
      if (control.on_fields) snapshot(t);
      ++next_field;
    }
    if (t >= t_max) break;
    if ((step & 255) == 0) {
      if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) {
        throw std::runtime_error("interrupted");
      }
      if (control.progress) {
        control.progress(std::clamp((t - t_start) / (t_expect - t_start), 0.0, 0.99));
      }
    }
  }

  // Results.
  res.separated = separated;
  if (!separated) {
    // No separation before t_max: report the current state.
    double ke_s = 0.0;
    for (int i = 0; i < nn; ++i)
      ke_s += 0.5 * mass[i] * (vr[i] * vr[i] + vz[i] * vz[i]) * is_sphere[i];
    final_ke_avg = ke_s;
  }
  res.e = v_com / v0;
  res.e_energy = std::sqrt(std::max(final_ke_avg, 0.0) / e0);
  res.contact_time = touched ? t_last - t_first : 0.0;
  {
    // Residual depth on the axis: the substrate surface node at the smallest r.
    res.crater_depth = z_axis_surface - z[masters[0]];
  }
  res.plastic_strain_max = eps_p_max;
  res.energy_sphere_loss = e0 - final_ke_avg;
  res.energy_dissipated_plastic = w_p;
  res.energy_hourglass = w_hg;
  res.energy_viscous = w_visc;
  res.energy_balance_error = balance_max;
  res.hysteresis_area = hysteresis;
  res.steps = step;
  res.end_time = t;
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  res.element_steps_per_s = static_cast<double>(ne) * static_cast<double>(step) / res.wall_s;
  if (control.progress) control.progress(1.0);
  return res;
}

}  // namespace corlab::fem
