// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/restitution/jackson_green2010.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "corlab/core/units.hpp"
#include "detail/numerics.hpp"

namespace corlab::restitution {

using units::kPi;

namespace {

// Dimensionless loading work I(s) = integral_0^s P/P_c d(omega*) of the Hertz part.
double hertz_work(double s) { return 0.4 * s * s * std::sqrt(s); }

// Panels of the graded Gauss-Legendre rule per doubling of omega*.
constexpr int kPanelsPerBracket = 2;

// Dimensionless work from s0 to s1 > s0 >= 1.9 of the JG 2005 law.
double plastic_work(const JacksonGreen2005& law, double s0, double s1) {
  if (s1 <= s0) return 0.0;
  const int panels = std::max(kPanelsPerBracket,
                              static_cast<int>(std::ceil(kPanelsPerBracket * std::log2(s1 / s0))));
  return detail::gauss_legendre_graded([&law](double s) { return law.load_ratio(s); }, s0, s1,
                                       panels);
}

// Largest omega* searched; beyond it the impact is treated as the v -> infinity limit (e -> 0).
constexpr double kMaxNormalizedInterference = 1e120;

// Dimensionless omega*_max with I(omega*_max) = target (> 0). Returns +inf when out of range.
double solve_normalized_interference(const JacksonGreen2005& law, double target) {
  const double s_h = JacksonGreen2005::kHertzLimit;
  const double i_h = hertz_work(s_h);
  if (target <= i_h) return std::pow(target / 0.4, 0.4);
  // bracket by doubling, accumulating the work
  double lo = s_h;
  double i_lo = i_h;
  double hi = 2.0 * lo;
  double i_hi = i_lo + plastic_work(law, lo, hi);
  while (i_hi < target) {
    if (hi > kMaxNormalizedInterference) return INFINITY;
    lo = hi;
    i_lo = i_hi;
    hi = 2.0 * lo;
    i_hi = i_lo + plastic_work(law, lo, hi);
  }
  // safeguarded Newton on I(s) - target, dI/ds = P/P_c
  double s = lo + (hi - lo) * (target - i_lo) / (i_hi - i_lo);
  for (int iter = 0; iter < 100; ++iter) {
    const double i_s = i_lo + plastic_work(law, lo, s);
    const double f = i_s - target;
    if (std::abs(f) <= 1e-15 * target) return s;
    if (f < 0.0) {
      lo = s;
      i_lo = i_s;
    } else {
      hi = s;
      i_hi = i_s;
    }
    if (hi - lo <= 4.0 * std::numeric_limits<double>::epsilon() * hi) break;
    double next = s - f / law.load_ratio(s);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    s = next;
  }
  return s;
}

}  // namespace

JacksonGreen2005 JacksonGreen2010::loading_law() const {
  return JacksonGreen2005{.effective_modulus = pair.effective_modulus,
                          .yield_stress = pair.yield_stress,
                          .poisson_ratio = pair.substrate_poisson,
                          .radius = radius};
}

double JacksonGreen2010::yield_velocity() const {
  return jackson_green_critical_velocity(pair.effective_modulus, pair.yield_stress,
                                         pair.substrate_poisson, pair.sphere_density);
}

double JacksonGreen2010::mass() const {
  return 4.0 / 3.0 * kPi * radius * radius * radius * pair.sphere_density;
}

double JacksonGreen2010::loading_work(double interference) const {
  const JacksonGreen2005 law = loading_law();
  const double scale = law.critical_force() * law.critical_interference();
  const double s = std::max(interference, 0.0) / law.critical_interference();
  const double s_h = JacksonGreen2005::kHertzLimit;
  if (s <= s_h) return scale * hertz_work(s);
  return scale * (hertz_work(s_h) + plastic_work(law, s_h, s));
}

double JacksonGreen2010::max_interference(double velocity) const {
  const JacksonGreen2005 law = loading_law();
  const double scale = law.critical_force() * law.critical_interference();
  const double target = 0.5 * mass() * velocity * velocity / scale;
  return law.critical_interference() * solve_normalized_interference(law, target);
}

double JacksonGreen2010::unloading_work(double max_interference) const {
  const JacksonGreen2005 law = loading_law();
  const double w_max = max_interference;
  const double p_max = law.load(w_max);
  switch (residual) {
    case JacksonGreenResidual::kContinuousContactRadius: {
      // W = 8/15 E' sqrt(R_bar) (w_max - w_bar)^2.5 = 3/10 P_max^2 / (E' a_m)
      const double a_m = law.radius * law.contact_radius_ratio(w_max);
      return 0.3 * p_max * p_max / (law.effective_modulus * a_m);
    }
    case JacksonGreenResidual::kEtsion2005: {
      const double s = w_max / law.critical_interference();
      const double n = 1.5 * std::pow(s, -0.0331);
      const double residual_ratio = 1.02 * (1.0 - std::pow((s + 5.9) / 6.9, -0.54));
      // beyond omega*_max ~ 1e4 the fit gives omega_res > omega_max: no elastic recovery
      const double recovered = std::max(0.0, 1.0 - residual_ratio) * w_max;
      return p_max * recovered / (n + 1.0);
    }
  }
  return 0.0;
}

double JacksonGreen2010::cor(double velocity) const {
  if (velocity <= yield_velocity()) return 1.0;
  const double w_load = 0.5 * mass() * velocity * velocity;
  const double w_max = max_interference(velocity);
  if (!std::isfinite(w_load) || !std::isfinite(w_max)) return 0.0;  // v -> infinity limit
  const double ratio = unloading_work(w_max) / w_load;
  const double e = std::sqrt(std::max(ratio, 0.0));
  return clamp ? std::min(e, 1.0) : e;
}

double JacksonGreen2010Fit::yield_strain() const {
  const double eps = pair.yield_stress / pair.effective_modulus;
  return strain == JacksonGreenFitStrain::kYieldOverModulus
             ? eps
             : jackson_green_c(pair.substrate_poisson) * eps;
}

double JacksonGreen2010Fit::yield_velocity() const {
  return jackson_green_critical_velocity(pair.effective_modulus, pair.yield_stress,
                                         pair.substrate_poisson, pair.sphere_density);
}

double JacksonGreen2010Fit::cor(double velocity) const {
  const double v_ratio = velocity / yield_velocity();
  if (v_ratio <= 1.0) return 1.0;
  const double eps = yield_strain();
  // (V' - 1)^(9.5 eps) in logs; V' > 1 here so the log is finite
  const double e = 1.0 - 0.0361 * std::pow(eps, -0.114) * std::log(v_ratio) *
                             std::exp(9.5 * eps * std::log(v_ratio - 1.0));
  return clamp ? std::clamp(e, 0.0, 1.0) : e;
}

}  // namespace corlab::restitution
