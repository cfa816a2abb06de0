// Limits that join config keys (config_limits.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/config/config_limits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include "corlab/core/error.hpp"
#include "corlab/core/units.hpp"
#include "corlab/fem/mesh/contact_estimate.hpp"
#include "corlab/fem/mesh/hex_mesh_generator.hpp"
#include "corlab/fem/mesh/hex_resolution.hpp"
#include "corlab/fem/mesh/mesh_generator.hpp"

namespace corlab::fem {

namespace {

void check_plastic_body(const Material& m, std::string_view body) {
  // On every body, elastic too: a value that cannot be a hardening modulus is an error, not
  // ignored until someone gives the body a yield stress.
  if (!(m.hardening_modulus < m.youngs_modulus)) {
    throw_invalid(fmt::format("{}.hardening", body), m.hardening_modulus,
                  fmt::format("< {}.E = {:g} [Pa]", body, m.youngs_modulus));
  }
  if (!m.yield_stress) return;
  const double sy = *m.yield_stress;
  const double strain = sy / m.youngs_modulus;
  if (!(strain >= kMinYieldStrain && strain < kMaxYieldStrain)) {
    throw_invalid(
        fmt::format("{}.sigma_y", body), sy,
        fmt::format("in [{:g}, {:g}) [Pa]: a yield strain sigma_y/E in [{:g}, {:g}) "
                    "with {}.E = {:g} Pa",
                    kMinYieldStrain * m.youngs_modulus, kMaxYieldStrain * m.youngs_modulus,
                    kMinYieldStrain, kMaxYieldStrain, body, m.youngs_modulus));
  }
}

// With either model: an h_max below h_min left the 3-D mesh uniform at the contact size (15x
// the elements, accepted while the axisymmetric model refused it).
void check_sizes(const ImpactConfig& c) {
  if (!(c.mesh.h_max >= c.mesh.h_min)) {
    throw_invalid("mesh.h_max", c.mesh.h_max,
                  fmt::format(">= mesh.h_min = {:g} [m]", c.mesh.h_min));
  }
}

void check_geometry(const ImpactConfig& c) {
  if (c.impact.gap > c.sphere.radius) {
    throw_invalid("impact.gap", c.impact.gap,
                  fmt::format("<= sphere.radius = {:g} [m] (the gap is crossed in exact free "
                              "flight; a wider one only loses precision)",
                              c.sphere.radius));
  }
  if (c.mesh.transitions != 0.0 && c.mesh.transitions != 1.0) {
    throw_invalid("mesh.transitions", c.mesh.transitions, "0 (off) or 1 (on)");
  }
  // The axisymmetric model takes both bodies from mesh.file; the 3-D model only its half sphere,
  // and builds the flat from these keys.
  if (!c.mesh.file.empty() && !uses_3d_model(c)) {
    if (rigid_target(c)) {
      throw_invalid("substrate.shape", "rigid",
                    "flat with mesh.file (the rigid flat is for the built-in sphere mesh)");
    }
    return;  // the file's geometry is used, not these keys
  }
  const double a = uncapped_contact_radius(c);
  if (!(a <= kMaxContactRadiusFraction * c.sphere.radius)) {
    throw_invalid(
        "impact.velocity", c.impact.velocity,
        fmt::format("low enough for the predicted contact radius ({:.3g} m) to stay <= "
                    "{:g} x sphere.radius = {:.3g} m (too fast, or too soft a contact: E* = "
                    "{:g} Pa, yield stress {} Pa)",
                    a, kMaxContactRadiusFraction, kMaxContactRadiusFraction * c.sphere.radius,
                    contact_effective_modulus(c),
                    contact_yield_stress(c) ? fmt::format("{:g}", *contact_yield_stress(c))
                                            : std::string("none")));
  }
  try {
    validate(mesh_options_for(c));  // the generator's own limits, reported on the user's key
  } catch (const InputError& err) {
    throw InputError(fmt::format("invalid mesh.h_min = {}: the mesh it gives is refused ({})",
                                 c.mesh.h_min, err.what()));
  }
  if (rigid_target(c)) return;  // no substrate body: its size keys are unused
  const double min_size = kMinSubstrateContactRadii * predicted_contact_radius(c);
  for (const auto& [key, value] : {std::pair{"substrate.radius", c.substrate.radius},
                                   std::pair{"substrate.depth", c.substrate.depth}}) {
    // A second sphere has a radius, no depth: the unused key is not checked (as a rigid flat's).
    if (sphere_target(c) && std::string_view(key) == "substrate.depth") continue;
    if (value < min_size) {
      throw_invalid(
          key, value,
          fmt::format(">= {:.3g} [m]: {:g} x the predicted contact radius {:.3g} m", min_size,
                      kMinSubstrateContactRadii, min_size / kMinSubstrateContactRadii));
    }
  }
}

void check_solver(const ImpactConfig& c) {
  const double max_safety = 1.0 / std::sqrt(1.0 + c.solver.penalty_scale);
  if (c.solver.safety_factor > max_safety) {
    throw_invalid("solver.safety_factor", c.solver.safety_factor,
                  fmt::format("<= 1/sqrt(1 + solver.penalty_scale) = {:.4f} (the contact "
                              "penalty stiffens the fastest mode)",
                              max_safety));
  }
  const double t_contact = contact_start_time(c);
  if (c.solver.t_max > 0.0 && !(c.solver.t_max > t_contact)) {
    throw_invalid("solver.t_max", c.solver.t_max,
                  fmt::format("0 (automatic) or > impact.gap / the normal speed = {:.4g} [s], the "
                              "moment of contact",
                              t_contact));
  }
}

// A key the model in use does not read, set to `value`: accepted at its default and at `also`
// (the value that says what the model does anyway), else refused naming the model.
void check_unread(
    std::string_view key, double value, double fallback, double also, std::string_view why) {
  if (value == fallback || value == also) return;
  const std::string alternative = also == fallback ? "" : fmt::format(" or {:g}", also);
  throw_invalid(
      key, value,
      fmt::format("{:g} (the default){} with solver.model = {}", fallback, alternative, why));
}

// The keys one model does not read: refused when set to something it would ignore.
void check_unread_keys(const ImpactConfig& c) {
  const ImpactConfig d;
  if (!uses_3d_model(c)) {
    check_unread("solver.hourglass_3d", c.solver.hourglass_3d, d.solver.hourglass_3d,
                 d.solver.hourglass_3d, "axisymmetric (the 3-D model's hexahedra only)");
    return;
  }
  const std::string_view no_subcycling = "3d (the 3-D model steps every element at the base step)";
  check_unread("solver.subcycling_levels", c.solver.subcycling_levels, d.solver.subcycling_levels,
               0.0, no_subcycling);
  const std::string_view no_scaling = "3d (the 3-D model does not scale masses)";
  check_unread("solver.mass_scaling_max", c.solver.mass_scaling_max, d.solver.mass_scaling_max, 1.0,
               no_scaling);
  check_unread("solver.mass_scaling_inertia", c.solver.mass_scaling_inertia,
               d.solver.mass_scaling_inertia, d.solver.mass_scaling_inertia, no_scaling);
  check_unread("solver.in_run_step_floor", c.solver.in_run_step_floor, d.solver.in_run_step_floor,
               0.0, no_scaling);
  check_unread("solver.in_run_added_mass", c.solver.in_run_added_mass, d.solver.in_run_added_mass,
               d.solver.in_run_added_mass, no_scaling);
  check_unread("solver.hourglass", c.solver.hourglass, d.solver.hourglass, d.solver.hourglass,
               "3d (its hexahedra take solver.hourglass_3d)");
  check_unread("mesh.transitions", c.mesh.transitions, d.mesh.transitions, 0.0,
               "3d (the 3-D mesh has no transitions)");
}

// What the 3-D model supports so far, and friction and angles only where a model has them.
void check_model(const ImpactConfig& c) {
  check_unread_keys(c);
  if (!uses_3d_model(c)) {
    if (c.impact.angle.radians != 0.0)
      throw_invalid("impact.angle", c.impact.angle.in_degrees(),
                    "0 with solver.model = axisymmetric (an oblique impact needs solver.model = "
                    "3d)");
    if (c.contact.friction != 0.0)
      throw_invalid("contact.friction", c.contact.friction,
                    "0 with the axisymmetric model (friction needs solver.model = 3d)");
    if (c.contact.enforcement != ContactConfig{}.enforcement)
      throw_invalid("contact.friction_enforcement", to_string(c.contact.enforcement),
                    fmt::format("{} (the default) with the axisymmetric model (friction needs "
                                "solver.model = 3d)",
                                to_string(ContactConfig{}.enforcement)));
    return;
  }
  if (c.impact.angle.radians > 0.0 && c.impact.angle.in_degrees() < kMinObliqueAngle) {
    throw_invalid("impact.angle", c.impact.angle.in_degrees(),
                  fmt::format("0 or >= {:g} [deg] (below it the tangential speed is too small "
                              "for e_t = v_x'/v_x to mean anything)",
                              kMinObliqueAngle));
  }
  if (sphere_target(c))
    throw_invalid("substrate.shape", to_string(c.substrate.shape),
                  "flat or rigid with the 3-D model (solver.model = 3d): its second sphere is not "
                  "built yet");
  if (c.impact.repeats != 1)
    throw_invalid("impact.repeats", c.impact.repeats, "1 with the 3-D model");
  const HexMeshOptions mesh = hex_mesh_options_for(c);  // names the keys where no default fits
  try {
    validate(mesh);
  } catch (const InputError& err) {
    if (uses_default_3d_resolution(c))
      throw InputError(fmt::format("the 3-D model's default mesh (h = {:.3g} m) is refused: {}",
                                   mesh.h_contact, err.what()));
    throw InputError(fmt::format("invalid mesh.h_min = {}: the 3-D mesh it gives is refused ({})",
                                 c.mesh.h_min, err.what()));
  }
}

/// Element size at distance d from the contact [m]: h within `zone`, then growing by
/// (growth - 1) per unit length (each element `growth` times its neighbour) up to h_max.
struct Grading {
  double h = 0.0;
  double zone = 0.0;
  double growth = 1.0;
  double h_max = 0.0;
  double at(double d) const {
    return d <= zone ? h : std::min(h_max, h + (growth - 1.0) * (d - zone));
  }
};

/// The integral of measure(d) / h(d)^dim over d in (0, extent]: the elements of a body whose
/// part at distance d from the contact has length (2-D) or area (3-D) measure(d). Midpoint rule
/// on a log-spaced grid from h/100 (the zone in a few uniform steps): 0.1 % of the exact value.
template <class Measure>
double graded_count(double extent, const Grading& g, int dim, Measure measure) {
  constexpr int kUniform = 64;
  constexpr int kLog = 512;
  double sum = 0.0;
  auto add = [&](double a, double b) {
    const double d = 0.5 * (a + b);
    sum += measure(d) / std::pow(g.at(d), dim) * (b - a);
  };
  const double inner = std::min(extent, g.zone);
  for (int i = 0; i < kUniform; ++i) add(inner * i / kUniform, inner * (i + 1) / kUniform);
  if (extent <= inner) return sum;
  const double ratio = std::pow(extent / inner, 1.0 / kLog);
  for (double a = inner; a < extent * (1.0 - 1e-12); a *= ratio)
    add(a, std::min(a * ratio, extent));
  return sum;
}

/// Elements of the axisymmetric flat block (width w, depth depth) with transitions: the quarter
/// circle of radius d about the contact corner inside the rectangle.
double block_elements_2d(double w, double depth, const Grading& g) {
  return graded_count(std::hypot(w, depth), g, 2, [w, depth](double d) {
    const double lo = std::acos(std::min(1.0, w / d));
    const double hi = std::asin(std::min(1.0, depth / d));
    return d * std::max(0.0, hi - lo);
  });
}

/// Intervals of a 1-D grading of `length` (graded_positions).
double intervals(double length, double h, double zone, double growth, double h_max) {
  return static_cast<double>(graded_positions(length, h, zone, growth, h_max).size() - 1);
}

/// Steps to the expected end of the run: run_cost.hpp's rule (1.3 Hertz contact times and 4
/// wave transits of the sphere and of a second sphere; 1.5 contact times in 3-D) over the step
/// `dt`, for every impact.
double expected_steps(const ImpactConfig& c, double dt) {
  const double t_hertz = hertz_reference(c).contact_time;
  double t = uses_3d_model(c) ? 1.5 * t_hertz : 1.3 * t_hertz;
  if (!uses_3d_model(c)) {
    double t_wave = 4.0 * c.sphere.radius / c.sphere.material.dilatational_wave_speed();
    if (sphere_target(c)) {
      t_wave = std::max(t_wave,
                        4.0 * c.substrate.radius / c.substrate.material.dilatational_wave_speed());
    }
    t += t_wave;
  }
  return t / dt * c.impact.repeats;
}

// The work caps, from the mesh's sizes before it is built (a 10 m second sphere meshed 2.8
// million elements and ran past 20 min).
void check_work(const ImpactConfig& c) {
  if (!c.mesh.file.empty()) return;  // element sizes unknown before reading the file
  const RunEstimate e = estimate_run(c);
  const auto raise = [](std::string_view key, double estimate, double cap, std::string_view what) {
    throw InputError(fmt::format(
        "invalid {} = {:.4g}: must be >= the {} estimated before meshing, {:.3g}; check "
        "sphere.radius, substrate.radius/depth, mesh.h_min, mesh.h_max and mesh.growth, or "
        "raise {} to run it",
        key, cap, what, estimate, key));
  };
  if (e.elements > static_cast<double>(c.solver.max_elements)) {
    raise("solver.max_elements", e.elements, static_cast<double>(c.solver.max_elements),
          "element count");
  }
  if (e.element_steps() > c.solver.max_element_steps) {
    raise("solver.max_element_steps", e.element_steps(), c.solver.max_element_steps,
          fmt::format("work (elements x expected steps: {:.3g} x {:.3g})", e.elements,
                      e.expected_steps));
  }
}

void check_step_budget(const ImpactConfig& c) {
  if (!c.mesh.file.empty()) return;  // element sizes unknown before reading the file
  const RunEstimate e = estimate_run(c);
  if (e.steps <= static_cast<double>(c.solver.max_steps)) return;
  throw InputError(fmt::format(
      "invalid solver.max_steps = {}: must be >= the estimated {:.3g} time steps of this run "
      "({:.3g} s simulated / dt {:.3g} s, from h = {:.3g} m at the contact and wave speed {:.4g} "
      "m/s); check sphere/substrate E, rho, nu, mesh.h_min and solver.t_max, or raise "
      "solver.max_steps",
      c.solver.max_steps, e.steps, e.simulated_time, e.time_step, e.element_size, e.wave_speed));
}

}  // namespace

RunEstimate estimate_run(const ImpactConfig& c) {
  RunEstimate e;
  e.contact_radius = uncapped_contact_radius(c);
  e.element_size = mesh_options_for(c).h_contact;
  e.wave_speed = rigid_target(c) ? c.sphere.material.dilatational_wave_speed()
                                 : std::max(c.sphere.material.dilatational_wave_speed(),
                                            c.substrate.material.dilatational_wave_speed());
  const double b1 = c.solver.bulk_viscosity_linear;
  // Square element: L_e = h / sqrt 2 (stable_time_step.hpp), a cube's h / sqrt 3 (hex8.hpp);
  // the hoop term next to the axis only shortens it, so this is a lower bound on the step count.
  const double lattice = uses_3d_model(c) ? std::sqrt(3.0) : std::sqrt(2.0);
  const double h = uses_3d_model(c) ? hex_mesh_options_for(c).h_contact : e.element_size;
  e.element_size = h;
  e.time_step =
      c.solver.safety_factor * h / lattice / e.wave_speed * (std::sqrt(1.0 + b1 * b1) - b1);
  // Default t_max: 20 Hertz contact times after contact (explicit_solver.cpp).
  e.simulated_time = c.solver.t_max > 0.0 ? c.solver.t_max - contact_start_time(c)
                                          : 20.0 * hertz_reference(c).contact_time;
  e.simulated_time *= c.impact.repeats;
  e.steps = e.simulated_time / e.time_step;
  e.elements = estimate_elements(c);
  e.expected_steps = expected_steps(c, e.time_step);
  return e;
}

double estimate_elements(const ImpactConfig& c) {
  // The 3-D mesh is a few tensor grids: counted exactly from its node distributions (a graded
  // ball's count was 0.06x the O-grid sphere's, whose shells keep the contact's size all round).
  if (uses_3d_model(c)) return hex_impact_elements(hex_mesh_options_for(c));
  const MeshOptions o = mesh_options_for(c);
  const Grading g{o.h_contact, o.zone_radius, o.growth, o.h_max};
  double n = sphere_mesh_elements(o);
  if (o.target == SubstrateShape::kSphere) {
    MeshOptions target = o;
    target.sphere_radius = o.target_radius;
    n += sphere_mesh_elements(target);
  }
  if (o.target == SubstrateShape::kFlat) {
    n += o.transitions
             ? block_elements_2d(o.substrate_radius, o.substrate_depth, g)
             : intervals(o.substrate_radius, o.h_contact, o.zone_radius, o.growth, o.h_max) *
                   intervals(o.substrate_depth, o.h_contact, o.zone_depth, o.growth, o.h_max);
  }
  return n;
}

// Absorbing far faces exist only on the flat substrate (the rigid flat has no body, the second
// sphere no far face).
void check_boundary(const ImpactConfig& c) {
  if (c.substrate.boundary != SubstrateBoundary::kFixed &&
      c.substrate.shape != SubstrateShape::kFlat)
    throw_invalid("substrate.boundary", to_string(c.substrate.boundary),
                  fmt::format("fixed with substrate.shape = {} (absorbing far faces need the flat "
                              "substrate)",
                              to_string(c.substrate.shape)));
}

void validate_limits(const ImpactConfig& config) {
  check_boundary(config);
  check_plastic_body(config.sphere.material, "sphere");
  if (!rigid_target(config)) check_plastic_body(config.substrate.material, "substrate");
  check_sizes(config);
  check_model(config);
  if (!uses_3d_model(config)) check_geometry(config);
  check_solver(config);
  check_step_budget(config);
  check_work(config);
}

}  // namespace corlab::fem
