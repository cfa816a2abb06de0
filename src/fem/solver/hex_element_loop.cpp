// The 3-D solver's element pass (hex_element_loop.hpp). Compiled with -fopenmp-simd
// -fno-math-errno (src/CMakeLists.txt), like element_loop.cpp, so that the lane loop vectorises.
// SPDX-License-Identifier: BSD-3-Clause
#include "fem/solver/hex_element_loop.hpp"

#include <algorithm>
#include <cstddef>

#include "corlab/fem/kernels/bulk_viscosity.hpp"
#include "corlab/fem/kernels/hex8.hpp"
#include "corlab/fem/kernels/hourglass.hpp"
#include "corlab/fem/kernels/j2_plasticity.hpp"
#include "corlab/fem/kernels/objective_rate.hpp"
#include "corlab/fem/kernels/stable_time_step.hpp"
#include "corlab/fem/kernels/sym_tensor3.hpp"
#include "fem/solver/lane_results.hpp"
#include "fem/solver/simd_variants.hpp"

namespace corlab::fem::hex_solver {
namespace {

// Elements per block: two AVX-512 vectors of doubles per nodal value (1.1x over one, measured).
constexpr int kBlock = 16;

// The gathered nodal values of a block and the forces its lanes compute, [corner][lane].
struct HexLanes {
  alignas(64) double x[8][kBlock], y[8][kBlock], z[8][kBlock];
  alignas(64) double vx[8][kBlock], vy[8][kBlock], vz[8][kBlock];
  alignas(64) double fx[8][kBlock], fy[8][kBlock], fz[8][kBlock];
};

using HexLaneResults = solver::LaneResults<kBlock>;

// One body's constants for the lane loop.
struct HexBody {
  J2Plasticity material;
  double density;     // [kg/m^3]
  double wave_speed;  // [m/s]
  double b1, b2;      // bulk viscosity [-]
  double kappa_hg;    // hourglass coefficient [-]
};

// The element state of the block starting at e0.
struct HexBlockState {
  double* __restrict stress[6];  // xx, yy, zz, xy, yz, zx [Pa]
  double* __restrict eps_p;
  double* __restrict q[12];  // hourglass Q[d][a] at d * 4 + a [N]
};

[[gnu::always_inline]] inline HexBlockState block_state(HexState& s, std::size_t e0) {
  HexBlockState b{};
  for (int c = 0; c < 6; ++c) b.stress[c] = s.stress[static_cast<std::size_t>(c)].data() + e0;
  b.eps_p = s.eps_p.data() + e0;
  for (int k = 0; k < 12; ++k) b.q[k] = s.hourglass[static_cast<std::size_t>(k)].data() + e0;
  return b;
}

// Stress update of lane l at the mid-step geometry; returns the rates' volumetric part and
// writes the lane's works and plastic strain.
[[gnu::always_inline]] inline double lane_stress(const HexBody& p,
                                                 const HexBlockState& b,
                                                 int l,
                                                 const Hex8Geometry& gm,
                                                 const double* vx,
                                                 const double* vy,
                                                 const double* vz,
                                                 double dt,
                                                 SymTensor3& sigma,
                                                 HexLaneResults& out) {
  const StrainRate3 rate = hex8_strain_rate(gm, vx, vy, vz);
  const SymTensor3 de{rate.d.xx * dt, rate.d.yy * dt, rate.d.zz * dt,
                      rate.d.xy * dt, rate.d.yz * dt, rate.d.zx * dt};
  sigma = {b.stress[0][l], b.stress[1][l], b.stress[2][l],
           b.stress[3][l], b.stress[4][l], b.stress[5][l]};
  rotate_hughes_winget(sigma, Spin3{rate.spin.x * dt, rate.spin.y * dt, rate.spin.z * dt});
  const SymTensor3 old = sigma;
  J2Plasticity::State state{b.eps_p[l]};
  const J2Plasticity::Increment inc = p.material.update(sigma, state, de);
  b.eps_p[l] = state.eps_p;
  out.eps_p[l] = state.eps_p;
  out.w_int[l] = 0.5 * gm.volume * (contract(old, de) + contract(sigma, de));
  out.w_p[l] = inc.plastic_work * gm.volume;
  b.stress[0][l] = sigma.xx;
  b.stress[1][l] = sigma.yy;
  b.stress[2][l] = sigma.zz;
  b.stress[3][l] = sigma.xy;
  b.stress[4][l] = sigma.yz;
  b.stress[5][l] = sigma.zx;
  return trace(rate.d);
}

// Hourglass forces of lane l added to f*, its work into `out`.
[[gnu::always_inline]] inline void lane_hourglass(const HexBody& p,
                                                  const HexBlockState& b,
                                                  int l,
                                                  const Hex8Geometry& g,
                                                  const double* const (&pos)[3],
                                                  const double* const (&vel)[3],
                                                  double dt,
                                                  double* fx,
                                                  double* fy,
                                                  double* fz,
                                                  HexLaneResults& out) {
  double gamma[4][8];
  hex8_hourglass_shape(g, pos[0], pos[1], pos[2], gamma);
  const double k_hg =
      hourglass_stiffness(p.kappa_hg, p.material.shear_modulus, g.volume, hex8_gradient_norm2(g));
  Hex8HourglassForce q;
#pragma GCC unroll 12
  for (int k = 0; k < 12; ++k) q.q[k / 4][k % 4] = b.q[k][l];
  out.w_hg[l] = hex8_hourglass_update(gamma, vel[0], vel[1], vel[2], k_hg, dt, q, fx, fy, fz);
#pragma GCC unroll 12
  for (int k = 0; k < 12; ++k) b.q[k][l] = q.q[k / 4][k % 4];
}

// Lane l of a block: one element's update (stress, forces, stable step).
[[gnu::always_inline]] inline void lane_update(
    const HexBody& p, const HexBlockState& b, HexLanes& ln, int l, double dt, HexLaneResults& out) {
  double x[8], y[8], z[8], vx[8], vy[8], vz[8], mx[8], my[8], mz[8];
#pragma GCC unroll 8
  for (int i = 0; i < 8; ++i) {
    x[i] = ln.x[i][l];
    y[i] = ln.y[i][l];
    z[i] = ln.z[i][l];
    vx[i] = ln.vx[i][l];
    vy[i] = ln.vy[i][l];
    vz[i] = ln.vz[i][l];
    mx[i] = x[i] - 0.5 * dt * vx[i];
    my[i] = y[i] - 0.5 * dt * vy[i];
    mz[i] = z[i] - 0.5 * dt * vz[i];
  }
  const Hex8Geometry gm = hex8_geometry(mx, my, mz);
  const Hex8Geometry g = hex8_geometry(x, y, z);
  out.omega[l] = std::min(g.volume, gm.volume);
  SymTensor3 sigma;
  const double vol_rate = lane_stress(p, b, l, gm, vx, vy, vz, dt, sigma, out);
  const double length = hex8_characteristic_length(g);
  const double viscous = bulk_viscous_stress(vol_rate, p.density, p.wave_speed, length, p.b1, p.b2);
  out.w_v[l] = viscous * vol_rate * dt * gm.volume;
  sigma.xx += viscous;
  sigma.yy += viscous;
  sigma.zz += viscous;
  double fx[8] = {};
  double fy[8] = {};
  double fz[8] = {};
  hex8_add_internal_force(g, sigma, fx, fy, fz);
  lane_hourglass(p, b, l, g, {x, y, z}, {vx, vy, vz}, dt, fx, fy, fz, out);
#pragma GCC unroll 8
  for (int i = 0; i < 8; ++i) {
    ln.fx[i][l] = fx[i];
    ln.fy[i][l] = fy[i];
    ln.fz[i][l] = fz[i];
  }
  const double xi = bulk_viscous_damping_ratio(vol_rate, p.wave_speed, length, p.b1, p.b2);
  out.dt[l] = element_stable_time_step(length, p.wave_speed, xi);
}

// Generic vectors (GCC, Clang): the shuffles below compile to the instruction set of the SIMD level
// the pass is inlined into (two-source permutes at x86-64-v4; at lower levels plain moves).
using V2 = double __attribute__((vector_size(16)));
using V4 = double __attribute__((vector_size(32)));
using V8 = double __attribute__((vector_size(64)));
static_assert(sizeof(NodeKinematics) == 6 * sizeof(double) &&
                  offsetof(NodeKinematics, vy) == 4 * sizeof(double),
              "gather_eight reads a node record as x, y, z, vx then vy, vz");

// Corner i of the eight lanes [l0, l0 + 8) of a full block: the eight node records loaded as
// vectors and transposed into the lanes (x, y, z, vx in two permute stages, vy, vz in one)
// instead of 48 scalar loads and stores.
[[gnu::always_inline]] inline void gather_eight(
    const HexState& s, const int* nodes, int i, int l0, HexLanes& ln) {
  V8 p[4];
  V4 q[4];
#pragma GCC unroll 4
  for (int k = 0; k < 4; ++k) {
    // Each record's first four values (x, y, z, vx) and last two (vy, vz).
    V4 head[2];
    V2 tail[2];
#pragma GCC unroll 2
    for (int j = 0; j < 2; ++j) {
      const NodeKinematics& r = s.node[static_cast<std::size_t>(nodes[l0 + 2 * k + j])];
      __builtin_memcpy(&head[j], &r, sizeof(V4));
      __builtin_memcpy(&tail[j], reinterpret_cast<const char*>(&r) + offsetof(NodeKinematics, vy),
                       sizeof(V2));
    }
    p[k] = __builtin_shufflevector(head[0], head[1], 0, 1, 2, 3, 4, 5, 6, 7);
    q[k] = __builtin_shufflevector(tail[0], tail[1], 0, 1, 2, 3);
  }
  // lo: lanes 0-3, hi: lanes 4-7; [x of 4 lanes, y of 4 lanes] and [z ..., vx ...].
  const V8 xy_lo = __builtin_shufflevector(p[0], p[1], 0, 4, 8, 12, 1, 5, 9, 13);
  const V8 zv_lo = __builtin_shufflevector(p[0], p[1], 2, 6, 10, 14, 3, 7, 11, 15);
  const V8 xy_hi = __builtin_shufflevector(p[2], p[3], 0, 4, 8, 12, 1, 5, 9, 13);
  const V8 zv_hi = __builtin_shufflevector(p[2], p[3], 2, 6, 10, 14, 3, 7, 11, 15);
  const V8 t_lo = __builtin_shufflevector(q[0], q[1], 0, 1, 2, 3, 4, 5, 6, 7);
  const V8 t_hi = __builtin_shufflevector(q[2], q[3], 0, 1, 2, 3, 4, 5, 6, 7);
  const V8 out[6] = {__builtin_shufflevector(xy_lo, xy_hi, 0, 1, 2, 3, 8, 9, 10, 11),
                     __builtin_shufflevector(xy_lo, xy_hi, 4, 5, 6, 7, 12, 13, 14, 15),
                     __builtin_shufflevector(zv_lo, zv_hi, 0, 1, 2, 3, 8, 9, 10, 11),
                     __builtin_shufflevector(zv_lo, zv_hi, 4, 5, 6, 7, 12, 13, 14, 15),
                     __builtin_shufflevector(t_lo, t_hi, 0, 2, 4, 6, 8, 10, 12, 14),
                     __builtin_shufflevector(t_lo, t_hi, 1, 3, 5, 7, 9, 11, 13, 15)};
  double* dst[6] = {ln.x[i], ln.y[i], ln.z[i], ln.vx[i], ln.vy[i], ln.vz[i]};
#pragma GCC unroll 6
  for (int c = 0; c < 6; ++c) __builtin_memcpy(dst[c] + l0, &out[c], sizeof(V8));
}

static_assert(kBlock % 8 == 0, "gather_eight fills a full block eight lanes at a time");

// Gathers the block's nodal values into the lanes: at x86-64-v4 a full block eight lanes at a
// time (gather_eight: 1.03-1.12x in BM_HexThroughput; at x86-64-v3 its 512-bit permutes split into
// 256-bit ones and it ran 0.67x, docs/dev/performance.md), else value by value. Both copy bits:
// the results do not depend on which.
template <SimdLevel kLevel>
[[gnu::always_inline]] inline void gather(
    const HexModel& m, const HexState& s, std::size_t e0, int nb, HexLanes& ln) {
  if (kLevel == SimdLevel::kX86_64_V4 && nb == kBlock) {
    for (int i = 0; i < 8; ++i) {
      const int* nodes = m.corner[static_cast<std::size_t>(i)].data() + e0;
#pragma GCC unroll 2
      for (int l0 = 0; l0 < kBlock; l0 += 8) gather_eight(s, nodes, i, l0, ln);
    }
    return;
  }
  for (int i = 0; i < 8; ++i) {
    const int* nodes = m.corner[static_cast<std::size_t>(i)].data() + e0;
    for (int l = 0; l < nb; ++l) {
      const auto n = static_cast<std::size_t>(nodes[l]);
      ln.x[i][l] = s.node[n].x;
      ln.y[i][l] = s.node[n].y;
      ln.z[i][l] = s.node[n].z;
      ln.vx[i][l] = s.node[n].vx;
      ln.vy[i][l] = s.node[n].vy;
      ln.vz[i][l] = s.node[n].vz;
    }
  }
}

// Subtracts the block's forces from the nodes, element by element (each node's sum in element
// order, so its bits do not depend on the block size) and adds its lanes' results to `sums`.
[[gnu::always_inline]] inline void scatter(const HexModel& m,
                                           HexState& s,
                                           std::size_t e0,
                                           int nb,
                                           const HexLanes& ln,
                                           const HexLaneResults& out,
                                           solver::ElementSums& sums) {
  for (int l = 0; l < nb; ++l) {
    for (int i = 0; i < 8; ++i) {
      const auto n = static_cast<std::size_t>(m.corner[static_cast<std::size_t>(i)][e0 + l]);
      s.nodal_force[n].x -= ln.fx[i][l];
      s.nodal_force[n].y -= ln.fy[i][l];
      s.nodal_force[n].z -= ln.fz[i][l];
    }
  }
  solver::add_lane_sums<true>(out, static_cast<int>(e0), nb, sums);
}

// Prefetch of the cache line at p. An asm statement on x86-64: GCC drops __builtin_prefetch from
// the loops it vectorises.
[[gnu::always_inline]] inline void prefetch(const void* p) {
#if defined(__GNUC__) && defined(__x86_64__)
  asm volatile("prefetcht0 %0" : : "m"(*static_cast<const char*>(p)));
#else
  __builtin_prefetch(p);
#endif
}

// Blocks ahead that prefetch_block_state fetches (1 and 3 measured alike).
constexpr std::size_t kPrefetchBlocks = 2;

// Prefetches the element state and node indices of the block kPrefetchBlocks ahead of e0: 19
// state arrays and 8 index arrays are more streams than the hardware prefetcher follows (1.06x
// in BM_HexThroughput, docs/dev/performance.md). The caller keeps e0 + (kPrefetchBlocks + 1) x
// kBlock within the run, so that every address lies inside its array.
[[gnu::always_inline]] inline void prefetch_block_state(const HexModel& m,
                                                        const HexState& s,
                                                        std::size_t e0) {
  const std::size_t ahead = e0 + kPrefetchBlocks * kBlock;
  for (const Vec* a : {&s.stress[0], &s.stress[1], &s.stress[2], &s.stress[3], &s.stress[4],
                       &s.stress[5], &s.eps_p}) {
    prefetch(a->data() + ahead);
    prefetch(a->data() + ahead + 8);
  }
  for (const Vec& a : s.hourglass) {
    prefetch(a.data() + ahead);
    prefetch(a.data() + ahead + 8);
  }
  for (const std::vector<int>& c : m.corner) prefetch(c.data() + ahead);
}

[[gnu::always_inline]] inline HexBody body_constants(const HexModel& m, Body body) {
  const BodyMaterial& b = m.bodies[static_cast<std::size_t>(body)];
  const SolverConfig& sc = *m.solver;
  return HexBody{b.material,
                 b.density,
                 b.wave_speed,
                 sc.bulk_viscosity_linear,
                 sc.bulk_viscosity_quadratic,
                 sc.hourglass_3d};
}

template <SimdLevel kLevel>
[[gnu::always_inline]] inline solver::ElementSums pass_body(const HexModel& m,
                                                            HexState& s,
                                                            double dt) {
  solver::ElementSums sums;
  HexLanes ln;
  HexLaneResults out;
  for (const HexElementRun& run : m.runs) {
    const HexBody p = body_constants(m, run.body);
    for (std::size_t e0 = run.begin; e0 < run.end; e0 += kBlock) {
      const int nb = static_cast<int>(std::min<std::size_t>(kBlock, run.end - e0));
      if (e0 + (kPrefetchBlocks + 1) * kBlock <= run.end) prefetch_block_state(m, s, e0);
      gather<kLevel>(m, s, e0, nb, ln);
      const HexBlockState b = block_state(s, e0);
#pragma GCC ivdep
      for (int l = 0; l < nb; ++l) lane_update(p, b, ln, l, dt, out);
      scatter(m, s, e0, nb, ln, out, sums);
    }
  }
  return sums;
}

}  // namespace

CORLAB_SIMD_VARIANTS(solver::ElementSums,
                     hex_element_pass,
                     (const HexModel& m, HexState& s, double dt),
                     (m, s, dt),
                     pass_body<kSimdLevel>(m, s, dt))

}  // namespace corlab::fem::hex_solver
