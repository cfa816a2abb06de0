#include "corlab/dem/dem_export.hpp"

#include <cmath>

#include "corlab/core/error.hpp"
#include "corlab/core/units.hpp"
#include "corlab/dem/hysteresis_chi.hpp"
#include "corlab/dem/lammps_mapping.hpp"
#include "corlab/restitution/registry.hpp"

namespace corlab::dem {
namespace {

double sphere_mass(const ParticleType& t) {
  return 4.0 / 3.0 * units::kPi * t.radius * t.radius * t.radius * t.material.density;
}

void validate_spec(const ExportSpec& spec) {
  if (spec.types.empty()) throw_invalid("types", 0.0, "at least one particle type");
  for (const auto& t : spec.types) {
    require_positive("type radius", t.radius, "[m]");
    validate(t.material, "type material");
  }
  if (spec.wall) validate(*spec.wall, "wall");
  if (spec.wall_only && !spec.wall) throw_invalid("wall_only", 1.0, "used with a wall");
  const int targets = static_cast<int>(spec.restitution.has_value()) +
                      static_cast<int>(!spec.model.empty()) +
                      static_cast<int>(spec.table.has_value());
  if (targets != 1) {
    throw_invalid("target", static_cast<double>(targets),
                  "exactly one of --restitution, --model, --table");
  }
  if (spec.restitution) require_open_range("restitution", *spec.restitution, 0.0, 1.0);
  require_positive("v_min", spec.v_min, "[m/s]");
  if (!(spec.v_max > spec.v_min)) throw_invalid("v_max", spec.v_max, "> v_min");
  if (spec.fit_points < 2 || spec.fit_points > 200)
    throw_invalid("fit_points", spec.fit_points, "in [2, 200]");
}

// e(v) of sphere material `a` hitting `b`: the registered model needs the yielding body as the
// substrate, so the body with a yield stress (the softer if both) is taken as the flat.
RestitutionCurve model_curve(const ExportSpec& spec,
                             const Material& a,
                             const Material& b,
                             std::string& description) {
  if (spec.table) {
    description = "table " + spec.table_source;
    return *spec.table;
  }
  const bool b_yields = b.yield_stress.has_value();
  const bool a_yields = a.yield_stress.has_value();
  if (!a_yields && !b_yields) {
    throw_invalid("material pair", a.name + " / " + b.name,
                  "one of them with a yield stress for model " + spec.model);
  }
  const bool b_is_flat = b_yields && (!a_yields || *b.yield_stress <= *a.yield_stress);
  const Material& sphere = b_is_flat ? a : b;
  const Material& flat = b_is_flat ? b : a;
  description = spec.model + " (" + sphere.name + " on " + flat.name + ")";
  auto model = restitution::make_model(spec.model, sphere, flat);
  return [model](double v) { return model.cor(v); };
}

PairCalibration calibrate_one(const ExportSpec& spec, int i, int j) {
  const ParticleType& ti = spec.types[static_cast<std::size_t>(i - 1)];
  PairCalibration c;
  c.type_i = i;
  c.type_j = j;
  c.particle_radius = ti.radius;
  const Material* other = nullptr;
  if (j == 0) {
    other = &*spec.wall;
    c.effective_radius = ti.radius;
    c.effective_mass = sphere_mass(ti);
  } else {
    const ParticleType& tj = spec.types[static_cast<std::size_t>(j - 1)];
    other = &tj.material;
    c.effective_radius = ti.radius * tj.radius / (ti.radius + tj.radius);
    c.effective_mass = sphere_mass(ti) * sphere_mass(tj) / (sphere_mass(ti) + sphere_mass(tj));
  }
  c.effective_modulus = corlab::effective_modulus(ti.material, *other);
  c.hertz_stiffness = hertz_stiffness(c.effective_modulus, c.effective_radius);
  if (spec.restitution) {
    const double e = *spec.restitution;
    c.target = "constant e = " + std::to_string(e);
    c.curve = [e](double) { return e; };
    c.chi = exact_chi(e);
    c.tsuji_alpha = calibrate_tsuji_alpha(e);
    c.lammps_tsuji_input = lammps_tsuji_input(e);
    return c;
  }
  c.curve = model_curve(spec, ti.material, *other, c.target);
  const auto speeds = log_speeds(spec.v_min, spec.v_max, spec.fit_points);
  c.viscoelastic = fit_viscoelastic_damping(c.hertz_stiffness, c.effective_mass, speeds, c.curve);
  c.liggghts = fit_liggghts_thornton_pressure(c.effective_modulus, c.effective_radius,
                                              c.effective_mass, speeds, c.curve);
  c.thornton = fit_thornton_pressure(c.effective_modulus, c.effective_radius, c.effective_mass,
                                     speeds, c.curve);
  return c;
}

}  // namespace

double PairCalibration::lammps_viscoelastic_eta() const {
  return viscoelastic ? viscoelastic->parameter / (effective_mass * std::sqrt(effective_radius))
                      : 0.0;
}

double PairCalibration::liggghts_yield_ratio() const {
  return liggghts ? units::kPi * effective_radius * liggghts->parameter /
                        (2.0 * effective_modulus * particle_radius)
                  : 0.0;
}

std::vector<PairCalibration> calibrate_pairs(const ExportSpec& spec) {
  validate_spec(spec);
  std::vector<PairCalibration> pairs;
  const int n = static_cast<int>(spec.types.size());
  for (int i = 1; i <= n && !spec.wall_only; ++i) {
    for (int j = i; j <= n; ++j) pairs.push_back(calibrate_one(spec, i, j));
  }
  if (spec.wall) {
    for (int i = 1; i <= n; ++i) pairs.push_back(calibrate_one(spec, i, 0));
  }
  return pairs;
}

}  // namespace corlab::dem
