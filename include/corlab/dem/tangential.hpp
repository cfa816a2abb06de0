// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file tangential.hpp
/// The tangential (Mindlin) part of a DEM export: Coulomb friction mu and the Mindlin no-slip
/// stiffness k_t = 8 G* a (a = sqrt(R* delta) the contact radius [m]) as each code takes it.
/// Sources (docs/theory/dem_contact_laws.md#the-tangential-part-mindlin-and-coulomb):
/// LAMMPS pair_style granular `tangential mindlin k_t x_gamma mu` (F_t = -min(mu F_n0,
/// |-k_t a xi + F_t,damp|), k_t NULL = 8 G* with 1/G* = 2(2-nu_i)(1+nu_i)/E_i + ...);
/// LIGGGHTS `model hertz tangential history` (k_t = 8 G* sqrt(R* delta) from youngsModulus and
/// poissonsRatio); YADE 2023.02a Ip2_FrictMat_FrictMat_MindlinPhys (k_s = kso sqrt(u_N),
/// kso = 8 G* sqrt(R), measured; on a Box or Wall it takes R = r/2, for k_n as well).

#include <string_view>

#include "corlab/materials/material.hpp"

namespace corlab::dem {

/// The fragments' header line when no friction was asked for (every code's).
inline constexpr std::string_view kFrictionlessComment =
    "# Tangential: frictionless (corlab dem --friction MU).\n";

/// Mindlin's effective shear modulus G* [Pa]: 1/G* = (2 - nu_1)/G_1 + (2 - nu_2)/G_2,
/// G = E/(2 (1 + nu)).
double mindlin_shear_modulus(const Material& a, const Material& b);

/// k_t / a of Mindlin's no-slip tangential stiffness, 8 G* [Pa] (k_t = 8 G* a [N/m]): LAMMPS's
/// `tangential mindlin` k_t.
double mindlin_coefficient(double shear_modulus);

/// LAMMPS's x_gamma (tangential damping eta_t = x_gamma eta_n) that gives the tangential
/// dashpot the normal one's damping ratio, as LIGGGHTS and YADE do: sqrt(k_t'/k_n') with the
/// tangent stiffnesses 8 G* a and 2 E* a, i.e. sqrt(4 G*/E*) [-].
double tangential_damping_ratio(double shear_modulus, double effective_modulus);

/// Validates a Coulomb friction coefficient mu [-] (finite, >= 0); InputError naming `friction`.
void validate_friction(double friction);

}  // namespace corlab::dem
