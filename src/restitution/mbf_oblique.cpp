// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/restitution/mbf_oblique.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "corlab/core/error.hpp"
#include "corlab/core/units.hpp"
#include "corlab/materials/material.hpp"

namespace corlab::restitution {
namespace {

using units::kDegree;
using units::kPi;

void check(const char* field, double value, bool ok, const char* constraint) {
  if (std::isnan(value) || !ok) throw_invalid(field, value, constraint);
}

// The annuli in the normalised problem. Lengths are in a_max = sqrt(R alpha_max), the normal
// approach x in alpha_max, an annulus's tangential force f_j in 2 mu E* a_max alpha_max (so
// that its Coulomb bound is the integral of x - xi^2 over its contact part, and the normal force
// times mu is 2/3 x^(3/2) in the same unit), the tangential displacement in mu alpha_max / kappa.
class Annuli {
 public:
  explicit Annuli(int count) : width_(1.0 / count), force_(static_cast<std::size_t>(count), 0.0) {}

  // Advances every annulus from approach x_old to x_new under the relative tangential
  // displacement `slide`; returns the total force. `all_slip` turns false when an annulus in
  // contact stuck.
  double advance(double x_old, double x_new, double slide, bool coulomb, bool& all_slip) {
    const double edge_old = std::sqrt(std::max(x_old, 0.0));
    const double edge_new = std::sqrt(std::max(x_new, 0.0));
    double total = 0.0;
    for (std::size_t j = 0; j < force_.size(); ++j) {
      const double lo = static_cast<double>(j) * width_;
      if (lo >= edge_new) {  // out of contact: traction released (and all beyond, too)
        std::fill(force_.begin() + static_cast<std::ptrdiff_t>(j), force_.end(), 0.0);
        break;
      }
      // The part of the annulus in contact during the step (the last annulus is unbounded).
      const bool last = j + 1 == force_.size();
      const double hi_new = last ? edge_new : std::min(lo + width_, edge_new);
      const double hi_old = last ? edge_old : std::min(lo + width_, edge_old);
      const double length = 0.5 * (std::max(hi_old - lo, 0.0) + (hi_new - lo));
      const double trial = force_[j] + length * slide;
      if (coulomb) {
        // The Coulomb bound: the annulus's share of the normal force, exactly integrated.
        const double bound =
            x_new * (hi_new - lo) - (hi_new * hi_new * hi_new - lo * lo * lo) / 3.0;
        force_[j] = std::clamp(trial, -bound, bound);
        if (std::abs(trial) <= bound) all_slip = false;
      } else {
        force_[j] = trial;
        all_slip = false;
      }
      total += force_[j];
    }
    return total;
  }

