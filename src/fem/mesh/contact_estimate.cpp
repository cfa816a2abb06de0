// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/mesh/contact_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "corlab/materials/material.hpp"

namespace corlab::fem {

double sphere_mass(double radius, double density) {
  return 4.0 / 3.0 * std::numbers::pi * radius * radius * radius * density;
}

double contact_curvature_radius(const ImpactConfig& config) {
  const double r1 = config.sphere.radius;
  if (!sphere_target(config)) return r1;
  const double r2 = config.substrate.radius;
  return r1 * r2 / (r1 + r2);
}

double contact_mass(const ImpactConfig& config) {
  const double m1 = sphere_mass(config.sphere.radius, config.sphere.material.density);
  if (!sphere_target(config)) return m1;
  const double m2 = sphere_mass(config.substrate.radius, config.substrate.material.density);
  return m1 * m2 / (m1 + m2);
}

double hertz_force(double overlap, double sphere_radius, double effective_modulus) {
  return 4.0 / 3.0 * effective_modulus * std::sqrt(sphere_radius) *
         std::pow(std::max(overlap, 0.0), 1.5);
}

double hertz_contact_radius(double overlap, double sphere_radius) {
  return std::sqrt(sphere_radius * std::max(overlap, 0.0));
}

double hertz_max_pressure(const HertzReference& hertz) {
  return 1.5 * hertz.max_force / (std::numbers::pi * hertz.contact_radius * hertz.contact_radius);
}

HertzReference hertz_reference_of_pair(double radius,
                                       double effective_modulus,
                                       double mass,
                                       double velocity) {
  HertzReference ref;
  const double r = radius;
  ref.effective_modulus = effective_modulus;
  ref.mass = mass;
  ref.max_overlap = std::pow(
      15.0 * ref.mass * velocity * velocity / (16.0 * effective_modulus * std::sqrt(r)), 0.4);
  ref.max_force = hertz_force(ref.max_overlap, r, effective_modulus);
  ref.contact_radius = hertz_contact_radius(ref.max_overlap, r);
  ref.contact_time = hertz_contact_time_factor() * ref.max_overlap / velocity;
  return ref;
}

HertzReference hertz_reference(double sphere_radius,
                               double effective_modulus,
                               double sphere_density,
                               double velocity) {
  return hertz_reference_of_pair(sphere_radius, effective_modulus,
                                 sphere_mass(sphere_radius, sphere_density), velocity);
}

HertzReference hertz_reference(const ImpactConfig& config) {
  return hertz_reference_of_pair(contact_curvature_radius(config),
                                 contact_effective_modulus(config), contact_mass(config),
                                 config.impact.velocity);
}

double plastic_contact_radius_of_pair(double radius,
                                      double mass,
                                      double velocity,
                                      double yield_stress) {
  const double r = radius;
  const double mean_pressure = kPlasticMeanPressureFactor * yield_stress;
  // m v^2 / 2 = pi p_m R delta^2  ->  delta; then a^2 = 2 R delta.
  const double delta =
      std::sqrt(mass * velocity * velocity / (2.0 * std::numbers::pi * mean_pressure * r));
  return std::sqrt(2.0 * r * delta);
}

double plastic_contact_radius(double sphere_radius,
                              double sphere_density,
                              double velocity,
                              double yield_stress) {
  return plastic_contact_radius_of_pair(sphere_radius, sphere_mass(sphere_radius, sphere_density),
                                        velocity, yield_stress);
}

double uncapped_contact_radius(const ImpactConfig& config) {
  double a = hertz_reference(config).contact_radius;
  if (const std::optional<double> sy = contact_yield_stress(config)) {
    a = std::max(
        a, plastic_contact_radius_of_pair(contact_curvature_radius(config), contact_mass(config),
                                          config.impact.velocity, *sy));
  }
  return a;
}

double predicted_contact_radius(const ImpactConfig& config) {
  double r = config.sphere.radius;
  if (sphere_target(config)) r = std::min(r, config.substrate.radius);
  return std::min(uncapped_contact_radius(config), kMaxContactRadiusFraction * r);
}

}  // namespace corlab::fem
