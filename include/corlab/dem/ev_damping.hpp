// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file ev_damping.hpp
/// The e(v) damping that corlab adds to an elastic Hertz contact of a DEM code (LAMMPS: the
/// compiled fix corlab/ev of `corlab-lammps`; the Python hook of lammps.in evaluates the same law):
/// F_d = K delta^1.5 chi(e(v_in)) delta_dot / v_in [N], K = 4/3 E* sqrt(R*), v_in the contact's
/// normal approach speed at its first step, chi exact (hysteresis_chi.hpp) at the nodes of a
/// uniform speed table and linear in v between them (end values outside).

#include <array>
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

/// The contact of a sphere at `x` [m] with radius `radius` [m] with a plane (the particles on
/// its normal's side) or a cylinder (the particles inside, between lo and hi along its axis);
/// nullopt when they do not touch.
std::optional<WallContact> wall_contact(const Wall& wall,
                                        const std::array<double, 3>& x,
                                        double radius);

}  // namespace corlab::dem
