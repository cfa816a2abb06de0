// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dem/contact_ode.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "corlab/core/error.hpp"
#include "dem/detail/gsl_solvers.hpp"

namespace corlab::dem {
namespace {

// Scaled problem: x = delta/L, u = delta_dot/v, tau = t v/L; du/dtau = -F L/(m v^2).
struct Scaled {
  const ForceLaw* law;
  ContactHistory* history;
  double length;    // L [m]
  double velocity;  // v [m/s]
  double factor;    // L/(m v^2) [1/N]
};

int scaled_rhs(double /*tau*/, const double y[], double dydt[], void* params) {
  const auto& p = *static_cast<const Scaled*>(params);
  dydt[0] = y[1];
  dydt[1] = -p.factor * (*p.law)(p.length * y[0], p.velocity * y[1], *p.history);
  return std::isfinite(dydt[1]) ? GSL_SUCCESS : GSL_EBADFUNC;
}

// Overlap L at which the quasi-static work of the loading law equals the impact energy.
double energy_length_scale(const ForceLaw& law, double energy) {
  const ContactHistory fresh{};
  const auto work = [&](double delta) {
    double sum = 0.0;
    constexpr int kPanels = 64;
    for (int k = 0; k < kPanels; ++k) {  // midpoint rule: accuracy of a scale is enough
      const double x = (k + 0.5) * delta / kPanels;
      sum += law(x, 0.0, fresh);
    }
    return sum * delta / kPanels;
  };
  double hi = 1e-15;
  while (work(hi) < energy) {
    hi *= 4.0;
    if (hi > 1e6)
      throw std::runtime_error("simulate_impact: the law never stores the impact energy");
  }
  double lo = hi / 4.0;
  for (int i = 0; i < 30; ++i) {
    const double mid = std::sqrt(lo * hi);
    (work(mid) < energy ? lo : hi) = mid;
  }
  return hi;
}

struct Gsl {
  std::unique_ptr<gsl_odeiv2_step, decltype(&gsl_odeiv2_step_free)> step{
      gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, 2), &gsl_odeiv2_step_free};
  std::unique_ptr<gsl_odeiv2_step, decltype(&gsl_odeiv2_step_free)> probe{
      gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, 2), &gsl_odeiv2_step_free};
  std::unique_ptr<gsl_odeiv2_evolve, decltype(&gsl_odeiv2_evolve_free)> evolve{
      gsl_odeiv2_evolve_alloc(2), &gsl_odeiv2_evolve_free};
  std::unique_ptr<gsl_odeiv2_control, decltype(&gsl_odeiv2_control_free)> control;
  explicit Gsl(double tol)
      : control(gsl_odeiv2_control_y_new(tol, tol), &gsl_odeiv2_control_free) {}
};

// One probe step of size h from y0 (accurate: h is within an accepted step).
std::array<double, 2> probe_step(Gsl& gsl,
                                 gsl_odeiv2_system& sys,
                                 const std::array<double, 2>& y0,
                                 double h) {
  std::array<double, 2> y = y0;
  std::array<double, 2> err{};
  if (h <= 0.0) return y;
  gsl_odeiv2_step_reset(gsl.probe.get());
  gsl_odeiv2_step_apply(gsl.probe.get(), 0.0, h, y.data(), err.data(), nullptr, nullptr, &sys);
  return y;
}

// The step length in (0, dt] at which component `index` reaches zero.
double locate_zero(Gsl& gsl,
                   gsl_odeiv2_system& sys,
                   const std::array<double, 2>& y0,
                   double dt,
                   std::size_t index) {
  const auto f = [&](double h) { return probe_step(gsl, sys, y0, h)[index]; };
  if (f(dt) > 0.0) return dt;  // the accepted step and the probe disagree at round-off
  return detail::brent_root(f, 0.0, dt, dt * 1e-15, 0.0);
}

}  // namespace

ImpactOutcome simulate_impact(const ForceLaw& law,
                              double effective_mass,
                              double impact_velocity,
                              const ImpactOptions& options) {
  require_positive("effective_mass", effective_mass, "[kg]");
  require_positive("impact_velocity", impact_velocity, "[m/s]");
  gsl_set_error_handler_off();
  ContactHistory history{.impact_velocity = impact_velocity};
  const double energy = 0.5 * effective_mass * impact_velocity * impact_velocity;
  const double length = energy_length_scale(law, energy);
  Scaled scaled{&law, &history, length, impact_velocity, length / (2.0 * energy)};
  gsl_odeiv2_system sys{&scaled_rhs, nullptr, 2, &scaled};
  Gsl gsl(options.tolerance);
  std::array<double, 2> y{0.0, 1.0};
  double tau = 0.0;
  double h = 1e-3;
  for (long n = 0; n < options.max_steps; ++n) {
    const std::array<double, 2> y_prev = y;
    const double tau_prev = tau;
    const int status = gsl_odeiv2_evolve_apply(gsl.evolve.get(), gsl.control.get(), gsl.step.get(),
                                               &sys, &tau, 1e9, &h, y.data());
    if (status != GSL_SUCCESS) throw std::runtime_error("simulate_impact: integration failed");
    if (!history.unloading && y[1] <= 0.0) {  // velocity reversal: start unloading there
      const double dt = locate_zero(gsl, sys, y_prev, tau - tau_prev, 1);
      y = probe_step(gsl, sys, y_prev, dt);
      y[1] = 0.0;
      tau = tau_prev + dt;
      history.unloading = true;
      history.max_overlap = length * y[0];
      gsl_odeiv2_evolve_reset(gsl.evolve.get());
      gsl_odeiv2_step_reset(gsl.step.get());
      continue;
    }
    if (history.unloading && y[0] <= 0.0) {  // separation
      const double dt = locate_zero(gsl, sys, y_prev, tau - tau_prev, 0);
      const auto end = probe_step(gsl, sys, y_prev, dt);
      return {.restitution = -end[1],
              .contact_time = (tau_prev + dt) * length / impact_velocity,
              .max_overlap = history.max_overlap};
    }
    if (tau > 1e6) break;
  }
  throw NotSeparated("simulate_impact: the bodies did not separate (overdamped or stuck)");
}

}  // namespace corlab::dem
