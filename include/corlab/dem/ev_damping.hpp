// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file ev_damping.hpp
/// The e(v) damping that corlab adds to an elastic Hertz contact of a DEM code (LAMMPS: the
/// compiled fix corlab/ev of `corlab-lammps`; the Python hook of lammps.in evaluates the same law):
/// F_d = K delta^1.5 chi(e(v_in)) delta_dot / v_in [N], K = 4/3 E* sqrt(R*), v_in the contact's
/// normal approach speed at its first step, chi exact (hysteresis_chi.hpp) at the nodes of a
/// uniform speed table and linear in v between them (end values outside).

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "corlab/dem/contact_laws.hpp"
#include "corlab/dem/dem_walls.hpp"
#include "corlab/dem/uniform_table.hpp"

namespace corlab::dem {

/// chi(v) of one pair: exact_chi(min(e_k, 1)) at the speeds v_min + k (v_max - v_min)/(n - 1)
/// [m/s], k = 0..n-1 (n = restitution.size()). Throws InputError for n < 2, v_max <= v_min or an
/// e_k below kMinRestitution.
UniformTable chi_table(double v_min, double v_max, const std::vector<double>& restitution);

/// The damping law of a contact at its first step: approach speed `rate` [m/s] (> 0
/// approaching), E* [Pa], R* [m]. A contact that starts separating (rate <= 0) is undamped.
HysteresisLaw onset_law(const UniformTable& chi,
                        double rate,
                        double effective_modulus,
                        double effective_radius);

/// A sphere touching a wall: overlap [m] (> 0) and the unit normal from the wall into the sphere.
struct WallContact {
  double overlap = 0.0;
  std::array<double, 3> normal{0.0, 0.0, 1.0};
};

/// Distance [m] of `x` [m] from a plane wall, positive on its particles' side.
inline double plane_gap(const Wall& plane, const std::array<double, 3>& x) {
  return (x[0] - plane.point[0]) * plane.normal[0] + (x[1] - plane.point[1]) * plane.normal[1] +
         (x[2] - plane.point[2]) * plane.normal[2];
}

/// The contact of a sphere at `x` [m] with radius `radius` [m] with a plane (the particles on
/// its normal's side) or a cylinder (the particles inside, between lo and hi along its axis);
/// nullopt when they do not touch. Inline: a DEM step asks it for every atom and wall.
inline std::optional<WallContact> wall_contact(const Wall& wall,
                                               const std::array<double, 3>& x,
                                               double radius) {
  if (wall.shape == WallShape::plane) {
    const double gap = plane_gap(wall, x);
    if (!(radius > gap)) return std::nullopt;
    return WallContact{radius - gap, wall.normal};
  }
  const auto axis = static_cast<std::size_t>(wall.axis);
  if (x[axis] < wall.lo || x[axis] > wall.hi) return std::nullopt;
  const std::size_t o1 = axis == 0 ? 1 : 0;
  const std::size_t o2 = axis == 2 ? 1 : 2;
  const double d1 = x[o1] - wall.centre[0];
  const double d2 = x[o2] - wall.centre[1];
  const double rho = std::sqrt(d1 * d1 + d2 * d2);
  if (!(radius > wall.radius - rho)) return std::nullopt;
  WallContact c{radius - (wall.radius - rho), {0.0, 0.0, 0.0}};
  const double inv = 1.0 / std::max(rho, 1e-300);
  c.normal[o1] = -d1 * inv;
  c.normal[o2] = -d2 * inv;
  return c;
}

}  // namespace corlab::dem
