// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file corlab2026.hpp
/// corlab's own model of the coefficient of restitution, fitted to corlab's FE restitution
/// dataset (data/fe_restitution/, docs/theory/corlab_model.md). Thornton's (1997) closed form
/// with the limiting pressure replaced by the mean contact pressure of an elastic-plastic contact:
/// it grows from the first-yield pressure like Johnson's expanding-cavity model (logarithmically
/// in E* a / (Y R)), up to a fully plastic cap (Tabor), and with linear hardening like the flow
/// stress at Tabor's representative strain; a second factor for the other body when it yields
/// too, and a third for deep craters (Johnson's damage number). Exactly 1 at the pair's first
/// yield (restitution/first_yield.hpp), never above 1, continuous and non-increasing in v; for
/// perfect plasticity and shallow craters e ~ v^(-1/4) at high speed (Johnson's trend). The
/// body that takes more of the deformation (the larger share of the pair's elastic compliance)
/// weighs more; the other body yields under the pressure the first one's plastic contact can
/// carry; a sphere that yields first is flattened, with Jackson & Green's falling hardness.
///
///   x = v / v_y,   x_w = 1 + exp(q_w (l_w - 1/2)) (x - 1)     (first body's stretched overload)
///   g(x, h, k) = (1 + k h x^(2/5)) / (1 + k h)                  (flow stress / yield stress)
///   A(h) = (1 - c/0.4) kappa_c h / (1 + kappa_c h)               (hardening of the cavity range)
///   phi(x, h, c, P) = min(1 + c ln x + A(h) (x^(2/5) - 1), P g(x, h, kappa))
///                                                               (mean pressure / at first yield)
///   n = C(0.3) / C(nu_w),  C(nu) = 1.295 exp(0.736 nu)         (p_y = C Y: c1, phi_max in Y)
///   P_w = max(1, n phi_max J(s (a_y/R*) (R*/R_w) x_w^(2/5)))    (R*/R_w = 0 for a flat: J = 1)
///   J(a/R) = 1 - exp(-0.82 (a/R)^(-0.7))                        (Jackson & Green 2005, over 2.84)
///   phi_w = phi(x_w, h_w, n c1, P_w),   x_o* = phi_w^(5/2) x_o / x
///   phi_o = phi(x_o*, h_o, c1, phi_max),   T(x, phi) = e_Thornton(phi^(5/2) / x) (1 for x <= 1)
///   w_o = gamma exp(q_o (l_o - l_w))
///   e = T(x_w, phi_w) T(x_o*, phi_o)^w_o / (1 + b (D_y (x^2 - 1) / g(x, h_w, kappa))^c)
///
/// phi^(5/2)/x decreases: the cavity branch's rate (c + 0.4 A x^(2/5)) / phi is below 2/5 for
/// every x >= 1 because A < 1 - c/0.4 (c <= 0.39), g's is below 2/5, and a cap falling with x (J)
/// only lowers it; so each T decreases, and x_o* grows with phi_w. h = H / E* of a body, w the
/// body that yields first, o the other (x_o = v / v_y,o; gamma = gamma_sphere or gamma_substrate
/// after which body that is; x_o = 0 if it is elastic), D_y = rho_sphere v_y^2 / p_y the damage
/// number at first yield (over g: on the flow stress), a_y/R* = pi p_y / (2 E*) the contact radius
/// at first yield and l = E* (1 - nu^2) / E a body's share of the compliance (l_w + l_o = 1).
/// R*/R_w is the first body's share of the pair's curvature, from r = R1/R2 (radius_ratio): the
/// sphere's 1/(1 + r), a second sphere's r/(1 + r), a flat's 0 (a flat is indented, not
/// flattened). For a sphere on a flat (r = 0) this is the model as first fitted; pairs of spheres
/// and unequal densities: corlab2026p.hpp.

#include <array>
#include <string_view>
#include <utility>

#include "corlab/materials/material.hpp"

