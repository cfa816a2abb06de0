// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file spline_surface.hpp
/// Projection of a slave node on a smooth master surface through the nodes of a structured grid
/// (the 3-D model's block top): the tensor-product Catmull-Rom spline (Catmull & Rom 1974), the
/// cubic Hermite patch whose tangents at the nodes are the central differences of their
/// neighbours. The node (a, b) of the grid sits at parameters (u, v) = (a, b); the patch
/// [k, k + 1] x [l, l + 1] is x(u, v) = sum_ab C_a(u - k) C_b(v - l) P_(k-1+a, l-1+b) over the
/// sixteen nodes a, b = 0 .. 3, with
///   C_0 = (-t^3 + 2 t^2 - t)/2, C_1 = (3 t^3 - 5 t^2 + 2)/2, C_2 = (-3 t^3 + 4 t^2 + t)/2,
///   C_3 = (t^3 - t^2)/2.
/// The surface passes through the nodes, is C1 (its normal is continuous: no kinks between faces)
/// and reproduces quadratic surfaces exactly, so it stands O(h^3) off a smooth indentation where
/// the nodes' facets stand O(h^2).
///
/// The closest point (u, v) is found by Gauss-Newton on (x - p) . x_u = (x - p) . x_v = 0; there
/// p - x = g n with n = x_u x x_v / |x_u x x_v|, so the gap g is the signed distance and its exact
/// gradient is dg/dp = n, dg/dP_ab = -C_a(u) C_b(v) n (the terms through u, v vanish at the
/// closest point). A penalty force f n on the slave with -C_a C_b f n on the nodes is therefore
/// -d(1/2 k g^2)/d(positions): the contact is conservative, and its normal is smooth. (The
/// weights sum to 1, the outer ones are slightly negative.)

#include <cmath>

