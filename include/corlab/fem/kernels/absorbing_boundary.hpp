// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file absorbing_boundary.hpp
/// The viscous (non-reflecting) boundary of Lysmer & Kuhlemeyer (1969, J. Eng. Mech. Div. ASCE
/// 95:859): on a far face of a truncated elastic body, the traction
///   t_n = -rho c_p v_n,   t_s = -rho c_s v_s
/// (n the face's normal, s along the face) absorbs a plane wave that reaches it at normal
/// incidence exactly, and most of an obliquely incident one (docs/theory/solver.md, "Far
/// boundary"). Lumped to the face's nodes, each dof gets a dashpot c = (area share) x impedance;
/// its force -c v is applied at the half-step velocity (explicit, as LS-DYNA's
/// *BOUNDARY_NON_REFLECTING). Shared by the axisymmetric and the 3-D model. SI units.

#include <array>
#include <cmath>
#include <cstddef>

#include "corlab/core/units.hpp"

namespace corlab::fem {

/// The impedances of an elastic body [Pa s/m].
struct BoundaryImpedance {
  double normal = 0.0;  ///< rho c_p: against the velocity along the face's normal
  double shear = 0.0;   ///< rho c_s: against the velocity along the face
};

/// rho c_p = sqrt(rho M) and rho c_s = sqrt(rho G) of a body of density rho [kg/m^3], P-wave
/// modulus M = lambda + 2 G [Pa] and shear modulus G [Pa].
inline BoundaryImpedance lysmer_impedance(double density, double p_wave_modulus, double shear) {
  return {std::sqrt(density * p_wave_modulus), std::sqrt(density * shear)};
}

/// The dashpot coefficients [N s/m], one per axis, that a face whose normal is along axis
/// `normal_axis` gives one of its nodes carrying `area` [m^2] of it: area x rho c_p along the
/// normal, area x rho c_s along the other axes. A node on several faces sums theirs.
template <std::size_t D>
std::array<double, D> face_dashpot(std::size_t normal_axis, double area, BoundaryImpedance z) {
  std::array<double, D> c{};
  for (std::size_t a = 0; a < D; ++a) c[a] = area * (a == normal_axis ? z.normal : z.shear);
  return c;
}

/// The areas [m^2] of the surface of revolution swept by the segment from (r_a, z_a) to
/// (r_b, z_b) [m] about the axis r = 0 that its two nodes carry: 2 pi int N_i r ds, N_i the
/// linear shape functions (their sum is the surface, pi (r_a + r_b) L).
inline std::array<double, 2> ring_segment_areas(double r_a, double z_a, double r_b, double z_b) {
  const double length = std::hypot(r_b - r_a, z_b - z_a);
  const double third = units::kPi * length / 3.0;
  return {third * (2.0 * r_a + r_b), third * (r_a + 2.0 * r_b)};
}

/// The spring per unit area [Pa/m] of the viscous-spring boundary (Deeks & Randolph 1994, J.
/// Eng. Mech. 120:25; in 3-D Liu et al. 2006, Chin. J. Civ. Eng. 39:44) at distance `distance`
/// [m] from the source, for a body of shear modulus G [Pa]: alpha G / distance, alpha = 4/3 along
/// the face's normal and 2/3 along the face. With the dashpots it stands for the outer medium's
/// static stiffness too, so that a boundary within a wavelength of the source holds the body
/// where the dashpots alone let it float.
struct BoundaryStiffness {
  double normal = 0.0;  ///< [Pa/m]
  double shear = 0.0;   ///< [Pa/m]
};

inline constexpr double kSpringNormal = 4.0 / 3.0;  ///< alpha_N [-]
inline constexpr double kSpringShear = 2.0 / 3.0;   ///< alpha_T [-]

inline BoundaryStiffness spring_stiffness(double shear_modulus, double distance) {
  return {kSpringNormal * shear_modulus / distance, kSpringShear * shear_modulus / distance};
}

/// The springs [N/m] per axis that a face with normal axis `normal_axis` gives a node carrying
/// `area` [m^2] of it, as face_dashpot.
template <std::size_t D>
std::array<double, D> face_spring(std::size_t normal_axis, double area, BoundaryStiffness k) {
  return face_dashpot<D>(normal_axis, area, {k.normal, k.shear});
}

/// The force [N] of a dashpot c [N s/m] on a dof moving at v [m/s].
inline double dashpot_force(double c, double v) { return -c * v; }

/// The work [J] the dashpot takes out over a step dt [s] at velocity v [m/s]: c v^2 dt >= 0.
inline double dashpot_work(double c, double v, double dt) { return c * v * v * dt; }

}  // namespace corlab::fem
