// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dataset/impact_box.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "corlab/core/error.hpp"
#include "corlab/restitution/first_yield.hpp"

namespace corlab::dataset {
namespace {

double linear(const Range& r, double u) { return r.min + u * (r.max - r.min); }
double logarithmic(const Range& r, double u) {
  return std::exp(std::log(r.min) + u * (std::log(r.max) - std::log(r.min)));
}

// Effective modulus of the point's pair [Pa].
double point_effective_modulus(const ImpactBox& box, const DimensionlessImpact& p) {
  return effective_modulus(p.modulus_ratio * box.substrate_modulus, p.nu_sphere,
                           box.substrate_modulus, p.nu_substrate);
}

// rho* of the point's pair [kg/m^3].
double point_effective_density(const ImpactBox& box, const DimensionlessImpact& p) {
  return pair_effective_density(p.radius_ratio, p.density_ratio * box.density, p.density_ratio);
}

// Largest impact speed of the point: velocity_max, or less where the damage number
// rho* v^2 / sigma_y would pass its bound [m/s].
double speed_limit(const ImpactBox& box, const DimensionlessImpact& p, double substrate_yield) {
  return std::min(box.velocity_max, std::sqrt(box.damage_number_max * substrate_yield /
                                              point_effective_density(box, p)));
}

// The pair's first yield (v_y with rho*).
restitution::FirstYield point_first_yield(const ImpactBox& box, const DimensionlessImpact& p) {
  const PointMaterials m = point_materials(box, p);
  return restitution::first_yield(m.sphere, m.substrate, point_effective_density(box, p));
}

std::string text(double v) { return fmt::format("{}", v); }

}  // namespace

ImpactBox pair_box() {
  ImpactBox box;
  box.modulus_ratio = {0.05, 20.0};
  box.density_ratio = {0.1, 10.0};
  box.flat_fraction = 0.25;
  box.radius_ratio = {0.1, 1.0};
  return box;
}

bool is_pair_box(const ImpactBox& box) {
  return box.density_ratio.min != 1.0 || box.density_ratio.max != 1.0 || box.flat_fraction < 1.0;
}

int box_dimension(const ImpactBox& box) {
  return is_pair_box(box) ? kPairBoxDimension : kBoxDimension;
}

DimensionlessImpact box_point(const ImpactBox& box, std::span<const double> u) {
  const int dimension = box_dimension(box);
  if (u.size() != static_cast<std::size_t>(dimension)) {
    throw_invalid("design point dimension", static_cast<double>(u.size()),
                  fmt::format("{}", dimension));
  }
  DimensionlessImpact p;
  p.k2 = logarithmic(box.k2, u[0]);
  p.modulus_ratio = logarithmic(box.modulus_ratio, u[2]);
  if (u[3] >= box.elastic_sphere_fraction) {
    const double w = (u[3] - box.elastic_sphere_fraction) / (1.0 - box.elastic_sphere_fraction);
    p.sphere_yield_ratio = logarithmic(box.sphere_yield_ratio, w);
  }
  p.nu_substrate = linear(box.nu, u[4]);
  p.hardening_ratio = linear(box.hardening_ratio, u[5]);
  p.nu_sphere = linear(box.nu, u[6]);
  if (dimension == kPairBoxDimension) {
    p.density_ratio = logarithmic(box.density_ratio, u[7]);
    if (u[8] >= box.flat_fraction) {
      const double w = (u[8] - box.flat_fraction) / (1.0 - box.flat_fraction);
      p.radius_ratio = linear(box.radius_ratio, w);
    }
  }
  // The velocity range depends on the first-yield speed of this pair.
  p.velocity_ratio = 1.0;
  const PointMaterials m = point_materials(box, p);
  const double v_y = point_first_yield(box, p).velocity;
  const double ratio_max = speed_limit(box, p, *m.substrate.yield_stress) / v_y;
  p.velocity_ratio = logarithmic({box.velocity_ratio_min, ratio_max}, u[1]);
  return p;
}

PointMaterials point_materials(const ImpactBox& box, const DimensionlessImpact& p) {
  const double substrate_yield = p.k2 * point_effective_modulus(box, p);
  PointMaterials m;
  m.substrate = Material{.name = "inline",
                         .youngs_modulus = box.substrate_modulus,
                         .poisson_ratio = p.nu_substrate,
                         .density = box.density,
                         .yield_stress = substrate_yield,
                         .hardening_modulus = p.hardening_ratio * box.substrate_modulus,
                         .source = "corlab dataset box"};
  const double sphere_modulus = p.modulus_ratio * box.substrate_modulus;
  m.sphere = Material{.name = "inline",
                      .youngs_modulus = sphere_modulus,
                      .poisson_ratio = p.nu_sphere,
                      .density = p.density_ratio * box.density,
                      .yield_stress = std::nullopt,
                      .hardening_modulus = 0.0,
                      .source = "corlab dataset box"};
  if (p.sphere_yield_ratio) {
    m.sphere.yield_stress = *p.sphere_yield_ratio * substrate_yield;
    m.sphere.hardening_modulus = p.hardening_ratio * sphere_modulus;
  }
  return m;
}

double point_velocity(const ImpactBox& box, const DimensionlessImpact& p) {
  return p.velocity_ratio * point_first_yield(box, p).velocity;
}

study::Settings point_settings(const ImpactBox& box, const DimensionlessImpact& p) {
  const PointMaterials m = point_materials(box, p);
  study::Settings settings{
      {"sphere.E", text(m.sphere.youngs_modulus)},
      {"sphere.nu", text(m.sphere.poisson_ratio)},
      {"sphere.sigma_y", m.sphere.yield_stress ? text(*m.sphere.yield_stress) : "none"},
      {"sphere.hardening", text(m.sphere.hardening_modulus)},
      {"substrate.nu", text(m.substrate.poisson_ratio)},
      {"substrate.sigma_y", text(*m.substrate.yield_stress)},
      {"substrate.hardening", text(m.substrate.hardening_modulus)},
      {"impact.velocity", text(point_velocity(box, p))},
  };
  if (is_pair_box(box)) {
    settings.emplace_back("sphere.rho", text(m.sphere.density));
    const bool flat = p.radius_ratio == 0.0;
    settings.emplace_back("substrate.shape", flat ? "flat" : "sphere");
    if (!flat)
      settings.emplace_back("substrate.radius", text(fem::SphereConfig{}.radius / p.radius_ratio));
  }
  return settings;
}

DimensionlessInputs dimensionless_inputs(const fem::ImpactConfig& config) {
  constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const Material& s = config.sphere.material;
  const Material& b = config.substrate.material;
  const double v = config.impact.velocity;
  const double e_star = fem::contact_effective_modulus(config);
  DimensionlessInputs d;
  d.radius_ratio =
      fem::sphere_target(config) ? config.sphere.radius / config.substrate.radius : 0.0;
  d.effective_density = pair_effective_density(d.radius_ratio, s.density, s.density / b.density);
  d.k1 = k1(e_star, d.effective_density, v);
  d.k2 = b.yield_stress ? k2(*b.yield_stress, e_star) : kNan;
  d.velocity_ratio = kNan;
  d.first_yield_velocity = kNan;
  if (s.yield_stress || b.yield_stress) {
    const restitution::FirstYield y = restitution::first_yield(s, b, d.effective_density);
    d.first_yield_velocity = y.velocity;
    d.velocity_ratio = v / y.velocity;
    d.sphere_yields_first = y.sphere_first;
  }
  d.modulus_ratio = s.youngs_modulus / b.youngs_modulus;
  d.sphere_yield_ratio =
      !s.yield_stress ? kInf : (b.yield_stress ? *s.yield_stress / *b.yield_stress : kNan);
  d.nu_sphere = s.poisson_ratio;
  d.nu_substrate = b.poisson_ratio;
  d.hardening_ratio_sphere = s.hardening_modulus / s.youngs_modulus;
  d.hardening_ratio_substrate = b.hardening_modulus / b.youngs_modulus;
  d.density_ratio = s.density / b.density;
  d.damage_number = b.yield_stress ? d.effective_density * v * v / *b.yield_stress : kNan;
  return d;
}

}  // namespace corlab::dataset
