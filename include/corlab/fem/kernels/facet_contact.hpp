// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file facet_contact.hpp
/// Projection of a slave node on a bilinear master facet (the 3-D counterpart of
/// penalty_contact.hpp's segment projection; Hallquist, Goudreau & Benson 1985, node on facet).
/// The facet x(xi, eta) = sum_I N_I(xi, eta) x_I, N_I = (1 + xi_I xi)(1 + eta_I eta) / 4, corners
/// counter-clockwise seen from its outward side; the closest point is found by Gauss-Newton on
/// (x(xi, eta) - p) . x_xi = (x(xi, eta) - p) . x_eta = 0, the gap is (p - x) . n with
/// n = x_xi x x_eta / |x_xi x x_eta|, and the weights N_I(xi, eta) share the slave's force among
/// the corners (their sum is 1, so the pair's forces balance).

#include <cmath>

namespace corlab::fem {

/// Where a slave meets a facet.
struct FacetProjection {
  double gap = 0.0;                         ///< signed normal distance [m] (< 0: penetration)
  double normal[3] = {0.0, 0.0, 1.0};       ///< outward unit normal at the closest point [-]
  double weight[4] = {0.0, 0.0, 0.0, 0.0};  ///< N_I at the closest point [-]
  double xi = 0.0;                          ///< natural coordinates of the closest point [-]
  double eta = 0.0;
};

/// Projects the point p [m] on the facet with corners c[4][3] [m].
inline FacetProjection project_on_facet(const double* p, const double (*c)[3]) {
  constexpr double kXi[4] = {-1.0, 1.0, 1.0, -1.0};
  constexpr double kEta[4] = {-1.0, -1.0, 1.0, 1.0};
  FacetProjection f;
  double x[3];
  double dxi[3];
  double deta[3];
  // x(xi, eta) and its tangents x_xi, x_eta at the current natural coordinates.
  auto evaluate = [&] {
    for (int d = 0; d < 3; ++d) {
      x[d] = 0.0;
      dxi[d] = 0.0;
      deta[d] = 0.0;
    }
    for (int i = 0; i < 4; ++i) {
      const double a = 1.0 + kXi[i] * f.xi;
      const double b = 1.0 + kEta[i] * f.eta;
      for (int d = 0; d < 3; ++d) {
        x[d] += 0.25 * a * b * c[i][d];
        dxi[d] += 0.25 * kXi[i] * b * c[i][d];
        deta[d] += 0.25 * kEta[i] * a * c[i][d];
      }
    }
  };
  // Gauss-Newton converges in one or two steps on a nearly flat facet, linearly on a warped one
  // far from the point.
  for (int iteration = 0; iteration < 25; ++iteration) {
    evaluate();
    // Gauss-Newton: [x_xi . x_xi, x_xi . x_eta; sym, x_eta . x_eta] d = [x_xi . r, x_eta . r].
    const double r[3] = {p[0] - x[0], p[1] - x[1], p[2] - x[2]};
    const double a11 = dxi[0] * dxi[0] + dxi[1] * dxi[1] + dxi[2] * dxi[2];
    const double a12 = dxi[0] * deta[0] + dxi[1] * deta[1] + dxi[2] * deta[2];
    const double a22 = deta[0] * deta[0] + deta[1] * deta[1] + deta[2] * deta[2];
    const double b1 = dxi[0] * r[0] + dxi[1] * r[1] + dxi[2] * r[2];
    const double b2 = deta[0] * r[0] + deta[1] * r[1] + deta[2] * r[2];
    const double det = a11 * a22 - a12 * a12;
    const double step_xi = (a22 * b1 - a12 * b2) / det;
    const double step_eta = (a11 * b2 - a12 * b1) / det;
    f.xi += step_xi;
    f.eta += step_eta;
    if (std::abs(step_xi) + std::abs(step_eta) < 1e-12) break;
  }
  evaluate();
  const double n[3] = {dxi[1] * deta[2] - dxi[2] * deta[1], dxi[2] * deta[0] - dxi[0] * deta[2],
                       dxi[0] * deta[1] - dxi[1] * deta[0]};
  const double inv = 1.0 / std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (int d = 0; d < 3; ++d) f.normal[d] = n[d] * inv;
  f.gap = (p[0] - x[0]) * f.normal[0] + (p[1] - x[1]) * f.normal[1] + (p[2] - x[2]) * f.normal[2];
  for (int i = 0; i < 4; ++i) f.weight[i] = 0.25 * (1.0 + kXi[i] * f.xi) * (1.0 + kEta[i] * f.eta);
  return f;
}

/// Whether the natural coordinates lie on the facet (with a relative margin `tolerance` [-]).
inline bool on_facet(const FacetProjection& f, double tolerance = 1e-9) {
  return std::abs(f.xi) <= 1.0 + tolerance && std::abs(f.eta) <= 1.0 + tolerance;
}

}  // namespace corlab::fem
