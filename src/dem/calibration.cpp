// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dem/calibration.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "corlab/core/error.hpp"
#include "corlab/core/golden_section.hpp"
#include "corlab/dem/contact_ode.hpp"
#include "dem/detail/gsl_solvers.hpp"

namespace corlab::dem {
namespace {

// e of a law in unit scales, 0 where it holds the bodies together: e falls to 0 at a finite
// damping and the bracketing below steps past it (dem --restitution 1e-3 stopped there).
double restitution_or_stuck(const ForceLaw& force) {
  try {
    return simulate_impact(force, 1.0, 1.0).restitution;
  } catch (const NotSeparated&) {
    return 0.0;
  }
}

// e of the hysteresis law in unit scales (e does not depend on K, m*, v).
double hysteresis_restitution_by_ode(double chi) {
  const HysteresisLaw law{.stiffness = 1.0, .chi = chi, .impact_velocity = 1.0};
  const ForceLaw force = [&law](double d, double r, const ContactHistory&) {
    return law.force(d, r);
  };
  return restitution_or_stuck(force);
}

CurveFit fit_one_parameter(const std::function<double(double param, double v)>& law_e,
                           std::span<const double> velocities,
                           const RestitutionCurve& target,
                           double log_lo,
                           double log_hi) {
  if (velocities.empty()) throw_invalid("velocities", 0.0, "a non-empty list");
  CurveFit fit;
  fit.velocities.assign(velocities.begin(), velocities.end());
  for (const double v : velocities) fit.target.push_back(target(v));
  const auto cost = [&](double log_p) {
    double sum = 0.0;
    for (std::size_t i = 0; i < velocities.size(); ++i) {
      const double d = law_e(std::exp(log_p), velocities[i]) - fit.target[i];
      sum += d * d;
    }
    return sum;
  };
  // Coarse scan (the cost may be flat far from the optimum), then golden section around it.
  constexpr int kScan = 24;
  double best = log_lo;
  double best_cost = cost(log_lo);
  for (int k = 1; k <= kScan; ++k) {
    const double x = log_lo + (log_hi - log_lo) * k / kScan;
    const double c = cost(x);
    if (c < best_cost) {
      best = x;
      best_cost = c;
    }
  }
  const double width = (log_hi - log_lo) / kScan;
  const double log_p = golden_section_minimum(cost, best - width, best + width, 1e-9);
  fit.parameter = std::exp(log_p);
  double sum = 0.0;
  for (std::size_t i = 0; i < velocities.size(); ++i) {
    fit.fitted.push_back(law_e(fit.parameter, velocities[i]));
    const double d = fit.fitted.back() - fit.target[i];
    sum += d * d;
    fit.max_abs_error = std::max(fit.max_abs_error, std::abs(d));
  }
  fit.rms_error = std::sqrt(sum / static_cast<double>(velocities.size()));
  return fit;
}

}  // namespace

double calibrate_chi_by_ode(double e) {
  require_open_range("restitution", e, 0.0, 1.0);
  const auto f = [e](double chi) { return hysteresis_restitution_by_ode(chi) - e; };
  // e(chi) falls from 1 (chi = 0) to 0 (chi -> infinity); bracket by doubling.
  double hi = 1.0;
  while (f(hi) > 0.0) hi *= 2.0;
  return detail::brent_root(f, hi > 1.0 ? hi / 2.0 : 0.0, hi, 1e-13, 1e-11);
}

double tsuji_restitution(double alpha) {
  require_non_negative("alpha", alpha);
  const TsujiLaw law{.stiffness = 1.0, .alpha = alpha, .effective_mass = 1.0};
  const ForceLaw force = [&law](double d, double r, const ContactHistory&) {
    return law.force(d, r);
  };
  return simulate_impact(force, 1.0, 1.0).restitution;
}

double calibrate_tsuji_alpha(double e) {
  if (!(e >= kMinRestitution && e < 1.0)) {
    throw_invalid("restitution", e, fmt::format("in [{}, 1)", kMinRestitution));
  }
  const auto f = [e](double alpha) {
    const TsujiLaw law{.stiffness = 1.0, .alpha = alpha, .effective_mass = 1.0};
    return restitution_or_stuck(
               [&law](double d, double r, const ContactHistory&) { return law.force(d, r); }) -
           e;
  };
  double hi = 0.5;
  while (f(hi) > 0.0) hi *= 2.0;
  return detail::brent_root(f, hi > 0.5 ? hi / 2.0 : 0.0, hi, 1e-13, 1e-11);
}

std::vector<double> log_speeds(double v_min, double v_max, int n) {
  require_positive("v_min", v_min, "[m/s]");
  if (!(v_max > v_min)) throw_invalid("v_max", v_max, "> v_min");
  if (n < 2) throw_invalid("speeds", n, ">= 2");
  std::vector<double> v(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    v[static_cast<std::size_t>(i)] =
        v_min * std::pow(v_max / v_min, static_cast<double>(i) / (n - 1));
  return v;
}

CurveFit fit_viscoelastic_damping(double stiffness,
                                  double effective_mass,
                                  std::span<const double> velocities,
                                  const RestitutionCurve& target) {
  require_positive("stiffness", stiffness, "[N/m^1.5]");
  require_positive("effective_mass", effective_mass, "[kg]");
  const auto law_e = [&](double c, double v) {
    const ViscoelasticHertzLaw law{.stiffness = stiffness, .damping = c};
    const ForceLaw force = [&law](double d, double r, const ContactHistory&) {
      return law.force(d, r);
    };
    return simulate_impact(force, effective_mass, v).restitution;
  };
  // e depends on g = c v^(1/5) K^(-3/5) m^(-2/5); search g in [1e-6, 10] at the geometric mean v.
  const double v_ref = std::sqrt(velocities.front() * velocities.back());
  const double c_unit =
      std::pow(stiffness, 0.6) * std::pow(effective_mass, 0.4) / std::pow(v_ref, 0.2);
  return fit_one_parameter(law_e, velocities, target, std::log(1e-6 * c_unit),
                           std::log(10.0 * c_unit));
}

namespace {

/// The yield pressure p_y [Pa] of a Thornton-Ning-type `Law` whose e(v) follows `target`.
template <typename Law>
CurveFit fit_yield_pressure(double effective_modulus,
                            double effective_radius,
                            double effective_mass,
                            std::span<const double> velocities,
                            const RestitutionCurve& target) {
  require_positive("effective_modulus", effective_modulus, "[Pa]");
  require_positive("effective_radius", effective_radius, "[m]");
  require_positive("effective_mass", effective_mass, "[kg]");
  const auto law_e = [&](double p_y, double v) {
    const Law law{{effective_modulus, effective_radius, p_y}};
    const ForceLaw force = [&law](double d, double, const ContactHistory& h) {
      return law.force(d, h);
    };
    return simulate_impact(force, effective_mass, v).restitution;
  };
  return fit_one_parameter(law_e, velocities, target, std::log(1e-5 * effective_modulus),
                           std::log(0.5 * effective_modulus));
}

}  // namespace

CurveFit fit_thornton_pressure(double effective_modulus,
                               double effective_radius,
                               double effective_mass,
                               std::span<const double> velocities,
                               const RestitutionCurve& target) {
  return fit_yield_pressure<ThorntonNingLaw>(effective_modulus, effective_radius, effective_mass,
                                             velocities, target);
}

CurveFit fit_liggghts_thornton_pressure(double effective_modulus,
                                        double effective_radius,
                                        double effective_mass,
                                        std::span<const double> velocities,
                                        const RestitutionCurve& target) {
  return fit_yield_pressure<LiggghtsThorntonNingLaw>(effective_modulus, effective_radius,
                                                     effective_mass, velocities, target);
}

RestitutionCurve tabulated_curve(std::vector<double> v, std::vector<double> e) {
  if (v.size() != e.size())
    throw_invalid("table rows", static_cast<double>(e.size()), "equal to the number of velocities");
  if (v.size() < 2) throw_invalid("table rows", static_cast<double>(v.size()), ">= 2");
  for (std::size_t i = 0; i < v.size(); ++i) {
    require_positive("table velocity", v[i], "[m/s]");
    require_closed_range("table restitution", e[i], kMinRestitution, 1.0);
    if (i > 0 && !(v[i] > v[i - 1])) throw_invalid("table velocity", v[i], "strictly increasing");
  }
  return [v = std::move(v), e = std::move(e)](double speed) {
    if (speed <= v.front()) return e.front();
    if (speed >= v.back()) return e.back();
    const auto it = std::upper_bound(v.begin(), v.end(), speed);
    const auto j = static_cast<std::size_t>(it - v.begin());
    const double w = (speed - v[j - 1]) / (v[j] - v[j - 1]);
    return e[j - 1] + w * (e[j] - e[j - 1]);
  };
}

}  // namespace corlab::dem
