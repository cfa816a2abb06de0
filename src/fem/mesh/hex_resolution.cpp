// The 3-D model's element size at the contact (hex_resolution.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/mesh/hex_resolution.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "corlab/core/error.hpp"
#include "corlab/fem/mesh/contact_estimate.hpp"

namespace corlab::fem {
namespace {

// The predicted contact radius at the normal speed v cos(angle) [m].
double normal_contact_radius(const ImpactConfig& config) {
  ImpactConfig normal = config;
  normal.impact.velocity = normal_velocity(config);
  return predicted_contact_radius(normal);
}

// The largest body size the limit R / h, w / h, depth / h <= 2000 reads [m].
double largest_size(const ImpactConfig& config) {
  double size = config.sphere.radius;
  if (config.substrate.shape == SubstrateShape::kFlat)
    size = std::max({size, config.substrate.radius, config.substrate.depth});
  return size;
}

// The model's default block [m] (HexResolution::block_size) for the element size h [m]: the
// wave-travel rule, at most the default size and 2000 h, at least twice the fine zone (the
// generator's own bound: hex_mesh_generator.hpp).
double default_block(const ImpactConfig& config, double a, double h) {
  ImpactConfig normal = config;
  normal.impact.velocity = normal_velocity(config);
  const double wave = kDefaultBlockWaveFraction *
                      config.substrate.material.dilatational_wave_speed() *
                      hertz_reference(normal).contact_time;
  const double zone = std::max(2.0 * (config.mesh.refine_factor * a + contact_travel(config)),
                               2.0 * std::max(config.mesh.refine_depth * a, 2.0 * h));
  return std::max(std::min({wave, SubstrateConfig{}.radius, kMaxSizeOverElement * h}), zone);
}

// Whether the block is the model's to choose: the flat with neither size key nor the boundary set.
bool default_block_keys(const ImpactConfig& config) {
  const SubstrateConfig d;
  return config.substrate.shape == SubstrateShape::kFlat && config.substrate.radius == d.radius &&
         config.substrate.depth == d.depth && config.substrate.boundary == d.boundary;
}

// No default mesh: the InputError naming the keys that give one (a [m] the predicted contact
// radius, h_finest [m] the limit's smallest h, size [m] the largest body).
[[noreturn]] void refuse_default(const ImpactConfig& config,
                                 double a,
                                 double h_finest,
                                 double size) {
  const double n = std::floor(10.0 * a / h_finest) / 10.0;
  // Where the sphere itself is the largest body, a smaller block does not help.
  const double block_fit = kMaxSizeOverElement * a / kMinDefaultContactElements;
  const bool block_helps = config.sphere.radius <= block_fit;
  std::string keys;
  if (n >= 1.0)
    keys = fmt::format(
        "set mesh.contact_elements = {:g} (coarser than the default's {:g}: check "
        "it with --error-estimate)",
        n, kMinDefaultContactElements);
  if (block_helps)
    keys += fmt::format("{}substrate.radius and substrate.depth <= {:.3g} m",
                        keys.empty() ? "set " : ", or ", block_fit);
  if (keys.empty())
    keys = fmt::format("set mesh.h_min >= {:.3g} m and mesh.contact_elements = 0", h_finest);
  throw InputError(fmt::format(
      "invalid mesh.contact_elements = default: no default 3-D mesh for this case: the predicted "
      "contact radius a = {:.3g} m needs h <= a / {:g} = {:.3g} m, finer than the limit h >= "
      "{:.3g} m / {:g} = {:.3g} m (the largest body); {}",
      a, kMinDefaultContactElements, a / kMinDefaultContactElements, size, kMaxSizeOverElement,
      h_finest, keys));
}

}  // namespace

double contact_travel(const ImpactConfig& config) {
  ImpactConfig normal = config;
  normal.impact.velocity = normal_velocity(config);
  const double v_t = config.impact.velocity * std::sin(config.impact.angle.radians);
  return v_t * 1.5 * hertz_reference(normal).contact_time;
}

bool uses_default_3d_resolution(const ImpactConfig& config) {
  const MeshConfig d;
  return uses_3d_model(config) && config.mesh.h_min == d.h_min &&
         config.mesh.contact_elements == d.contact_elements;
}

HexResolution hex_resolution(const ImpactConfig& config) {
  const double a = normal_contact_radius(config);
  HexResolution r;
  r.contact_radius = a;
  r.boundary = config.substrate.boundary;
  r.growth = config.mesh.growth;
  if (!uses_default_3d_resolution(config)) {
    r.h_contact = config.mesh.h_min;
    if (config.mesh.contact_elements > 0.0)
      r.h_contact = std::min(r.h_contact, a / config.mesh.contact_elements);
    r.reason = fmt::format("set: min(mesh.h_min, a / mesh.contact_elements), a/h = {:.3g}",
                           a / r.h_contact);
    return r;
  }
  r.model_choice = true;
  if (config.mesh.growth == MeshConfig{}.growth) r.growth = kDefaultGrowth3d;
  const double size = largest_size(config);
  const double h_finest = size / kMaxSizeOverElement;     // the limit's smallest h [m]
  const double h_coarsest = 0.05 * config.sphere.radius;  // the sphere's R / 20 [m]
  const double h_default = std::min(a / kDefaultContactElements, h_coarsest);
  const std::string basis = fmt::format(
      "a/4: Kharaz's e_t within 0.002 of a/6 (9.5 deg), inside its error bar; growth {:g} ({}) "
      "(docs/theory/solver3d.md)",
      r.growth,
      r.growth == kDefaultGrowth3d ? "e_n, e_t, omega within 0.13 of their bars of 1.15's"
                                   : "mesh.growth");
  if (default_block_keys(config) && config.sphere.radius <= kMaxSizeOverElement * h_default) {
    r.h_contact = h_default;
    r.block_size = default_block(config, a, h_default);
    r.boundary = SubstrateBoundary::kViscousSpring;
    r.reason = fmt::format(
        "model default: h = {:.3g} m, {:.3g} elements across the predicted contact radius a = "
        "{:.3g} m, on a block {:.3g} m wide and deep with the viscous_spring far boundary "
        "({:g} c_p t_c, at most 70 mm and 2000 h: e_n within 0.003 of the half-space's, "
        "docs/theory/solver3d.md; neither substrate size key nor substrate.boundary set); {}",
        r.h_contact, a / r.h_contact, a, r.block_size, kDefaultBlockWaveFraction, basis);
    return r;
  }
  if (h_default >= h_finest) {
    r.h_contact = h_default;
    r.reason = fmt::format(
        "model default: h = {:.3g} m, {:.3g} elements across the predicted "
        "contact radius a = {:.3g} m; {}",
        r.h_contact, a / r.h_contact, a, basis);
    return r;
  }
  const SubstrateConfig d;
  if (config.substrate.shape == SubstrateShape::kFlat && config.substrate.radius == d.radius &&
      config.substrate.depth == d.depth &&
      config.sphere.radius <= kMaxSizeOverElement * h_default) {
    r.h_contact = h_default;
    r.block_size = kMaxSizeOverElement * h_default;
    r.reason = fmt::format(
        "model default: h = {:.3g} m, {:.3g} elements across the predicted "
        "contact radius a = {:.3g} m, on a block {:.3g} m wide and deep "
        "(size / h <= {:g}; neither substrate size key set); {}",
        r.h_contact, a / r.h_contact, a, r.block_size, kMaxSizeOverElement, basis);
    return r;
  }
  if (a / h_finest >= kMinDefaultContactElements) {
    r.h_contact = h_finest;
    r.reason = fmt::format(
        "model default: h = {:.3g} m, {:.3g} elements across the predicted "
        "contact radius a = {:.3g} m (the finest the limit size / h <= {:g} "
        "allows with a body {:.3g} m large; {})",
        r.h_contact, a / r.h_contact, a, kMaxSizeOverElement, size, basis);
    return r;
  }
  refuse_default(config, a, h_finest, size);
}

ImpactConfig with_resolved_3d_mesh(const ImpactConfig& config) {
  if (!uses_default_3d_resolution(config)) return config;
  const HexResolution r = hex_resolution(config);
  ImpactConfig c = config;
  c.mesh.h_min = r.h_contact;
  c.mesh.contact_elements = 0.0;
  c.mesh.growth = r.growth;
  c.mesh.h_max = std::max(c.mesh.h_max, c.mesh.h_min);
  if (r.block_size > 0.0) c.substrate.radius = c.substrate.depth = r.block_size;
  c.substrate.boundary = r.boundary;
  return c;
}

}  // namespace corlab::fem