namespace corlab::restitution {

/// The model's eleven coefficients, all dimensionless [-].
struct Corlab2026Coefficients {
  double c1 = 0.0;                ///< cavity-model slope of p_m / p_y in ln x (<= 0.39)
  double phi_max = 1.0;           ///< fully plastic cap of p_m / p_y (perfect plasticity)
  double kappa = 0.0;             ///< hardening of the fully plastic cap (Tabor's strain)
  double kappa_cavity = 0.0;      ///< hardening of the cavity-model growth before the cap
  double b = 0.0;                 ///< deep-crater factor
  double c = 1.0;                 ///< deep-crater exponent
  double gamma_sphere = 0.0;      ///< weight of a yielding sphere that yields second
  double gamma_substrate = 0.0;   ///< weight of a substrate that yields second
  double compliance_first = 0.0;  ///< q_w: overload stretch per compliance share, first body
  double compliance_other = 0.0;  ///< q_o: weight of the other body per shares' difference
  double flattening = 1.0;        ///< s: a/R of a flattened sphere over its Hertz estimate
};

/// The coefficients by name, in order: the one list that model_fit.json, the Python dicts and the
/// fit (python/corlab/model_fit.py, a test compares) read.
inline constexpr std::array<std::pair<std::string_view, double Corlab2026Coefficients::*>, 11>
    kCorlab2026Coefficients{{{"c1", &Corlab2026Coefficients::c1},
                             {"phi_max", &Corlab2026Coefficients::phi_max},
                             {"kappa", &Corlab2026Coefficients::kappa},
                             {"kappa_cavity", &Corlab2026Coefficients::kappa_cavity},
                             {"b", &Corlab2026Coefficients::b},
                             {"c", &Corlab2026Coefficients::c},
                             {"gamma_sphere", &Corlab2026Coefficients::gamma_sphere},
                             {"gamma_substrate", &Corlab2026Coefficients::gamma_substrate},
                             {"compliance_first", &Corlab2026Coefficients::compliance_first},
                             {"compliance_other", &Corlab2026Coefficients::compliance_other},
                             {"flattening", &Corlab2026Coefficients::flattening}}};

/// The coefficients fitted to the shipped dataset: data/fe_restitution/model_fit.json's, generated
/// at configure time (cmake/Corlab2026Coefficients.cmake; a test checks them bit for bit against
/// the file, and that refitting the shipped data gives them).
Corlab2026Coefficients corlab2026_fitted();

/// The dimensionless inputs of one impact.
struct Corlab2026Inputs {
  double velocity_ratio = 0.0;           ///< x = v / v_y, v_y of the pair [-]
  double velocity_ratio_other = 0.0;     ///< x_o = v / v_y,o of the other body (0: elastic) [-]
  double hardening_first = 0.0;          ///< h_w = H / E* of the body that yields first [-]
  double hardening_other = 0.0;          ///< h_o = H / E* of the other body [-]
  double damage_at_yield = 0.0;          ///< D_y = rho_sphere v_y^2 / p_y [-]
  double compliance_share = 0.5;         ///< l_s = ((1 - nu_s^2) / E_s) E* of the sphere [-]
  double contact_radius_at_yield = 0.0;  ///< a_y / R = pi p_y / (2 E*) [-]
  double poisson_first = 0.3;            ///< nu of the body that yields first [-]
  double radius_ratio = 0.0;             ///< r = R1/R2, the sphere's over the other's (0: flat) [-]
  bool other_is_sphere = false;          ///< the sphere yields second (else the substrate)
};

/// The real-valued inputs by name, in order (other_is_sphere aside): the one list that the
/// Python binding's dicts and the fit read.
inline constexpr std::array<std::pair<std::string_view, double Corlab2026Inputs::*>, 9>
    kCorlab2026Inputs{{{"velocity_ratio", &Corlab2026Inputs::velocity_ratio},
                       {"velocity_ratio_other", &Corlab2026Inputs::velocity_ratio_other},
                       {"hardening_first", &Corlab2026Inputs::hardening_first},
                       {"hardening_other", &Corlab2026Inputs::hardening_other},
                       {"damage_at_yield", &Corlab2026Inputs::damage_at_yield},
                       {"compliance_share", &Corlab2026Inputs::compliance_share},
                       {"contact_radius_at_yield", &Corlab2026Inputs::contact_radius_at_yield},
                       {"poisson_first", &Corlab2026Inputs::poisson_first},
                       {"radius_ratio", &Corlab2026Inputs::radius_ratio}}};

/// What the model needs of a material pair, independent of the speed.
struct Corlab2026Pair {
  double yield_velocity = 0.0;        ///< v_y of the pair [m/s]
  double yield_velocity_other = 0.0;  ///< v_y,o of the other body [m/s] (inf: elastic)
  /// The speed-independent inputs (velocity_ratio and velocity_ratio_other unset).
  Corlab2026Inputs inputs;
};

/// The pair quantities of a sphere and a substrate (materials not validated).
Corlab2026Pair corlab2026_pair(const Material& sphere, const Material& substrate);

/// The inputs of the pair at speed v > 0 [m/s].
Corlab2026Inputs corlab2026_inputs(const Corlab2026Pair& pair, double velocity);

/// Same from the materials.
Corlab2026Inputs corlab2026_inputs(const Material& sphere,
                                   const Material& substrate,
                                   double velocity);

/// e [-] for the given inputs and coefficients.
double corlab2026_restitution(const Corlab2026Inputs& in, const Corlab2026Coefficients& k);

/// The model bound to a material pair (registry name "corlab2026"). Cheap to copy.
struct Corlab2026 {
  Corlab2026Pair pair;
  Corlab2026Coefficients coefficients;
  /// First yield of the pair [m/s] (e = 1 at and below it).
  double yield_velocity() const;
  /// CoR at v > 0 [m/s].
  double cor(double velocity) const;
};

}  // namespace corlab::restitution
