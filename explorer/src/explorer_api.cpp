// The explorer's C++ side (explorer_api.hpp): catalog, evaluation, dataset.
// SPDX-License-Identifier: BSD-3-Clause
#include "explorer_api.hpp"

#include <fmt/format.h>

#include <cmath>
#include <exception>
#include <fstream>
#include <nlohmann/json.hpp>
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

  json out;
  out["sphere"] = material_json(sphere);
  out["substrate"] = material_json(substrate);
  out["velocity"] = velocities;
  json models = json::array();
  std::vector<double> e(velocities.size());
  for (const auto& name : restitution::model_names()) {
    const restitution::Model m = restitution::make_model(name, sphere, substrate);
    m.cor(velocities, e);  // checks every velocity (InputError naming the index)
    const auto check = restitution::calibration_check(m.info(), velocities, sphere, substrate);
    json calibration = nullptr;
    if (check.known) {
      calibration = {{"k2_outside", check.k2_outside},
                     {"k1_outside", check.k1_outside},
                     {"box", box_json(m.info().calibrated)}};
    }
    models.push_back(
        {{"model", name},
         {"status", restitution::to_string(m.info().status)},
         {"clamped", m.clamped()},
         {"v_y", m.yield_velocity()},
         {"e", e},
         {"calibration", calibration},
         {"warnings", restitution::validity_warnings(m.info(), velocities, sphere, substrate)}});
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
  for (const double v : velocities) k1s.push_back(k1(e_star, sphere.density, v));
  out["effective_modulus"] = e_star;
  out["k1"] = k1s;
  out["k2"] = k2(*substrate.yield_stress, e_star);
  out["first_yield_velocity"] = yield.velocity;
  out["sphere_yields_first"] = yield.sphere_first;
  const auto [v_min, v_max] = std::minmax_element(velocities.begin(), velocities.end());
  out["nearest"] = nearest_runs(dataset_runs(), sphere, substrate, *v_min, *v_max, nearest);
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
    for (const auto& name : db.names()) materials.push_back(material_json(db.get(name)));
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
    spec.types.push_back(type);
    spec.wall = parse_material_spec(substrate_spec, "substrate");
    spec.wall_only = true;
    spec.model = r.at("model").get<std::string>();
    spec.v_min = number("v_min", "a number [m/s]");
    spec.v_max = number("v_max", "a number [m/s]");
    const auto pairs = dem::calibrate_pairs(spec);  // validates the spec (InputError)
    json calibrations = json::array();
    for (const auto& p : pairs) {
      calibrations.push_back({{"target", p.target},
                              {"lammps_viscoelastic_eta", p.lammps_viscoelastic_eta()},
                              {"viscoelastic_max_abs_error", p.viscoelastic->max_abs_error},
                              {"liggghts_yield_ratio", p.liggghts_yield_ratio()},
                              {"liggghts_max_abs_error", p.liggghts->max_abs_error}});
    }
    return json{{"fragments",
                 {{"LAMMPS", dem::write_lammps(spec, pairs)},
                  {"LIGGGHTS", dem::write_liggghts(spec, pairs)},
                  {"YADE", dem::write_yade(spec, pairs)}}},
                {"command", fmt::format("corlab dem --type {}:{} --wall {} --wall-only --model {} "
                                        "--v-min {} --v-max {} --out dem_export",
                                        sphere_spec, type.radius, substrate_spec, spec.model,
                                        spec.v_min, spec.v_max)},
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
