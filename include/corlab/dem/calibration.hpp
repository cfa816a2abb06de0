// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file calibration.hpp
/// Exact calibration of contact-law parameters to a target restitution, by integrating the
/// contact ODE (contact_ode.hpp) and inverting with Brent's method; and least-squares fits of a
/// one-parameter law to a target e(v) (a registered CoR model, or an FE table).

#include <functional>
#include <span>
#include <vector>

#include "corlab/dem/contact_laws.hpp"

namespace corlab::dem {

/// e(v): impact speed [m/s] -> restitution [-].
using RestitutionCurve = std::function<double(double)>;

/// chi of the hysteresis law delivering e in (0, 1), found from ODE integrations (not from the
/// closed form; the tests compare both).
double calibrate_chi_by_ode(double restitution);

/// alpha of TsujiLaw delivering e in [kMinRestitution, 1) (exact, ODE); InputError outside.
double calibrate_tsuji_alpha(double restitution);

/// Restitution of TsujiLaw for alpha >= 0 (ODE; independent of K, m*, v).
double tsuji_restitution(double alpha);

/// Result of a one-parameter fit to a target e(v).
struct CurveFit {
  double parameter = 0.0;          ///< the fitted parameter (unit: see the fitting function)
  double rms_error = 0.0;          ///< sqrt(mean (e_law - e_target)^2) over the fit speeds [-]
  double max_abs_error = 0.0;      ///< max |e_law - e_target| over the fit speeds [-]
  std::vector<double> velocities;  ///< fit speeds [m/s]
  std::vector<double> target;      ///< e_target at those speeds [-]
  std::vector<double> fitted;      ///< e of the fitted law at those speeds (ODE) [-]
};

/// Speeds v_min .. v_max, n >= 2 log-uniform points [m/s].
std::vector<double> log_speeds(double v_min, double v_max, int n);

/// Fits c [N s/m^1.5] of ViscoelasticHertzLaw{K, c} to the target at the given speeds (least
/// squares in e). @param stiffness K [N/m^1.5]  @param effective_mass m* [kg]
CurveFit fit_viscoelastic_damping(double stiffness,
                                  double effective_mass,
                                  std::span<const double> velocities,
                                  const RestitutionCurve& target);

/// Fits the limiting pressure p_y [Pa] of ThorntonNingLaw (E*, R*) to the target: corlab's
/// FE-calibrated plastic law when the target is an FE e(v). @param effective_modulus E* [Pa]
/// @param effective_radius R* [m]  @param effective_mass m* [kg]
CurveFit fit_thornton_pressure(double effective_modulus,
                               double effective_radius,
                               double effective_mass,
                               std::span<const double> velocities,
                               const RestitutionCurve& target);

/// Fits p_y [Pa] of LiggghtsThorntonNingLaw (E*, R*) to the target; LIGGGHTS's
/// coefficientYieldRatio of the particle of radius r_i is then pi R* p_y / (2 E* r_i).
CurveFit fit_liggghts_thornton_pressure(double effective_modulus,
                                        double effective_radius,
                                        double effective_mass,
                                        std::span<const double> velocities,
                                        const RestitutionCurve& target);

/// e(v) of a (v, e) table, linear in v between points, end values outside (e.g. FE results).
/// Throws InputError unless sizes match, n >= 2, v strictly increasing > 0, e in (0, 1].
RestitutionCurve tabulated_curve(std::vector<double> velocities, std::vector<double> restitution);

}  // namespace corlab::dem
