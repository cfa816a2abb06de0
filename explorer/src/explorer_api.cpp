// The explorer's C++ side (explorer_api.hpp): catalog, evaluation, dataset.
// SPDX-License-Identifier: BSD-3-Clause
#include "explorer_api.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "corlab/core/error.hpp"
#include "corlab/dem/dem_export.hpp"
#include "corlab/materials/material_database.hpp"
#include "corlab/restitution/first_yield.hpp"
#include "corlab/restitution/registry.hpp"
#include "corlab/restitution/validity.hpp"
#include "corlab/version.hpp"
#include "nearest_runs.hpp"

namespace corlab::explorer {
namespace {

using nlohmann::json;

// The FE dataset's runs, once loaded (load_dataset).
std::vector<DatasetRun>& dataset_runs() {
  static std::vector<DatasetRun> runs;
  return runs;
}

json optional_number(const std::optional<double>& x) { return x ? json(*x) : json(nullptr); }

json material_json(const Material& m) {
  return {{"name", m.name},
          {"E", m.youngs_modulus},
          {"nu", m.poisson_ratio},
          {"rho", m.density},
          {"sigma_y", optional_number(m.yield_stress)},
          {"H", m.hardening_modulus},
          {"source", m.source}};
}

json box_json(const std::optional<restitution::DimensionlessBox>& box) {
  if (!box) return nullptr;
  return {{"k1_min", box->k1_min},
          {"k1_max", box->k1_max},
          {"k2_min", box->k2_min},
          {"k2_max", box->k2_max}};
}

// corlab2026's 95 % prediction interval: 95 % of its training runs' relative errors
// (model - FE)/FE lie within +-p (python/corlab/model_fit.py, data/fe_restitution/model_fit.json).
double prediction_interval_95() {
  std::ifstream in(data_directory() / "fe_restitution" / "model_fit.json");
  const json fit = json::parse(in);
  return fit.at("prediction_interval_95").get<double>();
}

json error_json(const InputError& err) {
  return {{"error",
           {{"message", err.what()},
            {"field", err.field()},
            {"value", err.value()},
            {"constraint", err.constraint()}}}};
}

// A number of the request, or `fallback` when absent; InputError naming the key otherwise.
double request_number(const json& request, const char* key, double fallback, const char* unit) {
  const auto it = request.find(key);
  if (it == request.end()) return fallback;
  if (!it->is_number()) throw_invalid(key, it->dump(), unit);
  return it->get<double>();
}

// Where a model is outside its accurate range at each speed [m/s] (the checks behind
// validity_warnings): its calibration box in k1, k2; a damage number rho* v^2/sigma_y above its
// accurate_damage_number; a speed beyond every model; a radius ratio beyond its fitted one.
json accuracy_json(const restitution::ModelInfo& info,
                   const std::vector<double>& velocities,
                   const Material& reduced,
                   const Material& substrate,
                   double radius_ratio) {
  const auto check = restitution::calibration_check(info, velocities, reduced, substrate);
  const bool ratio_outside = !restitution::radius_ratio_warning(info, radius_ratio).empty();
  std::vector<bool> outside(velocities.size(), ratio_outside);
  std::vector<std::string> reasons;
  if (ratio_outside) reasons.emplace_back("radius ratio beyond its fitted one");
  bool k1_out = false;
  bool damage_out = false;
  bool speed_out = false;
  for (std::size_t i = 0; i < velocities.size(); ++i) {
    const double v = velocities[i];
    const bool k1_i = check.known && (check.k2_outside || check.k1_outside[i]);
    const bool damage_i =
        info.accurate_damage_number && substrate.yield_stress &&
        reduced.density * v * v / *substrate.yield_stress > *info.accurate_damage_number;
    const bool speed_i = v > restitution::kMaxModelVelocity;
    k1_out = k1_out || k1_i;
    damage_out = damage_out || damage_i;
    speed_out = speed_out || speed_i;
    if (k1_i || damage_i || speed_i) outside[i] = true;
  }
  if (k1_out) reasons.emplace_back(check.k2_outside ? "k2 outside its box" : "k1 outside its box");
  if (damage_out) {
    reasons.push_back(
        fmt::format("damage number rho* v^2/sigma_y above {:g}", *info.accurate_damage_number));
  }
  if (speed_out) {
    reasons.push_back(fmt::format("speed above {:g} m/s", restitution::kMaxModelVelocity));
  }
  return {{"outside", outside}, {"reasons", reasons}};
}

json evaluate_json(const json& request) {
  const auto text = [&](const char* key) {
    const auto it = request.find(key);
    if (it == request.end() || !it->is_string()) throw_invalid(key, "missing", "a material spec");
    return it->get<std::string>();
  };
  const Material sphere = parse_material_spec(text("sphere"), "sphere");
  const Material substrate = parse_material_spec(text("substrate"), "substrate");
  const auto v_it = request.find("velocity");
  if (v_it == request.end() || !v_it->is_array() || v_it->empty()) {
    throw_invalid("velocity", "missing", "a non-empty list of speeds [m/s]");
  }
  std::vector<double> velocities;
  for (const auto& v : *v_it) {
    if (!v.is_number()) throw_invalid("velocity", v.dump(), "numbers [m/s]");
    velocities.push_back(v.get<double>());
  }
  const std::size_t nearest = request.value("nearest", std::size_t{10});
  restitution::ModelOptions options;
  options.radius_ratio = request_number(request, "radius_ratio", 0.0, "a number >= 0 [-]");
  // k1 and the boxes at the pair's rho* (the sphere itself on a flat), as `corlab predict`.
  const Material reduced = pair_reduced_sphere(sphere, substrate, options.radius_ratio);

  json out;
  out["sphere"] = material_json(sphere);
  out["substrate"] = material_json(substrate);
  out["velocity"] = velocities;
  out["radius_ratio"] = options.radius_ratio;
  json models = json::array();
  std::vector<double> e(velocities.size());
  for (const auto& name : restitution::model_names()) {
    const restitution::Model m = restitution::make_model(name, sphere, substrate, options);
    m.cor(velocities, e);  // checks every velocity (InputError naming the index)
    const auto check = restitution::calibration_check(m.info(), velocities, reduced, substrate);
    json calibration = nullptr;
    if (check.known) {
      calibration = {{"k2_outside", check.k2_outside},
                     {"k1_outside", check.k1_outside},
                     {"box", box_json(m.info().calibrated)}};
    }
    auto warnings = restitution::validity_warnings(m.info(), velocities, reduced, substrate);
    if (auto w = restitution::radius_ratio_warning(m.info(), options.radius_ratio); !w.empty()) {
      warnings.push_back(std::move(w));
    }
    models.push_back({{"model", name},
                      {"status", restitution::to_string(m.info().status)},
                      {"clamped", m.clamped()},
                      {"v_y", m.yield_velocity()},
                      {"e", e},
                      {"calibration", calibration},
                      {"accuracy", accuracy_json(m.info(), velocities, reduced, substrate,
                                                 options.radius_ratio)},
                      {"warnings", warnings}});
    if (name == "corlab2026") {
      // |model - FE| <= p FE for 95 % of the training runs: FE in [e/(1 + p), e/(1 - p)].
      const double p = prediction_interval_95();
      std::vector<double> low(e.size());
      std::vector<double> high(e.size());
      for (std::size_t i = 0; i < e.size(); ++i) {
        low[i] = e[i] / (1.0 + p);
        high[i] = e[i] / (1.0 - p);
      }
      out["prediction_interval"] = {
          {"model", name}, {"level", 0.95}, {"relative", p}, {"low", low}, {"high", high}};
    }
  }
  out["models"] = models;
  const double e_star = effective_modulus(sphere, substrate);
  const auto yield = restitution::first_yield(sphere, substrate);
  std::vector<double> k1s;
  for (const double v : velocities) k1s.push_back(k1(e_star, reduced.density, v));
  out["effective_modulus"] = e_star;
  out["effective_density"] = reduced.density;
  out["k1"] = k1s;
  out["k2"] = k2(*substrate.yield_stress, e_star);
  out["first_yield_velocity"] = yield.velocity;
  out["sphere_yields_first"] = yield.sphere_first;
  const auto [v_min, v_max] = std::minmax_element(velocities.begin(), velocities.end());
  out["nearest"] = nearest_runs(dataset_runs(), reduced, substrate, *v_min, *v_max, nearest);
  out["dataset_runs"] = dataset_runs().size();
  return out;
}

// Runs `body`, turning bad input into {"error": ...} and anything else into an internal error.
template <class Body>
std::string guarded(Body&& body) {
  try {
    return body().dump();
  } catch (const InputError& err) {
    return error_json(err).dump();
  } catch (const json::exception& err) {
    return json{{"error", {{"message", std::string("invalid request: ") + err.what()}}}}.dump();
  } catch (const std::exception& err) {
    return json{{"error", {{"message", std::string("internal error: ") + err.what()}}}}.dump();
  }
}

}  // namespace

std::string catalog() {
  return guarded([] {
    const MaterialDatabase& db = MaterialDatabase::builtin();
    json materials = json::array();
    for (const auto& name : db.names()) {
      json m = material_json(db.get(name));
      m["category"] = db.category(name);
      materials.push_back(std::move(m));
    }
    json models = json::array();
    for (const auto& info : restitution::model_catalog()) {
      models.push_back(restitution::model_info_json(info));
    }
    return json{{"version", std::string(kVersion)},
                {"materials", materials},
                {"models", models},
                {"prediction_interval_95", prediction_interval_95()},
                {"max_velocity", restitution::kMaxModelVelocity}};
  });
}

std::string evaluate(const std::string& request) {
  return guarded([&] { return evaluate_json(json::parse(request)); });
}

std::string dem_export(const std::string& request) {
  return guarded([&] {
    const json r = json::parse(request);
    const auto number = [&](const char* key, const char* unit) {
      const auto it = r.find(key);
      if (it == r.end() || !it->is_number()) throw_invalid(key, "missing", unit);
      return it->get<double>();
    };
    const std::string sphere_spec = r.at("sphere").get<std::string>();
    const std::string substrate_spec = r.at("substrate").get<std::string>();
    dem::ExportSpec spec;
    dem::ParticleType type;
    type.material = parse_material_spec(sphere_spec, "sphere");
    type.radius = number("radius", "a number [m]");
    const double radius_ratio = request_number(r, "radius_ratio", 0.0, "a number >= 0 [-]");
    if (radius_ratio < 0.0 || !std::isfinite(radius_ratio)) {
      throw_invalid("radius_ratio", radius_ratio, ">= 0 and finite [-]");
    }
    std::string types;  // the --type options of the command
    if (radius_ratio > 0.0) {
      // A particle pair: both bodies as particle types (R2 = R1/ratio), every pair calibrated.
      dem::ParticleType other;
      other.material = parse_material_spec(substrate_spec, "substrate");
      other.radius = type.radius / radius_ratio;
      type.label = "sphere";
      other.label = "substrate";
      spec.types = {type, other};
      types = fmt::format("--type sphere={}:{} --type substrate={}:{}", sphere_spec, type.radius,
                          substrate_spec, other.radius);
    } else {
      spec.types.push_back(type);
      spec.wall = parse_material_spec(substrate_spec, "substrate");
      spec.wall_only = true;
      types = fmt::format("--type {}:{} --wall {} --wall-only", sphere_spec, type.radius,
                          substrate_spec);
    }
    spec.model = r.at("model").get<std::string>();
    spec.v_min = number("v_min", "a number [m/s]");
    spec.v_max = number("v_max", "a number [m/s]");
    const auto pairs = dem::calibrate_pairs(spec);  // validates the spec (InputError)
    // How each fragment delivers the target: the route its writer takes (LAMMPS: the
    // recommended fix python/invoke hook, the route write_lammps writes) and its max |de|.
    const auto route = [](const char* code, const dem::Delivery& d, double step) {
      return json{{"code", code},
                  {"route", d.route},
                  {"max_abs_error", d.max_abs_error},
                  {"time_step", step}};
    };
    json calibrations = json::array();
    for (const auto& p : pairs) {
      calibrations.push_back(
          {{"target", p.target},
           {"routes",
            {route("LAMMPS", dem::lammps_delivery(spec, p, true),
                   dem::lammps_time_step(pairs, true)),
             route("LIGGGHTS", dem::liggghts_delivery(pairs, p), dem::liggghts_time_step(pairs)),
             route("YADE", dem::yade_delivery(spec, p), dem::yade_time_step(pairs))}}});
    }
    return json{
        {"fragments",
         {{"LAMMPS", dem::write_lammps(spec, pairs)},
          {"LIGGGHTS", dem::write_liggghts(spec, pairs)},
          {"YADE", dem::write_yade(spec, pairs)}}},
        {"command", fmt::format("corlab dem {} --model {} --v-min {} --v-max {} --out dem_export",
                                types, spec.model, spec.v_min, spec.v_max)},
        {"pairs", calibrations}};
  });
}

std::string load_dataset(const std::string& columns) {
  return guarded([&] {
    dataset_runs() = runs_from_columns(json::parse(columns));
    return json{{"runs", dataset_runs().size()}};
  });
}

}  // namespace corlab::explorer
