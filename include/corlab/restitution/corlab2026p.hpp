// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file corlab2026p.hpp
/// corlab's CoR model over particle pairs (issue 26): corlab2026's kernel (corlab2026.hpp) for a
/// sphere hitting a flat or a free second sphere, with any densities (docs/theory/corlab_model.md,
/// "Particle pairs"). Three things differ from corlab2026_pair(), none with a new coefficient:
/// - the Hertz impact of the pair (R*, m*) is that of a sphere of density
///   rho* = 3 m* / (4 pi R*^3) on a flat (pair_effective_density): first yield v_y and the other
///   body's v_y,o use rho*;
/// - the damage number is Johnson's, on the density of the body that cratered, the one that
///   yields first: D_y = rho_w v_y^2 / p_y (corlab2026 takes the sphere's; equal for the flat
///   dataset's equal densities);
/// - a curved body that yields first is flattened whichever it is: the Jackson & Green cap
///   sees a/R_w = (a/R*) (R*/R_w), R*/R1 = 1/(1 + r), R*/R2 = r/(1 + r), r = R1/R2
///   (Corlab2026Inputs::radius_ratio).
/// For a sphere on a flat of its own density the inputs are corlab2026_pair()'s, bit for bit.
/// The coefficients are fitted to the union of data/fe_restitution and data/fe_restitution_pairs
/// (python/corlab/model_fit.py --model corlab2026p); they live in
/// data/fe_restitution_pairs/model_fit.json, generated into corlab2026p_fitted() at configure time.
/// Registered as "corlab2026p" (registry.hpp; ModelOptions::radius_ratio is R1/R2).

#include "corlab/materials/material.hpp"
#include "corlab/restitution/corlab2026.hpp"

namespace corlab::restitution {

/// The pair quantities of a sphere (body 1) hitting `other` (body 2): a flat for
/// radius_ratio = 0, else a free sphere of radius R2 = R1 / radius_ratio at rest (materials not
/// validated; radius_ratio >= 0 and finite, else InputError) [-].
Corlab2026Pair corlab2026p_pair(const Material& sphere, const Material& other, double radius_ratio);

/// The coefficients fitted to the union of the flat and pair datasets:
/// data/fe_restitution_pairs/model_fit.json's "coefficients" (generated at configure time).
Corlab2026Coefficients corlab2026p_fitted();

/// The model bound to a pair, with corlab2026p_fitted() (e = model.cor(v), v [m/s]).
Corlab2026 corlab2026p(const Material& sphere, const Material& other, double radius_ratio);

}  // namespace corlab::restitution
