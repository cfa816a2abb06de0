// Hertz reference and predicted contact radius (contact_estimate.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "corlab/fem/mesh/contact_estimate.hpp"

namespace corlab::fem {
namespace {

// Independent check: integrate m x'' = -4/3 E* sqrt(R) x^(3/2) from x = 0, x' = v with RK4 and
// measure the peak overlap, peak force and contact duration.
struct OdeResult {
  double max_overlap = 0.0;
  double max_force = 0.0;
  double contact_time = 0.0;
};

OdeResult integrate_hertz(double radius, double e_star, double mass, double v) {
  const double k = 4.0 / 3.0 * e_star * std::sqrt(radius);
  auto acc = [&](double x) { return x > 0.0 ? -k * std::pow(x, 1.5) / mass : 0.0; };
  const double t_guess =
      3.0 * std::pow(15.0 * mass * v * v / (16.0 * e_star * std::sqrt(radius)), 0.4) / v;
  const double dt = t_guess / 200000.0;
  double x = 0.0;
  double u = v;
  double t = 0.0;
  OdeResult res;
  while (true) {
    const double k1x = u;
    const double k1u = acc(x);
    const double k2x = u + 0.5 * dt * k1u;
    const double k2u = acc(x + 0.5 * dt * k1x);
    const double k3x = u + 0.5 * dt * k2u;
    const double k3u = acc(x + 0.5 * dt * k2x);
    const double k4x = u + dt * k3u;
    const double k4u = acc(x + dt * k3x);
    const double xn = x + dt / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double un = u + dt / 6.0 * (k1u + 2 * k2u + 2 * k3u + k4u);
    if (xn <= 0.0 && t > 0.0) {
      res.contact_time = t + dt * x / (x - xn);  // linear interpolation of the zero crossing
      break;
    }
    x = xn;
    u = un;
    t += dt;
    res.max_overlap = std::max(res.max_overlap, x);
  }
  res.max_force = k * std::pow(res.max_overlap, 1.5);
  return res;
}

TEST(HertzReference, ContactTimeFactorMatchesQuadrature) {
  // 2 int_0^1 (1 - x^(5/2))^(-1/2) dx by the midpoint rule after x = 1 - u^2 (removes the
  // end singularity); Johnson (1985) quotes 2.94.
  const int n = 200000;
  double s = 0.0;
  for (int i = 0; i < n; ++i) {
    const double u = (i + 0.5) / n;
    const double x = 1.0 - u * u;
    s += 2.0 * u / std::sqrt(1.0 - std::pow(x, 2.5)) / n;
  }
  EXPECT_NEAR(hertz_contact_time_factor(), 2.0 * s, 1e-9);
  EXPECT_NEAR(hertz_contact_time_factor(), 2.9432751843, 1e-9);
}

TEST(HertzReference, PaperDefaultsMatchHandValues) {
  // Ma et al. 2023 Table 1: steel on steel, R = 35 mm, v = 5 m/s.
  const ImpactConfig config;
  const HertzReference ref = hertz_reference(config);
  EXPECT_NEAR(ref.effective_modulus, 210e9 / (2.0 * (1.0 - 0.09)), 1.0);
  EXPECT_NEAR(ref.mass, 1.4098158832372, 1e-12);
  EXPECT_NEAR(ref.max_overlap, 2.97821949477e-4, 1e-14);
  EXPECT_NEAR(ref.max_force, 147929.81655, 1e-3);
  EXPECT_NEAR(ref.contact_radius, 3.22858610412e-3, 1e-13);
  EXPECT_NEAR(ref.contact_time, 2.9432751843 * 2.97821949477e-4 / 5.0, 1e-12);
}

TEST(HertzReference, AgreesWithDirectIntegrationOfTheEquationOfMotion) {
  for (const double v : {0.1, 5.0, 70.0}) {
    const double radius = 0.01;
    const double e_star = 7.0e10;
    const double rho = 3900.0;
    const HertzReference ref = hertz_reference(radius, e_star, rho, v);
    const OdeResult ode = integrate_hertz(radius, e_star, ref.mass, v);
    EXPECT_NEAR(ref.max_overlap / ode.max_overlap, 1.0, 1e-6) << v;
    EXPECT_NEAR(ref.max_force / ode.max_force, 1.0, 1e-6) << v;
    EXPECT_NEAR(ref.contact_time / ode.contact_time, 1.0, 1e-6) << v;
  }
}

TEST(PredictedContactRadius, CoversHertzAndPlasticEstimates) {
  ImpactConfig config;
  for (const double v : {0.01, 0.1, 1.0, 5.0, 20.0, 70.0}) {
    config.impact.velocity = v;
    const double a = predicted_contact_radius(config);
    const double hertz = hertz_reference(config).contact_radius;
    const double plastic =
        plastic_contact_radius(config.sphere.radius, config.sphere.material.density, v, 500e6);
    EXPECT_GE(a, std::min(hertz, 0.9 * config.sphere.radius)) << v;
    EXPECT_GE(a, std::min(plastic, 0.9 * config.sphere.radius)) << v;
    EXPECT_LE(a, kMaxContactRadiusFraction * config.sphere.radius * (1 + 1e-15)) << v;
  }
  // the plastic estimate with p_m = 2 sigma_y: a^4 = m v^2 R / (2 pi p_m) * 4 ... by hand
  const double m = 4.0 / 3.0 * std::numbers::pi * std::pow(0.035, 3) * 7850.0;
  const double delta = std::sqrt(m * 25.0 / (2.0 * std::numbers::pi * 1.0e9 * 0.035));
  EXPECT_NEAR(plastic_contact_radius(0.035, 7850.0, 5.0, 500e6), std::sqrt(0.07 * delta), 1e-15);
  // elastic substrate: Hertz only
  config.impact.velocity = 5.0;
  config.substrate.material.yield_stress.reset();
  EXPECT_DOUBLE_EQ(predicted_contact_radius(config), hertz_reference(config).contact_radius);
}

TEST(PredictedContactRadius, GrowsWithVelocityAndIsCapped) {
  ImpactConfig config;
  double last = 0.0;
  for (const double v : {0.1, 1.0, 5.0, 20.0, 70.0, 500.0}) {
    config.impact.velocity = v;
    const double a = predicted_contact_radius(config);
    EXPECT_GE(a, last);
    last = a;
  }
  EXPECT_DOUBLE_EQ(last, 0.9 * config.sphere.radius);
}

}  // namespace
}  // namespace corlab::fem