namespace corlab::fem {

/// The Catmull-Rom weights at t = u - k in [0, 1] of the nodes k - 1 .. k + 2, and their
/// derivatives d/du [-].
struct CatmullRomWeights {
  double w[4];
  double dw[4];
};

/// The weights at t [-]: they sum to 1 and reproduce u = k + t and u^2.
inline CatmullRomWeights catmull_rom(double t) {
  const double t2 = t * t;
  const double t3 = t2 * t;
  return {{0.5 * (-t3 + 2.0 * t2 - t), 0.5 * (3.0 * t3 - 5.0 * t2 + 2.0),
           0.5 * (-3.0 * t3 + 4.0 * t2 + t), 0.5 * (t3 - t2)},
          {0.5 * (-3.0 * t2 + 4.0 * t - 1.0), 0.5 * (9.0 * t2 - 10.0 * t),
           0.5 * (-9.0 * t2 + 8.0 * t + 1.0), 0.5 * (3.0 * t2 - 2.0 * t)}};
}

/// Where a slave meets the spline surface.
struct SplineProjection {
  double gap = 0.0;                    ///< signed normal distance [m] (< 0: penetration)
  double normal[3] = {0.0, 0.0, 1.0};  ///< unit normal x_u x x_v at the closest point [-]
  /// C_a(u - k) C_b(v - l) of the node (k - 1 + a, l - 1 + b), at a + 4 b [-]
  double weight[16] = {};
  double u = 0.0;  ///< parameters of the closest point [-]
  double v = 0.0;
  long k = 0;  ///< the patch [k, k + 1] x [l, l + 1]
  long l = 0;
};

/// The parameter range the projection keeps to [-]: u in [u_min, u_max], v in [v_min, v_max].
struct SplineDomain {
  double u_min, u_max, v_min, v_max;
};

/// Projects p [m] on the surface from the start parameters (u, v) [-]. control(a, b, x) writes
/// the node (a, b) [m], for a from floor(u_min) - 1 to ceil(u_max) + 1 and b likewise (the
/// caller's ghost points beyond the grid's edges). A closest point outside the domain is clamped
/// to it: there the force is no longer the gap's gradient, so the domain has to cover every
/// contact.
template <class Control>
SplineProjection project_on_spline_surface(
    const double* p, double u, double v, const SplineDomain& domain, Control&& control) {
  SplineProjection s;
  double c[16][3];
  long k = 0;
  long l = 0;
  bool gathered = false;
  double x[3];
  double du[3];
  double dv[3];
  CatmullRomWeights bu{};
  CatmullRomWeights bv{};
  // The patch holding (u, v) (the last one holds its far edge), its nodes when it changed, and
  // x, x_u, x_v there.
  const auto patch = [](double t, double lo, double hi) {
    return static_cast<long>(
        std::fmax(std::floor(lo), std::fmin(std::floor(t), std::ceil(hi) - 1.0)));
  };
  auto evaluate = [&] {
    const long k_now = patch(u, domain.u_min, domain.u_max);
    const long l_now = patch(v, domain.v_min, domain.v_max);
    if (!gathered || k_now != k || l_now != l) {
      k = k_now;
      l = l_now;
      for (int b = 0; b < 4; ++b)
        for (int a = 0; a < 4; ++a) control(k - 1 + a, l - 1 + b, c[a + 4 * b]);
      gathered = true;
    }
    bu = catmull_rom(u - static_cast<double>(k));
    bv = catmull_rom(v - static_cast<double>(l));
    for (int d = 0; d < 3; ++d) x[d] = du[d] = dv[d] = 0.0;
    for (int b = 0; b < 4; ++b)
      for (int a = 0; a < 4; ++a) {
        const double* q = c[a + 4 * b];
        for (int d = 0; d < 3; ++d) {
          x[d] += bu.w[a] * bv.w[b] * q[d];
          du[d] += bu.dw[a] * bv.w[b] * q[d];
          dv[d] += bu.w[a] * bv.dw[b] * q[d];
        }
      }
  };
  // Gauss-Newton: [x_u . x_u, x_u . x_v; sym, x_v . x_v] d = [x_u . r, x_v . r], r = p - x. On a
  // surface curved by an indentation of depth delta over a radius a it contracts by about
  // |g| delta / a^2 per step: a few steps from the start grid's guess.
  for (int iteration = 0; iteration < 50; ++iteration) {
    evaluate();
    const double r[3] = {p[0] - x[0], p[1] - x[1], p[2] - x[2]};
    const double a11 = du[0] * du[0] + du[1] * du[1] + du[2] * du[2];
    const double a12 = du[0] * dv[0] + du[1] * dv[1] + du[2] * dv[2];
    const double a22 = dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2];
    const double b1 = du[0] * r[0] + du[1] * r[1] + du[2] * r[2];
    const double b2 = dv[0] * r[0] + dv[1] * r[1] + dv[2] * r[2];
    const double det = a11 * a22 - a12 * a12;
    const double u_new =
        std::fmin(std::fmax(u + (a22 * b1 - a12 * b2) / det, domain.u_min), domain.u_max);
    const double v_new =
        std::fmin(std::fmax(v + (a11 * b2 - a12 * b1) / det, domain.v_min), domain.v_max);
    const double step = std::abs(u_new - u) + std::abs(v_new - v);
    u = u_new;
    v = v_new;
    if (step < 1e-13) break;
  }
  evaluate();
  const double n[3] = {du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2],
                       du[0] * dv[1] - du[1] * dv[0]};
  const double inv = 1.0 / std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (int d = 0; d < 3; ++d) s.normal[d] = n[d] * inv;
  s.gap = (p[0] - x[0]) * s.normal[0] + (p[1] - x[1]) * s.normal[1] + (p[2] - x[2]) * s.normal[2];
  for (int b = 0; b < 4; ++b)
    for (int a = 0; a < 4; ++a) s.weight[a + 4 * b] = bu.w[a] * bv.w[b];
  s.u = u;
  s.v = v;
  s.k = k;
  s.l = l;
  return s;
}

}  // namespace corlab::fem
