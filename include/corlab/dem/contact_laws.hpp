// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file contact_laws.hpp
/// Normal contact-force laws for DEM and multibody codes, as small pure structs. Every law gives
/// the repulsive normal force F [N] from the overlap delta [m] (> 0 in contact) and its rate
/// delta_dot [m/s] (> 0 approaching); F = 0 for delta <= 0. Laws with a memory (plasticity) read a
/// ContactHistory that the integrator (contact_ode.hpp) or the DEM code keeps per contact.
/// Citations and verification status: law_catalog() (law_info.hpp) and
/// docs/theory/dem_contact_laws.md.

#include <cmath>

#include "corlab/restitution/thornton1997.hpp"

namespace corlab::dem {

/// Smallest restitution the DEM tools take [-]: exact chi(e), the Tsuji alpha and the linear
/// damping are accurate down to it (the alpha's ODE e within 1e-6 relative at 1e-12; below it the
/// root finder's tolerance is the answer: asked 1e-20, e = 7e-13).
inline constexpr double kMinRestitution = 1e-12;

/// Per-contact memory of the history-dependent laws. A fresh contact starts zero-initialised.
struct ContactHistory {
  double max_overlap = 0.0;      ///< largest overlap reached so far [m]
  bool unloading = false;        ///< true once the overlap rate turned negative
  double impact_velocity = 0.0;  ///< normal approach speed at first touch [m/s]; 0 = not set
};

/// Hertz stiffness K = 4/3 E* sqrt(R*) [N/m^1.5] so that F = K delta^1.5.
/// @param effective_modulus E* [Pa]   @param effective_radius R* [m]
double hertz_stiffness(double effective_modulus, double effective_radius);

/// Hertz (1882) elastic sphere contact: F = K delta^1.5.
struct HertzLaw {
  double stiffness = 0.0;  ///< K [N/m^1.5]
  double force(double overlap) const {
    return overlap > 0.0 ? stiffness * overlap * std::sqrt(overlap) : 0.0;
  }
};

/// Hertz with hysteresis damping (Hunt-Crossley family): F = K delta^n (1 + chi delta_dot / v_in).
/// The restitution depends only on chi: chi (1 + e) = ln[(1 + chi)/(1 - e chi)]
/// (hysteresis_chi.hpp).
struct HysteresisLaw {
  double stiffness = 0.0;        ///< K [N/m^n]
  double chi = 0.0;              ///< dimensionless damping factor chi [-]
  double impact_velocity = 1.0;  ///< v_in, the normal approach speed at first touch [m/s]
  double exponent = 1.5;         ///< n [-]
  double force(double overlap, double overlap_rate) const {
    if (overlap <= 0.0) return 0.0;
    return stiffness * std::pow(overlap, exponent) * (1.0 + chi * overlap_rate / impact_velocity);
  }
  /// K chi / v_in [N s / m^(n+1)], fixed for the contact: damping() = it x delta^n x delta_dot.
  double damping_coefficient() const { return stiffness * chi / impact_velocity; }
  /// The damping part K delta^n chi delta_dot / v_in [N] alone (force() less elastic Hertz): what
  /// a DEM code running elastic Hertz adds per contact (ev_damping.hpp), given
  /// damping_coefficient() (kept per contact: no division per step).
  double damping(double overlap, double overlap_rate, double coefficient) const {
    if (overlap <= 0.0) return 0.0;
    const double power =
        exponent == 1.5 ? overlap * std::sqrt(overlap) : std::pow(overlap, exponent);
    return coefficient * power * overlap_rate;
  }
  double damping(double overlap, double overlap_rate) const {
    return damping(overlap, overlap_rate, damping_coefficient());
  }
};

/// Viscoelastic Hertz with Tsuji et al. (1992) damping, as LAMMPS `damping tsuji` evaluates it:
/// F = K delta^1.5 + alpha sqrt(m* K) delta^(1/4) delta_dot. e depends only on alpha.
struct TsujiLaw {
  double stiffness = 0.0;       ///< K [N/m^1.5]
  double alpha = 0.0;           ///< dimensionless damping alpha [-]
  double effective_mass = 0.0;  ///< m* [kg]
  double force(double overlap, double overlap_rate) const {
    if (overlap <= 0.0) return 0.0;
    const double root = std::sqrt(overlap);
    return stiffness * overlap * root +
           alpha * std::sqrt(effective_mass * stiffness) * std::sqrt(root) * overlap_rate;
  }
};

/// Viscoelastic Hertz with damping proportional to the contact radius (Kuwabara-Kono 1987,
/// Brilliantov et al. 1996; LAMMPS `damping viscoelastic`): F = K delta^1.5 + c delta^(1/2)
/// delta_dot. e falls with the impact speed: 1 - e ~ (c v^(1/5) K^(-3/5) m*^(-2/5)) at small
/// damping (Schwager & Poeschel 2008; closed-form e(v): viscoelastic_restitution.hpp). LAMMPS
/// writes c = eta_n m* sqrt(R*).
struct ViscoelasticHertzLaw {
  double stiffness = 0.0;  ///< K [N/m^1.5]
  double damping = 0.0;    ///< c [N s/m^1.5]
  double force(double overlap, double overlap_rate) const {
    if (overlap <= 0.0) return 0.0;
    const double root = std::sqrt(overlap);
    return stiffness * overlap * root + damping * root * overlap_rate;
  }
};

/// Linear spring-dashpot (Cundall & Strack 1979): F = k delta + c delta_dot.
/// Exact: e = exp(-pi zeta / sqrt(1 - zeta^2)), zeta = c / (2 sqrt(m* k)) (force not clamped).
struct LinearSpringDashpotLaw {
  double stiffness = 0.0;  ///< k [N/m]
  double damping = 0.0;    ///< c [N s/m]
  double force(double overlap, double overlap_rate) const {
    return overlap > 0.0 ? stiffness * overlap + damping * overlap_rate : 0.0;
  }
};

/// Restitution of the linear spring-dashpot law (unclamped force): exp(-pi zeta/sqrt(1-zeta^2)).
/// @param damping c [N s/m]  @param effective_mass m* [kg]  @param stiffness k [N/m]
double linear_restitution(double damping, double effective_mass, double stiffness);
/// Inverse: c [N s/m] = 2 sqrt(m* k) |ln e| / sqrt(ln^2 e + pi^2) for e in (0, 1].
double linear_damping_for_restitution(double restitution, double effective_mass, double stiffness);

/// Elastic-perfectly-plastic law of Thornton (1997), loading and unloading as in
/// restitution::ThorntonContact (the unloading used by LIGGGHTS `model thornton_ning` without
/// adhesion). Loading while !history.unloading, else the unloading curve from history.max_overlap.
struct ThorntonNingLaw {
  restitution::ThorntonContact contact;  ///< E* [Pa], R* [m], p_y [Pa]
  double force(double overlap, const ContactHistory& history) const {
    if (overlap <= 0.0) return 0.0;
    if (!history.unloading) return contact.loading_force(overlap);
    return contact.unloading_force(contact.unloading(history.max_overlap), overlap);
  }
};

/// LIGGGHTS 3.8 `model thornton_ning` without adhesion (surfaceEnergy 0), as its source
/// (normal_model_thornton_ning.h) evaluates it: Hertz loading until the contact radius reaches
/// a_y = yieldRatio r_i, then F_y + pi R* p_y (delta - delta_y) with p_y = 2 E* a_y/(pi R*);
/// unloading with the loading radius R* (dF = 2 E* sqrt(R* delta) d delta, unlike Thornton 1997),
/// F = F_max - K (delta_max^1.5 - delta^1.5), clamped at 0.
struct LiggghtsThorntonNingLaw {
  restitution::ThorntonContact contact;  ///< E* [Pa], R* [m], p_y [Pa]
  double force(double overlap, const ContactHistory& history) const {
    if (overlap <= 0.0) return 0.0;
    if (!history.unloading) return contact.loading_force(overlap);
    const double k = 4.0 / 3.0 * contact.effective_modulus * std::sqrt(contact.radius);
    const double d_max = history.max_overlap;
    const double f = contact.loading_force(d_max) -
                     k * (d_max * std::sqrt(d_max) - overlap * std::sqrt(overlap));
    return f > 0.0 ? f : 0.0;
  }
};

}  // namespace corlab::dem
