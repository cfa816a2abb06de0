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
/// perfect plasticity and shallow craters e ~ v^(-1/4) at high speed (Johnson's trend).
///
///   x = v / v_y,   T(x, h) = e_Thornton(phi(x, h)^(5/2) / x)   (T = 1 for x <= 1)
///   g(x, h) = (1 + kappa h x^(2/5)) / (1 + kappa h)      (flow stress / yield stress)
///   phi(x, h) = min((1 + c1 ln x) g^(1 - c1/0.39), phi_max g)
///   e = T(x, h_w) T(x_o, h_o)^gamma / (1 + b (D_y (x^2 - 1) / g(x, h_w))^c)
///
/// Both branches of phi grow slower than x^(2/5) (c1 <= 0.39), so phi^(5/2)/x and e decrease.
/// h = H / E* of a body, w the body that yields first, o the other one (x_o = v / v_y,o;
/// gamma = gamma_sphere or gamma_substrate after which body that is; T = 1 if it is elastic) and
/// D_y = rho_sphere v_y^2 / p_y the damage number at first yield (over g: on the flow stress).

#include <array>
#include <string_view>
#include <utility>

#include "corlab/materials/material.hpp"

namespace corlab::restitution {

/// The model's seven coefficients, all dimensionless [-].
struct Corlab2026Coefficients {
  double c1 = 0.0;               ///< cavity-model slope of p_m / p_y in ln x (<= 0.39)
  double phi_max = 1.0;          ///< fully plastic cap of p_m / p_y (perfect plasticity)
  double kappa = 0.0;            ///< hardening: flow stress at the representative strain
  double b = 0.0;                ///< deep-crater factor
  double c = 1.0;                ///< deep-crater exponent
  double gamma_sphere = 0.0;     ///< weight of a yielding sphere that yields second
  double gamma_substrate = 0.0;  ///< weight of a substrate that yields second
};

/// The coefficients by name, in order: the one list that model_fit.json, the Python dicts and the
/// fit (python/corlab/model_fit.py, a test compares) read.
inline constexpr std::array<std::pair<std::string_view, double Corlab2026Coefficients::*>, 7>
    kCorlab2026Coefficients{{{"c1", &Corlab2026Coefficients::c1},
                             {"phi_max", &Corlab2026Coefficients::phi_max},
                             {"kappa", &Corlab2026Coefficients::kappa},
                             {"b", &Corlab2026Coefficients::b},
                             {"c", &Corlab2026Coefficients::c},
                             {"gamma_sphere", &Corlab2026Coefficients::gamma_sphere},
                             {"gamma_substrate", &Corlab2026Coefficients::gamma_substrate}}};

/// The coefficients fitted to the shipped dataset (data/fe_restitution/model_fit.json; a test
/// checks that they are the file's and that refitting the shipped data gives them).
Corlab2026Coefficients corlab2026_fitted();

/// The dimensionless inputs of one impact.
struct Corlab2026Inputs {
  double velocity_ratio = 0.0;        ///< x = v / v_y, v_y of the pair [-]
  double velocity_ratio_other = 0.0;  ///< x_o = v / v_y,o of the other body (0: elastic) [-]
  double hardening_first = 0.0;       ///< h_w = H / E* of the body that yields first [-]
  double hardening_other = 0.0;       ///< h_o = H / E* of the other body [-]
  double damage_at_yield = 0.0;       ///< D_y = rho_sphere v_y^2 / p_y [-]
  bool other_is_sphere = false;       ///< the sphere yields second (else the substrate)
};

/// What the model needs of a material pair, independent of the speed.
struct Corlab2026Pair {
  double yield_velocity = 0.0;        ///< v_y of the pair [m/s]
  double yield_velocity_other = 0.0;  ///< v_y,o of the other body [m/s] (inf: elastic)
  double hardening_first = 0.0;       ///< H / E* of the body that yields first [-]
  double hardening_other = 0.0;       ///< H / E* of the other body [-]
  double damage_at_yield = 0.0;       ///< rho_sphere v_y^2 / p_y [-]
  bool other_is_sphere = false;       ///< the sphere yields second
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
