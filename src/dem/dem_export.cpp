// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dem/dem_export.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "corlab/core/error.hpp"
#include "corlab/core/number.hpp"
#include "corlab/core/text.hpp"
#include "corlab/core/units.hpp"
#include "corlab/dem/contact_ode.hpp"
#include "corlab/dem/hysteresis_chi.hpp"
#include "corlab/dem/lammps_mapping.hpp"
#include "corlab/dem/tangential.hpp"
#include "corlab/dem/time_step.hpp"
#include "corlab/materials/material_database.hpp"
#include "corlab/restitution/first_yield.hpp"
#include "corlab/restitution/registry.hpp"
#include "corlab/restitution/validity.hpp"
#include "dem/detail/export_spec.hpp"
#include "dem/detail/export_text.hpp"
#include "dem/detail/script_text.hpp"

namespace corlab::dem {
namespace {

double sphere_mass(const ParticleType& t) {
  return 4.0 / 3.0 * units::kPi * t.radius * t.radius * t.radius * t.material.density;
}

// The pair as `corlab predict` takes it: the particle of type_i is the sphere, the other body
// (type_j's particle, R1/R2 = r_i/r_j, or the wall, a flat) the substrate.
PairBodies pair_bodies(const ExportSpec& spec,
                       const PairCalibration& c,
                       const Material& a,
                       const Material& b) {
  PairBodies bodies{
      .sphere = a,
      .substrate = b,
      .sphere_label = type_label(spec, c.type_i),
      .substrate_label = c.type_j == 0 ? wall_label(spec) : type_label(spec, c.type_j)};
  if (c.type_j != 0) {
    bodies.radius_ratio = spec.types[static_cast<std::size_t>(c.type_i - 1)].radius /
                          spec.types[static_cast<std::size_t>(c.type_j - 1)].radius;
  }
  return bodies;
}

// e(v) of the pair from a registered model, oriented as `corlab predict` takes the pair: the
// particle is the sphere on the other body when that body yields (a model reads the
// substrate's yield stress; before, the softer body was the flat, and a brass particle on a
// stainless wall was the wall on the particle, 0.003-0.004 from `predict`); when only the
// particle yields, the other body is the sphere on it. A model is written for a sphere of
// density rho on a flat; the Hertz impact of any pair (R*, m*, E*) is exactly that of a sphere
// of density rho* = 3 m*/(4 pi R*^3) on a flat of the same E*, and every model depends on the
// sphere only through E* and its density (k1 = E*/(rho v^2), Thornton's v_y), not its radius.
// So the sphere gets the pair's rho* (c.effective_density; make_model's radius_ratio for two
// particles): 4 rho for two identical spheres, the particle's own density against the wall.
// corlab2026p reads the pair whole (R1/R2; the wall as a flat). The warnings are predict's.
RestitutionCurve model_curve(const ExportSpec& spec, PairCalibration& c, const PairBodies& p) {
  if (!p.sphere.yield_stress && !p.substrate.yield_stress) {
    throw_invalid(
        "pair " + c.name(), p.sphere_label + "/" + (c.type_j == 0 ? "wall" : p.substrate_label),
        fmt::format("a pair with a yield stress for model {} (neither material has one: its e "
                    "is the elastic-wave loss); use --model fe or auto (corlab's FE solver), set "
                    "its e with --pair {}/{}=E, give a material sy=..., or leave particle pairs "
                    "out with --wall-only",
                    spec.model, p.sphere_label, c.type_j == 0 ? "wall" : p.substrate_label));
  }
  const bool flipped = !p.substrate.yield_stress;  // only the particle yields
  Material sphere = flipped ? p.substrate : p.sphere;
  const Material& flat = flipped ? p.sphere : p.substrate;
  c.target = detail::script_text(spec.model) + " (" +
             (flipped ? p.substrate_label + " on " + p.sphere_label
                      : p.sphere_label + " on " + p.substrate_label);
  if (sphere.density != c.effective_density) {
    c.target += fmt::format(", sphere density rho* = {:.6g} kg/m^3", c.effective_density);
  }
  c.target += ")";
  restitution::ModelOptions options;
  if (c.type_j == 0) {
    sphere.density = c.effective_density;  // the particle's, also for a wall on a particle
  } else {  // make_model puts rho* on the sphere; corlab2026p reads R1/R2 whole
    options.radius_ratio = flipped ? 1.0 / p.radius_ratio : p.radius_ratio;
  }
  auto model = restitution::make_model(spec.model, sphere, flat, options);
  const auto speeds = log_speeds(spec.v_min, spec.v_max, spec.fit_points);
  c.warnings = restitution::validity_warnings(
      model.info(), speeds, pair_reduced_sphere(sphere, flat, options.radius_ratio), flat);
  if (auto w = restitution::radius_ratio_warning(model.info(), options.radius_ratio); !w.empty())
    c.warnings.push_back(std::move(w));
  return [model](double v) { return model.cor(v); };
}

// The pair's e(v) target: its own table, else the export's table, model or external source
// (fe, auto); sets c.target (and c.warnings).
RestitutionCurve pair_curve(const ExportSpec& spec,
                            PairCalibration& c,
                            const Material& a,
                            const Material& b) {
  if (const PairTable* t = detail::pair_table(spec, c.type_i, c.type_j)) {
    c.target = "table " + detail::script_text(t->source) + " (--pair-table)";
    return t->curve;
  }
  if (spec.table) {
    c.target = "table " + detail::script_text(spec.table_source);
    return *spec.table;
  }
  if (spec.model.empty()) {
    const std::string second = c.type_j == 0 ? "wall" : type_label(spec, c.type_j);
    throw_invalid("target of pair " + c.name(), type_label(spec, c.type_i) + "/" + second,
                  "set: --restitution, --model or --table for every pair, or --pair or "
                  "--pair-table for this one");
  }
  const PairBodies bodies = pair_bodies(spec, c, a, b);
  if (!is_external_model(spec.model)) return model_curve(spec, c, bodies);
  if (!spec.target_source) {
    throw_invalid("model", spec.model,
                  "a registered model (corlab models) here: fe and auto need corlab's FE solver "
                  "(corlab dem, corlab.dem.export)");
  }
  ExternalTarget target =
      spec.target_source(bodies, log_speeds(spec.v_min, spec.v_max, spec.fit_points));
  c.target = std::move(target.description);
  c.warnings = std::move(target.warnings);
  return std::move(target.curve);
}

// The constant e closest to the target in the worst case: the mid-range of e over the speeds.
CurveFit best_constant_fit(std::span<const double> speeds, const RestitutionCurve& curve) {
  CurveFit fit;
  fit.velocities.assign(speeds.begin(), speeds.end());
  for (const double v : speeds) fit.target.push_back(curve(v));
  const auto [lo, hi] = std::minmax_element(fit.target.begin(), fit.target.end());
  fit.parameter = std::min(1.0, 0.5 * (*lo + *hi));
  double sum = 0.0;
  for (const double e : fit.target) {
    fit.fitted.push_back(fit.parameter);
    fit.max_abs_error = std::max(fit.max_abs_error, std::abs(e - fit.parameter));
    sum += (e - fit.parameter) * (e - fit.parameter);
  }
  fit.rms_error = std::sqrt(sum / static_cast<double>(speeds.size()));
  return fit;
}

// The pair's e(v) target is an e in [1e-12, 1] (kMinRestitution) at every speed the fits and the
// hook tables read; else refused, naming the pair, its target (the model) and the speed.
void require_physical_target(const ExportSpec& spec, const PairCalibration& c) {
  auto speeds = log_speeds(spec.v_min, spec.v_max, spec.fit_points);
  const auto rows = detail::table_speeds(spec, detail::kHookTableRows);
  speeds.insert(speeds.end(), rows.begin(), rows.end());
  for (const double v : speeds) {
    const double e = c.curve(v);
    if (!(e >= kMinRestitution && e <= 1.0)) {
      throw_invalid("target e of pair " + c.name(), e,
                    fmt::format("in [{}, 1]: {} gives it at v = {:.6g} m/s, outside the range "
                                "where it holds (narrow --v-min/--v-max or choose another model)",
                                kMinRestitution, c.target, v));
    }
  }
}

PairCalibration calibrate_one(const ExportSpec& spec, int i, int j) {
  const ParticleType& ti = spec.types[static_cast<std::size_t>(i - 1)];
  PairCalibration c;
  c.type_i = i;
  c.type_j = j;
  c.friction = spec.friction;  // the export's mu; calibrate_export applies --friction A/B=MU
  c.particle_radius = ti.radius;
  c.label = type_label(spec, i) + "-" + (j == 0 ? wall_label(spec) : type_label(spec, j));
  const Material* other = nullptr;
  if (j == 0) {
    other = &*spec.wall;
    c.effective_radius = ti.radius;
    c.effective_mass = sphere_mass(ti);
    c.effective_density = ti.material.density;
  } else {
    const ParticleType& tj = spec.types[static_cast<std::size_t>(j - 1)];
    other = &tj.material;
    c.effective_radius = ti.radius * tj.radius / (ti.radius + tj.radius);
    c.effective_mass = sphere_mass(ti) * sphere_mass(tj) / (sphere_mass(ti) + sphere_mass(tj));
    c.effective_density = pair_effective_density(ti.radius / tj.radius, ti.material.density,
                                                 ti.material.density / tj.material.density);
  }
  c.effective_modulus = corlab::effective_modulus(ti.material, *other);
  c.hertz_stiffness = hertz_stiffness(c.effective_modulus, c.effective_radius);
  c.shear_modulus = mindlin_shear_modulus(ti.material, *other);
  c.friction = spec.friction;
  c.contact_time_fast = hertz_contact_time(c.hertz_stiffness, c.effective_mass, spec.v_max);
  c.contact_time_slow = hertz_contact_time(c.hertz_stiffness, c.effective_mass, spec.v_min);
  c.constant = detail::pair_override(spec, i, j);
  if (c.constant) {
    c.target = fmt::format("constant e = {:.6g} (--pair)", *c.constant);
  } else if (spec.restitution && !detail::pair_table(spec, i, j)) {
    c.constant = spec.restitution;
    c.target = fmt::format("constant e = {:.6g}", *c.constant);
  }
  const auto speeds = log_speeds(spec.v_min, spec.v_max, spec.fit_points);
  if (c.constant) {
    const double e = *c.constant;
    c.curve = [e](double) { return e; };
    c.chi = exact_chi(e);
    c.tsuji_alpha = e < 1.0 ? calibrate_tsuji_alpha(e) : 0.0;
    c.lammps_tsuji_input = e < 1.0 ? lammps_tsuji_input(e) : 1.0;  // e = 1: no damping
    c.best_constant = best_constant_fit(speeds, c.curve);
    return c;
  }
  c.curve = pair_curve(spec, c, ti.material, *other);
  require_physical_target(spec, c);
  c.viscoelastic = fit_viscoelastic_damping(c.hertz_stiffness, c.effective_mass, speeds, c.curve);
  c.liggghts = fit_liggghts_thornton_pressure(c.effective_modulus, c.effective_radius,
                                              c.effective_mass, speeds, c.curve);
  c.thornton = fit_thornton_pressure(c.effective_modulus, c.effective_radius, c.effective_mass,
                                     speeds, c.curve);
  c.best_constant = best_constant_fit(speeds, c.curve);
  return c;
}

// e of LIGGGHTS's thornton_ning for pair c at v when its yield radius is ratio * r_i [-].
double liggghts_e_at_ratio(const PairCalibration& c, double ratio, double v) {
  const double p_y =
      2.0 * c.effective_modulus * ratio * c.particle_radius / (units::kPi * c.effective_radius);
  const LiggghtsThorntonNingLaw law{{c.effective_modulus, c.effective_radius, p_y}};
  const ForceLaw f = [&law](double d, double, const ContactHistory& h) { return law.force(d, h); };
  return simulate_impact(f, c.effective_mass, v).restitution;
}

}  // namespace

bool is_external_model(std::string_view model) { return model == "fe" || model == "auto"; }

std::vector<double> liggghts_type_ratios(const ExportSpec& spec,
                                         const std::vector<PairCalibration>& pairs) {
  std::vector<double> ratios;
  for (int t = 1; t <= static_cast<int>(spec.types.size()); ++t) {
    const PairCalibration* chosen = nullptr;
    for (const auto& p : pairs) {
      if (p.type_i != t || !p.liggghts) continue;
      if (p.type_j == 0 || (!chosen && p.type_j == p.type_i)) chosen = &p;
    }
    // No fitted pair of this type (constant e only): a contact radius of a whole particle
    // radius is never reached, so its contacts stay elastic.
    ratios.push_back(chosen ? chosen->liggghts_yield_ratio() : 1.0);
  }
  return ratios;
}

std::string PairCalibration::name() const {
  return (type_j == 0 ? fmt::format("{}-wall", type_i) : fmt::format("{}-{}", type_i, type_j)) +
         " (" + label + ")";
}

double PairCalibration::lammps_viscoelastic_eta() const {
  return viscoelastic ? viscoelastic->parameter / (effective_mass * std::sqrt(effective_radius))
                      : 0.0;
}

double PairCalibration::liggghts_yield_ratio() const {
  return liggghts ? units::kPi * effective_radius * liggghts->parameter /
                        (2.0 * effective_modulus * particle_radius)
                  : 0.0;
}

bool liggghts_uses_thornton_ning(const std::vector<PairCalibration>& pairs) {
  // Several wall materials: a type's one yield ratio would be one wall's fit (and the misfits of
  // the others' pairs, fitted apart, would not be what runs): one constant e per pair instead.
  if (std::any_of(pairs.begin(), pairs.end(), [](const auto& p) { return p.wall > 0; })) {
    return false;
  }
  double worst_tn = 0.0;
  double worst_constant = 0.0;
  bool any_curve = false;
  for (const auto& p : pairs) {
    any_curve = any_curve || !p.constant;
    if (p.liggghts_written) worst_tn = std::max(worst_tn, p.liggghts_written->max_abs_error);
    worst_constant = std::max(worst_constant, p.best_constant->max_abs_error);
  }
  return any_curve && worst_tn < worst_constant;
}

std::vector<PairCalibration> calibrate_pairs(const ExportSpec& spec) {
  detail::validate_export_spec(spec);
  std::vector<PairCalibration> pairs;
  const int n = static_cast<int>(spec.types.size());
  for (int i = 1; i <= n && !spec.wall_only; ++i) {
    for (int j = i; j <= n; ++j) pairs.push_back(calibrate_one(spec, i, j));
  }
  if (spec.wall) {
    for (int i = 1; i <= n; ++i) pairs.push_back(calibrate_one(spec, i, 0));
  }
  // LIGGGHTS's yield ratio is per atom type (a_y = ratio r_i of the pair's first atom): the e
  // each pair gets with the ratios written, with the worse of its two types' ratios.
  const bool any_curve =
      std::any_of(pairs.begin(), pairs.end(), [](const auto& p) { return !p.constant; });
  if (!any_curve) return pairs;
  const auto ratios = liggghts_type_ratios(spec, pairs);
  for (auto& p : pairs) {
    CurveFit fit;
    fit.velocities = p.best_constant->velocities;
    fit.target = p.best_constant->target;
    const std::vector<int> types = p.type_j == 0 || p.type_j == p.type_i
                                       ? std::vector<int>{p.type_i}
                                       : std::vector<int>{p.type_i, p.type_j};
    for (const int t : types) {
      const double ratio = ratios[static_cast<std::size_t>(t - 1)];
      PairCalibration as_first = p;
      if (t != p.type_i)
        as_first.particle_radius = spec.types[static_cast<std::size_t>(t - 1)].radius;
      double sum = 0.0;
      double worst = 0.0;
      std::vector<double> e;
      for (std::size_t k = 0; k < fit.velocities.size(); ++k) {
        e.push_back(liggghts_e_at_ratio(as_first, ratio, fit.velocities[k]));
        const double d = e.back() - fit.target[k];
        worst = std::max(worst, std::abs(d));
        sum += d * d;
      }
      if (fit.fitted.empty() || worst > fit.max_abs_error) {
        fit.fitted = e;
        fit.parameter = ratio;
        fit.max_abs_error = worst;
        fit.rms_error = std::sqrt(sum / static_cast<double>(e.size()));
      }
    }
    p.liggghts_written = fit;
  }
  return pairs;
}

}  // namespace corlab::dem
