// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file lammps_mapping.hpp
/// What LAMMPS (29Sep2021, Debian 12 `lammps` 20220106) does with the restitution it is given,
/// and the input that makes it deliver a target e.
/// `pair_coeff ... hertz K damping tsuji` with restitution e_in sets alpha = poly(e_in)
/// (pair_granular.cpp, coeff()): poly = 1.2728 - 4.2783 e + 11.087 e^2 - 22.348 e^3 + 27.467 e^4
/// - 18.022 e^5 + 4.8218 e^6, then F = K sqrt(R*) delta^1.5 + alpha sqrt(m* K sqrt(R* delta))
/// delta_dot, i.e. TsujiLaw. poly(e) is not the exact alpha(e) of that law: asked 0.3 it delivers
/// about 0.44.

namespace corlab::dem {

/// LAMMPS's alpha for its input restitution e_in.
double lammps_tsuji_alpha(double input_restitution);

/// The e_in to write in the LAMMPS input so that it delivers `target` in (0, 1): poly(e_in) equals
/// the exact alpha(target). e_in may be below the target (or negative for targets below about
/// 0.2, which LAMMPS accepts as a number). Throws InputError if no e_in in [-1, 1] works.
double lammps_tsuji_input(double target_restitution);

}  // namespace corlab::dem