 private:
  double width_;
  std::vector<double> force_;
};

int sign_of(double value, double tolerance) {
  if (value > tolerance) return 1;
  if (value < -tolerance) return -1;
  return 0;
}

}  // namespace

MbfNormalised mbf_normalised(double chi, double psi1, const MbfDiscretisation& d) {
  check("chi", chi, chi > 0.0 && std::isfinite(chi), "> 0 and finite");
  check("psi1", psi1, psi1 >= 0.0 && std::isfinite(psi1), ">= 0 and finite");
  check("annuli", d.annuli, d.annuli >= 4, ">= 4");
  check("time_steps", d.time_steps, d.time_steps >= 100, ">= 100");
  // Normalised time tau = t v_n / alpha_max: x'' = -(5/4) x^(3/2) (Hertz, x' = 1 at x = 0) and
  // u'' = -(15/4) chi F, u = kappa (v_t - R omega) / (mu v_n), F the annuli's force sum.
  // Hertz's contact time in alpha_max / v_n over the steps.
  const double dt = hertz_contact_time_factor() / d.time_steps;
  Annuli annuli(d.annuli);
  double x = 0.0;
  double x_rate = 1.0;  // at the half steps (the force vanishes at x = 0)
  double u = psi1;      // at the half steps
  double tau = 0.0;
  bool all_slip = true;
  int last_sign = 0;
  MbfNormalised out;
  const double tolerance = 1e-12 * std::max(psi1, 1e-300);
  for (long step = 0; step < 4L * d.time_steps; ++step) {
    const double x_new = x + dt * x_rate;
    tau += dt;
    if (x_new <= 0.0) {  // the contact opened during the step: interpolate its time
      tau -= dt * x_new / x_rate;
      x = x_new;
      break;
    }
    const double force = annuli.advance(x, x_new, dt * u, d.coulomb, all_slip);
    x = x_new;
    x_rate -= dt * 1.25 * x * std::sqrt(x);
    u -= dt * 3.75 * chi * force;
    const int s = sign_of(force, tolerance);
    if (s != 0 && last_sign != 0 && s != last_sign) ++out.force_reversals;
    if (s != 0) last_sign = s;
  }
  if (x > 0.0) {  // cannot happen for Hertz (the contact opens after 1 contact time)
    out.psi2 = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  out.normal_restitution = -x_rate;
  out.psi2 = u / out.normal_restitution;
  out.contact_point_ratio = psi1 > 0.0 ? u / psi1 : std::numeric_limits<double>::quiet_NaN();
  out.contact_time = tau;
  out.gross_sliding = all_slip && d.coulomb && psi1 > 0.0;
  return out;
}

double mbf_stiffness_ratio(double modulus1, double poisson1, double modulus2, double poisson2) {
  check("sphere_modulus", modulus1, modulus1 > 0.0, "> 0");
  check("flat_modulus", modulus2, modulus2 > 0.0, "> 0 (+infinity: rigid)");
  check("sphere_poisson", poisson1, poisson1 > -1.0 && poisson1 < 0.5, "in (-1, 0.5)");
  check("flat_poisson", poisson2, poisson2 > -1.0 && poisson2 < 0.5, "in (-1, 0.5)");
  if (std::isinf(modulus1)) throw_invalid("sphere_modulus", modulus1, "finite");
  // Compliances in 1/G_i (a rigid body contributes nothing).
  const double c1 = 2.0 * (1.0 + poisson1) / modulus1;
  const double c2 = std::isinf(modulus2) ? 0.0 : 2.0 * (1.0 + poisson2) / modulus2;
  return ((1.0 - poisson1) * c1 + (1.0 - poisson2) * c2) /
         ((1.0 - 0.5 * poisson1) * c1 + (1.0 - 0.5 * poisson2) * c2);
}

double mbf_chi(double stiffness_ratio, double gyration) {
  check("stiffness_ratio", stiffness_ratio, stiffness_ratio > 0.0 && std::isfinite(stiffness_ratio),
        "> 0 and finite");
  check("gyration", gyration, gyration > 0.0 && gyration <= 1.0, "in (0, 1] (I / (m R^2))");
  return 0.5 * stiffness_ratio * (1.0 + 1.0 / gyration);
}

MbfRebound mbf_rebound(const MbfImpact& in, const MbfDiscretisation& d) {
  check("radius", in.radius, in.radius > 0.0 && std::isfinite(in.radius), "> 0 and finite");
  check("density", in.density, in.density > 0.0 && std::isfinite(in.density), "> 0 and finite");
  check("velocity", in.velocity, in.velocity > 0.0 && std::isfinite(in.velocity), "> 0 and finite");
  check("angle", in.angle, in.angle > 0.0 && in.angle < 90.0, "in (0, 90) degrees");
  check("friction", in.friction, in.friction > 0.0 && std::isfinite(in.friction),
        "> 0 and finite (mu = 0 is frictionless: e_t = 1)");
  MbfRebound out;
  out.stiffness_ratio =
      mbf_stiffness_ratio(in.sphere_modulus, in.sphere_poisson, in.flat_modulus, in.flat_poisson);
  out.chi = mbf_chi(out.stiffness_ratio, in.gyration);
  const double theta = in.angle * kDegree;
  const double v_n = in.velocity * std::cos(theta);
  const double v_t = in.velocity * std::sin(theta);
  out.psi1 = out.stiffness_ratio * v_t / (in.friction * v_n);
  const MbfNormalised n = mbf_normalised(out.chi, out.psi1, d);
  out.psi2 = n.psi2;
  out.normal_restitution = n.normal_restitution;
  out.force_reversals = n.force_reversals;
  out.gross_sliding = n.gross_sliding;
  // The contact point's velocity change gives the impulse per unit mass [m/s].
  out.contact_slip_velocity =
      n.psi2 * n.normal_restitution * in.friction * v_n / out.stiffness_ratio;
  const double impulse = (v_t - out.contact_slip_velocity) / (1.0 + 1.0 / in.gyration);
  const double mass = 4.0 / 3.0 * kPi * in.radius * in.radius * in.radius * in.density;
  out.tangential_impulse = mass * impulse;
  out.tangential_restitution = (v_t - impulse) / v_t;
  out.spin = impulse / (in.gyration * in.radius);
  out.rebound_angle = std::atan2(v_t - impulse, n.normal_restitution * v_n) / kDegree;
  // Hertz: alpha_max = (15 m v_n^2 / (16 E* sqrt(R)))^(2/5).
  const double flat_compliance = std::isinf(in.flat_modulus)
                                     ? 0.0
                                     : (1.0 - in.flat_poisson * in.flat_poisson) / in.flat_modulus;
  const double e_star =
      1.0 / ((1.0 - in.sphere_poisson * in.sphere_poisson) / in.sphere_modulus + flat_compliance);
  const double alpha_max =
      std::pow(15.0 * mass * v_n * v_n / (16.0 * e_star * std::sqrt(in.radius)), 0.4);
  out.contact_time = n.contact_time * alpha_max / v_n;
  return out;
}

}  // namespace corlab::restitution
