// The solver's hot loops (see element_loop.hpp). Compiled with -fopenmp-simd -fno-math-errno
// (src/CMakeLists.txt) so that the lane loops vectorise, and for each SimdLevel
// (simd_variants.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "fem/solver/element_loop.hpp"

#include <algorithm>
#include <cmath>

#include "corlab/core/units.hpp"
#include "corlab/fem/kernels/axisym_quad4.hpp"
#include "corlab/fem/kernels/bulk_viscosity.hpp"
#include "corlab/fem/kernels/hourglass.hpp"
#include "corlab/fem/kernels/objective_rate.hpp"
#include "corlab/fem/kernels/stable_time_step.hpp"
#include "fem/solver/lane_results.hpp"
#include "fem/solver/simd_variants.hpp"

namespace corlab::fem::solver {
namespace {

constexpr double kTwoPi = 2.0 * units::kPi;

// Elements per block of the element loop: gathered into lane arrays, computed lane-parallel
// (the pure kernels, inlined, vectorised across elements), then scattered.
constexpr int kBlock = 16;

// Bulk-viscous work of lane l over a step dt: the viscous stress at its end (kTrapezoid false),
// or the trapezoid of those at its start (bv[l], then updated) and end.
template <bool kTrapezoid>
[[gnu::always_inline]] inline double viscous_work(
    double* __restrict bv, int l, double vol, double s_bv, double evol, double dt) {
  if constexpr (kTrapezoid) {
    const double w = vol * 0.5 * (bv[l] + s_bv) * evol * dt;
    bv[l] = s_bv;
    return w;
  } else {
    return vol * s_bv * evol * dt;
  }
}

// One block of nb <= kBlock elements: gathered nodal positions x^{n+1} (xr, xz) and velocities
// v^{n+1/2} (ur, uz), [i * kBlock + lane]; the block's slices of the element state; f_r/f_z
// receive f_int.
struct Block {
  int nb;
  const double* __restrict xr;
  const double* __restrict xz;
  const double* __restrict ur;
  const double* __restrict uz;
  double* __restrict srr;
  double* __restrict szz;
  double* __restrict stt;
  double* __restrict srz;
  double* __restrict eps_p;
  double* __restrict qr;
  double* __restrict qz;
  double* __restrict bv;                // viscous mean stress at the last update (kTrapezoid only)
  const double* __restrict step_scale;  // stable step / the physical one (mass scaling)
  double* __restrict f_r;
  double* __restrict f_z;
};

// Gathered nodal values and computed forces of one block, [node i][lane].
struct BlockLanes {
  alignas(64) double xr[4][kBlock], xz[4][kBlock], ur[4][kBlock], uz[4][kBlock];
  alignas(64) double f_r[4][kBlock], f_z[4][kBlock];
};

// The block of nb elements from e0: its lanes and its slices of the element state (the viscous
// stress history only with `viscous_history`, i.e. subcycling) and of the step scales.
[[gnu::always_inline]] inline Block block_at(const double* step_scale,
                                             ElementState& es,
                                             int e0,
                                             int nb,
                                             BlockLanes& lanes,
                                             bool viscous_history) {
  return Block{nb,
               &lanes.xr[0][0],
               &lanes.xz[0][0],
               &lanes.ur[0][0],
               &lanes.uz[0][0],
               es.srr.data() + e0,
               es.szz.data() + e0,
               es.stt.data() + e0,
               es.srz.data() + e0,
               es.eps_p.data() + e0,
               es.qr.data() + e0,
               es.qz.data() + e0,
               viscous_history ? es.bv.data() + e0 : nullptr,
               step_scale + e0,
               &lanes.f_r[0][0],
               &lanes.f_z[0][0]};
}

// The node indices of the block from element e0, per corner: nd[i][l] is node i of lane l.
using BlockNodes = std::array<const int*, 4>;
[[gnu::always_inline]] inline BlockNodes block_nodes(const ElementConstants& ec, int e0) {
  return {ec.corner[0].data() + e0, ec.corner[1].data() + e0, ec.corner[2].data() + e0,
          ec.corner[3].data() + e0};
}

// What the stress update of one lane hands to its force computation.
struct LaneStress {
  AxisymTensor s;  // Cauchy stress after the update [Pa]
  double evol;     // volumetric strain rate trace d [1/s]
  double vol_mid;  // volume at the mid-step geometry [m^3]
};

// Stress update of lane l: rates at the mid-step geometry x^{n+1/2} (nodes r, z at x^{n+1},
// velocities vr, vz), objective (Hughes-Winget) rotation, J2 return; the block's stress and
// plastic strain updated, the lane's internal and plastic work into `out`.
[[gnu::always_inline]] inline LaneStress lane_stress(const J2Plasticity& mat,
                                                     const Block& b,
                                                     int l,
                                                     const double* r,
                                                     const double* z,
                                                     const double* vr,
                                                     const double* vz,
                                                     double dt,
                                                     LaneResults<kBlock>& out) {
  double mr[4], mz[4];
#pragma GCC unroll 4
  for (int i = 0; i < 4; ++i) {
    mr[i] = r[i] - 0.5 * dt * vr[i];
    mz[i] = z[i] - 0.5 * dt * vz[i];
  }
  const Quad4Geometry gm = quad4_geometry(mr, mz);
  const StrainRate rate = quad4_strain_rate(gm, vr, vz);
  AxisymTensor s{b.srr[l], b.szz[l], b.stt[l], b.srz[l]};
  rotate_hughes_winget(s, rate.spin * dt);
  const AxisymTensor s_old = s;
  const AxisymTensor de{rate.d.rr * dt, rate.d.zz * dt, rate.d.tt * dt, rate.d.rz * dt};
  const double vol_mid = kTwoPi * gm.omega;
  J2Plasticity::State state{b.eps_p[l]};
  const J2Plasticity::Increment inc = mat.update(s, state, de);
  b.eps_p[l] = state.eps_p;
  out.eps_p[l] = state.eps_p;
  out.w_p[l] = vol_mid * inc.plastic_work;
  out.w_int[l] = 0.5 * vol_mid * (contract(s_old, de) + contract(s, de));
  b.srr[l] = s.rr;
  b.szz[l] = s.zz;
  b.stt[l] = s.tt;
  b.srz[l] = s.rz;
  return LaneStress{s, trace(rate.d), vol_mid};
}

// The lane-parallel part of one block: stress update at the mid-step geometry x^{n+1/2}
// (lane_stress), bulk viscosity, internal + hourglass forces at x^{n+1} into b.f_r/f_z, and the
// stable step (kStableStep; a subcycled pass whose step is not used skips it); the block's sums
// added to `sums`. kTrapezoid (subcycling): the viscous work over the step is the trapezoid of
// the viscous stress at its start (b.bv, updated) and end, the rule that matches the
// product-form kinetic energy; else the stress at its end (as before subcycling).
// kKeepSteps (in-run mass scaling): each lane's stable step also into step_out[lane]. e0: the
// block's first element (for sums.bad_element).
template <bool kTrapezoid, bool kStableStep, bool kKeepSteps = false>
[[gnu::always_inline]] inline void element_block(const BodyParams& p,
                                                 const Block& b,
                                                 int e0,
                                                 double dt,
                                                 ElementSums& sums,
                                                 double* step_out = nullptr) {
  const double c = p.wave_speed;
  LaneResults<kBlock> out;
#pragma GCC ivdep
  for (int l = 0; l < b.nb; ++l) {
    double r[4], z[4], vr[4], vz[4];
#pragma GCC unroll 4
    for (int i = 0; i < 4; ++i) {
      r[i] = b.xr[i * kBlock + l];
      z[i] = b.xz[i * kBlock + l];
      vr[i] = b.ur[i * kBlock + l];
      vz[i] = b.uz[i * kBlock + l];
    }
    LaneStress ls = lane_stress(p.material, b, l, r, z, vr, vz, dt, out);
    const Quad4Geometry g = quad4_geometry(r, z);
    out.omega[l] = std::min(g.omega, g.area);
    const double length = characteristic_length(g);
    const double s_bv = bulk_viscous_stress(ls.evol, p.density, c, length, p.b1, p.b2);
    out.w_v[l] = viscous_work<kTrapezoid>(b.bv, l, ls.vol_mid, s_bv, ls.evol, dt);
    ls.s.rr += s_bv;
    ls.s.zz += s_bv;
    ls.s.tt += s_bv;
    double fr[4], fz[4];
    quad4_internal_forces(g, ls.s, fr, fz);
    double gamma[4];
    hourglass_shape(g, r, z, gamma);
    const double k_hg = hourglass_stiffness(p.hourglass, p.material.shear_modulus, kTwoPi * g.omega,
                                            quad4_gradient_norm2(g));
    out.w_hg[l] = hourglass_update(gamma, vr, vz, k_hg, dt, b.qr[l], b.qz[l], fr, fz);
#pragma GCC unroll 4
    for (int i = 0; i < 4; ++i) {
      b.f_r[i * kBlock + l] = fr[i];
      b.f_z[i * kBlock + l] = fz[i];
    }
    if constexpr (kStableStep) {
      const double xi = bulk_viscous_damping_ratio(ls.evol, c, length, p.b1, p.b2);
      // A scaled element's wave speed is c / step_scale; its viscous damping ratio is below xi,
      // so keeping xi errs on the safe side.
      out.dt[l] = element_stable_time_step(length, c, xi) * b.step_scale[l];
    }
  }
  add_lane_sums<kStableStep>(out, e0, b.nb, sums);
  if constexpr (kKeepSteps) std::copy_n(out.dt, b.nb, step_out);
}

// One pass over the elements of `pass` (element_loop.hpp): gather, the block kernel, scatter.
// kSubcycled (element_loop_subcycled): the rate from each element's own interval (its stored
// positions, updated), the trapezoidal viscous work, and scale x f_int scattered.
template <bool kSubcycled>
[[gnu::always_inline]] inline void pass_body(const ElementPass& pass,
                                             double scale,
                                             bool stable_step,
                                             ElementSums& sums) {
  // Copies, not references into `pass`: the loop's stores could alias a referenced field.
  const BodyParams& p = pass.body;
  const ElementConstants& ec = pass.elements;
  const double* step_scale =
      pass.step_scale != nullptr ? pass.step_scale : pass.elements.step_scale.data();
  double* const step_out = pass.step_out;
  ElementState& es = pass.state;
  const int begin = pass.begin;
  const int end = pass.end;
  const NodalArrays x = pass.x;
  const double dt = pass.dt;
  const double* __restrict r = x.r;
  const double* __restrict z = x.z;
  const double* __restrict vr = x.vr;
  const double* __restrict vz = x.vz;
  double* __restrict fr_out = x.fr;
  double* __restrict fz_out = x.fz;
  BlockLanes lanes;
  auto& [xr, xz, ur, uz, f_r, f_z] = lanes;
  const double inv_dt = 1.0 / dt;
  for (int e0 = begin; e0 < end; e0 += kBlock) {
    const int nb = std::min(kBlock, end - e0);
    const BlockNodes nd = block_nodes(ec, e0);
    // lanes.*, not the bindings: clang rejects structured bindings inside omp simd.
    for (int i = 0; i < 4; ++i) {
      const int* __restrict ni = nd[i];
      if constexpr (kSubcycled) {
        double* __restrict rp = es.r_prev[i].data() + e0;
        double* __restrict zp = es.z_prev[i].data() + e0;
#pragma omp simd
        for (int l = 0; l < nb; ++l) {
          const int n = ni[l];
          const double rn = r[n];
          const double zn = z[n];
          lanes.xr[i][l] = rn;
          lanes.xz[i][l] = zn;
          lanes.ur[i][l] = (rn - rp[l]) * inv_dt;
          lanes.uz[i][l] = (zn - zp[l]) * inv_dt;
          rp[l] = rn;
          zp[l] = zn;
        }
      } else {
#pragma omp simd
        for (int l = 0; l < nb; ++l) {
          const int n = ni[l];
          lanes.xr[i][l] = r[n];
          lanes.xz[i][l] = z[n];
          lanes.ur[i][l] = vr[n];
          lanes.uz[i][l] = vz[n];
        }
      }
    }
    const Block b = block_at(step_scale, es, e0, nb, lanes, kSubcycled);
    if (!kSubcycled && step_out != nullptr) {
      element_block<false, true, true>(p, b, e0, dt, sums, step_out + e0);
    } else if (!kSubcycled || stable_step) {
      element_block<kSubcycled, true>(p, b, e0, dt, sums);
    } else {
      element_block<kSubcycled, false>(p, b, e0, dt, sums);
    }
    // Element by element (nodes are shared): the order of each node's sum is the element order.
    for (int l = 0; l < nb; ++l) {
#pragma GCC unroll 4
      for (int i = 0; i < 4; ++i) {
        const int n = nd[i][l];
        if constexpr (kSubcycled) {
          fr_out[n] -= scale * f_r[i][l];
          fz_out[n] -= scale * f_z[i][l];
        } else {
          fr_out[n] -= f_r[i][l];
          fz_out[n] -= f_z[i][l];
        }
      }
    }
  }
}

// The subcycled nodal update's pass over `count` nodes: node order[k] (kListed) or k
// (contiguous). In the contiguous pass a node of scale above due_scale is not due: it has no
// force (none of its elements updated) and a zero step.
template <bool kListed>
[[gnu::always_inline]] inline NodeSums subcycled_node_pass(const SubcycledNodes& a,
                                                           int count,
                                                           double due_scale) {
  const int* __restrict order = a.order;
  double* __restrict pr = a.x.r;
  double* __restrict pz = a.x.z;
  double* __restrict pvr = a.x.vr;
  double* __restrict pvz = a.x.vz;
  double* __restrict pfr = a.x.fr;
  double* __restrict pfz = a.x.fz;
  const double* __restrict pm = a.x.m;
  const double* __restrict pim = a.x.im;
  const double* __restrict pfree_r = a.x.free_r;
  const double* __restrict pfree_z = a.x.free_z;
  const double* __restrict psph = a.x.sphere;
  const double* __restrict pscale = a.scale;
  const double dt_avg = a.dt_avg;
  const double dt = a.step[0];
  double ke = 0.0, ke_sphere = 0.0, p_sphere = 0.0, mz_sphere = 0.0;
#pragma omp simd reduction(+ : ke, ke_sphere, p_sphere, mz_sphere)
  for (int k = 0; k < count; ++k) {
    const int i = kListed ? order[k] : k;
    const double h = kListed || pscale[i] <= due_scale ? dt * pscale[i] : 0.0;
    const double vr_new = (pvr[i] + dt_avg * pfr[i] * pim[i]) * pfree_r[i];
    const double vz_new = (pvz[i] + dt_avg * pfz[i] * pim[i]) * pfree_z[i];
    const double k_i = 0.5 * pm[i] * (pvr[i] * vr_new + pvz[i] * vz_new);
    ke += k_i;
    ke_sphere += k_i * psph[i];
    p_sphere += pm[i] * vz_new * psph[i];
    mz_sphere += pm[i] * pz[i] * psph[i];
    pvr[i] = vr_new;
    pvz[i] = vz_new;
    pr[i] += h * vr_new;
    pz[i] += h * vz_new;
    pfr[i] = 0.0;
    pfz[i] = 0.0;
  }
  return NodeSums{ke, ke_sphere, p_sphere, mz_sphere};
}

// Central-difference nodal update (element_loop.hpp), vectorised with simd reductions.
// The arrays are restrict-qualified parameters here, not locals copied from NodalArrays: that
// loop is 6 % shorter (callgrind, x86-64-v3).
[[gnu::always_inline]] inline NodeSums node_update_body(int nn,
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

}  // namespace

CORLAB_SIMD_VARIANTS(void,
                     element_loop,
                     (const ElementPass& pass, ElementSums& sums),
                     (pass, sums),
                     pass_body<false>(pass, 1.0, true, sums))

CORLAB_SIMD_VARIANTS(void,
                     element_loop_subcycled,
                     (const ElementPass& pass, double scale, bool stable_step, ElementSums& sums),
                     (pass, scale, stable_step, sums),
                     pass_body<true>(pass, scale, stable_step, sums))

CORLAB_SIMD_VARIANTS(NodeSums,
                     node_update_subcycled,
                     (const SubcycledNodes& a),
                     (a),
                     subcycled_node_pass<true>(a, a.count, 0.0))

CORLAB_SIMD_VARIANTS(NodeSums,
                     node_update_due,
                     (const SubcycledNodes& a, int nn, int due_level),
                     (a, nn, due_level),
                     subcycled_node_pass<false>(a, nn, static_cast<double>(1 << due_level)))

CORLAB_SIMD_VARIANTS(
    NodeSums,
    node_update,
    (const NodalArrays& x, int nn, double dt, double dt_avg),
    (x, nn, dt, dt_avg),
    node_update_body(
        nn, dt, dt_avg, x.r, x.z, x.vr, x.vz, x.fr, x.fz, x.m, x.im, x.free_r, x.free_z, x.sphere))

}  // namespace corlab::fem::solver
