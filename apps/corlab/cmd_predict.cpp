// `corlab predict`: evaluate analytic CoR models for a sphere/substrate pair over velocities.
//   corlab predict --model ma2023 --sphere alumina_ma2023 --substrate aluminium_ma2023
//                  --velocity 0.05:6:50 --spacing log --format csv
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "command.hpp"
#include "corlab/core/error.hpp"
#include "corlab/core/number.hpp"
#include "corlab/materials/material_database.hpp"
#include "corlab/restitution/registry.hpp"
#include "corlab/restitution/validity.hpp"
#include "predict_fe.hpp"

namespace corlab::cli {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct PredictOptions {
  std::string model;
  std::string sphere;
  std::string substrate;
  std::string velocity;
  std::string spacing = "lin";
  std::string format = "csv";
  std::string clamp = "default";
  double radius = 1.0;
  double radius_ratio = 0.0;  ///< R1/R2 of a free second sphere of the substrate's material [-]
  FeOptions fe;               ///< --model fe|auto only (predict_fe.hpp)
};

/// Most velocities one `predict` evaluates: a million points, each model's e and k1 held in
/// memory and written as they are computed (the JSON one model at a time).
constexpr std::size_t kMaxPoints = 1'000'000;

constexpr const char* kRangeSyntax =
    "V, a list V1,V2,... or START:STOP:N with 0 < START <= STOP and an integer N >= 1 [m/s]";

// "V1,V2,..." -> the listed speeds, in the order given (each one checked as a single V).
std::vector<double> parse_velocity_list(const std::string& text) {
  std::vector<double> v;
  std::string_view rest(text);
  while (true) {
    const auto comma = rest.find(',');
    const std::optional<double> x = parse_double(rest.substr(0, comma));
    if (!x) throw_invalid("velocity", text, kRangeSyntax);
    restitution::require_velocity(*x);
    v.push_back(*x);
    if (comma == std::string_view::npos) return v;
    rest.remove_prefix(comma + 1);
  }
}

// "V", "V1,V2,..." or "START:STOP:N" -> velocities (lin or log spacing for a range); one-line
// InputError otherwise.
std::vector<double> parse_velocities(const std::string& text, const std::string& spacing) {
  if (text.find(',') != std::string::npos) {
    if (text.find(':') != std::string::npos) throw_invalid("velocity", text, kRangeSyntax);
    return parse_velocity_list(text);
  }
  std::vector<std::string_view> parts;
  std::string_view rest(text);
  while (true) {
    const auto colon = rest.find(':');
    parts.push_back(rest.substr(0, colon));
    if (colon == std::string_view::npos) break;
    rest.remove_prefix(colon + 1);
  }
  if (parts.size() == 1) {
    const std::optional<double> v = parse_double(parts[0]);
    if (!v) throw_invalid("velocity", text, kRangeSyntax);
    restitution::require_velocity(*v);
    return {*v};
  }
  if (parts.size() != 3) throw_invalid("velocity", text, kRangeSyntax);
  const double start = parse_double(parts[0]).value_or(kNaN);
  const double stop = parse_double(parts[1]).value_or(kNaN);
  const double count = parse_double(parts[2]).value_or(kNaN);
  if (!(std::isfinite(start) && std::isfinite(stop)) || !(start > 0.0) || !(stop >= start) ||
      !(count >= 1.0) || count != std::floor(count)) {
    throw_invalid("velocity", text, kRangeSyntax);
  }
  if (count > static_cast<double>(kMaxPoints)) {
    throw_invalid(
        "velocity", text,
        fmt::format("at most {} points (the cap of `predict`; split the range)", kMaxPoints));
  }
  const auto n = static_cast<std::size_t>(count);
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = n == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(n - 1);
    v[i] = spacing == "log" ? start * std::pow(stop / start, t) : start + (stop - start) * t;
  }
  if (n > 1) v.back() = stop;
  return v;
}

// k1 = E*/(rho v^2) overflows for a tiny v (1e-300 m/s wrote k1 = inf): refused with the bound.
void require_finite_k1(double v, double e_star, double density) {
  if (std::isfinite(k1(e_star, density, v))) return;
  const double v_min = std::sqrt(e_star / density / std::numeric_limits<double>::max());
  throw_invalid("velocity", v,
                fmt::format("large enough for a finite k1 = E*/(rho v^2): >= {:.3g} [m/s] for "
                            "this pair",
                            v_min * (1 + 1e-12)));
}

// `text` with `indent` after each line break (a nested JSON value in a dump(2) document).
std::string indented(const std::string& text, std::string_view indent) {
  std::string out;
  out.reserve(text.size() + text.size() / 8);
  for (const char c : text) {
    out += c;
    if (c == '\n') out += indent;
  }
  return out;
}

// One stderr warning per model asked outside its validity (validity.hpp).
void warn_outside_validity(const std::vector<restitution::Model>& models,
                           const std::vector<double>& velocities,
                           const Material& sphere,
                           const Material& substrate) {
  for (const auto& m : models) {
    for (const auto& w : restitution::validity_warnings(m.info(), velocities, sphere, substrate))
      std::fprintf(stderr, "corlab: warning: %s\n", w.c_str());
  }
}

// One stderr warning per model fitted to smaller radius ratios than asked (validity.hpp).
void warn_radius_ratio(const std::vector<restitution::Model>& models, double radius_ratio) {
  for (const auto& m : models) {
    if (const auto w = restitution::radius_ratio_warning(m.info(), radius_ratio); !w.empty())
      std::fprintf(stderr, "corlab: warning: %s\n", w.c_str());
  }
}

int run_predict(const PredictOptions& o) {
  const Material sphere = parse_material_spec(o.sphere, "sphere");
  const Material substrate = parse_material_spec(o.substrate, "substrate");
  const std::vector<double> velocities = parse_velocities(o.velocity, o.spacing);
  require_no_fe_options(o.fe, o.radius_ratio);
  std::vector<std::string> names;
  if (o.model == "all") {
    names = restitution::model_names();
  } else {
    names.push_back(restitution::model_info(o.model).name);  // throws for an unknown name
  }
  restitution::ModelOptions options;
  options.radius = o.radius;
  options.radius_ratio = o.radius_ratio;
  if (o.clamp == "on") options.clamp = true;
  if (o.clamp == "off") options.clamp = false;

  std::vector<restitution::Model> models;
  models.reserve(names.size());
  for (const auto& name : names)
    models.push_back(restitution::make_model(name, sphere, substrate, options));
  for (const auto& m : models) {
    if (m.info().status == restitution::Status::kUnverified) {
      std::fprintf(stderr, "corlab: warning: model '%s' is UNVERIFIED: %s\n", m.info().name.c_str(),
                   m.info().status_note.c_str());
    }
  }
  const double e_star = effective_modulus(sphere, substrate);
  const double sy = *substrate.yield_stress;
  // k1 and the validity boxes at the pair's rho* [kg/m^3] (the sphere's own density on a flat).
  const Material reduced = pair_reduced_sphere(sphere, substrate, o.radius_ratio);
  const double rho = reduced.density;
  // k1 falls with v: the slowest listed speed (a list is in the order given) bounds them all
  require_finite_k1(*std::min_element(velocities.begin(), velocities.end()), e_star, rho);
  warn_outside_validity(models, velocities, reduced, substrate);
  warn_radius_ratio(models, o.radius_ratio);
  std::vector<double> e(velocities.size());
  if (o.format == "json") {
    // The document of out.dump(2), written one model at a time (a million points of every model
    // in one tree took gigabytes).
    nlohmann::json head;
    head["sphere"] = o.sphere;
    head["substrate"] = o.substrate;
    head["effective_modulus"] = e_star;
    head["k2"] = k2(sy, e_star);
    fmt::print("{{\n  \"effective_modulus\": {},\n  \"k2\": {},\n  \"models\": [",
               head["effective_modulus"].dump(), head["k2"].dump());
    for (std::size_t i = 0; i < models.size(); ++i) {
      const auto& m = models[i];
      m.cor(velocities, e);
      std::vector<double> k1s(velocities.size());
      for (std::size_t j = 0; j < velocities.size(); ++j) {
        k1s[j] = k1(e_star, rho, velocities[j]);
      }
      const nlohmann::json model{{"model", m.info().name},
                                 {"status", restitution::to_string(m.info().status)},
                                 {"status_note", m.info().status_note},
                                 {"clamped", m.clamped()},
                                 {"v_y", m.yield_velocity()},
                                 {"velocity", velocities},
                                 {"k1", k1s},
                                 {"e", e}};
      fmt::print("{}\n    {}", i == 0 ? "" : ",", indented(model.dump(2), "    "));
    }
    fmt::print("{}],\n  \"radius_ratio\": {},\n  \"sphere\": {},\n  \"substrate\": {}\n}}\n",
               models.empty() ? "" : "\n  ", nlohmann::json(o.radius_ratio).dump(),
               head["sphere"].dump(), head["substrate"].dump());
    return 0;
  }
  fmt::print("model,velocity,e,k1,k2,v_y,status\n");
  for (const auto& m : models) {
    m.cor(velocities, e);
    const double vy = m.yield_velocity();
    const auto status = restitution::to_string(m.info().status);
    for (std::size_t i = 0; i < velocities.size(); ++i) {
      fmt::print("{},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{}\n", m.info().name, velocities[i],
                 e[i], k1(e_star, rho, velocities[i]), k2(sy, e_star), vy, status);
    }
  }
  return 0;
}

// --model fe|auto (predict_fe.hpp).
int run_predict_fe_model(const PredictOptions& o) {
  return run_predict_fe({o.model, o.sphere, o.substrate, parse_material_spec(o.sphere, "sphere"),
                         parse_material_spec(o.substrate, "substrate"),
                         parse_velocities(o.velocity, o.spacing), o.radius_ratio, o.format, o.fe});
}

const CommandRegistration kRegistration{Command{
    "predict", "Evaluate analytic CoR models e(v) for a sphere on a substrate",
    [](CLI::App& sub) -> std::function<int()> {
      auto o = std::make_shared<PredictOptions>();
      sub.add_option(
             "--model", o->model,
             "model name (see `corlab models`), 'all', 'fe' (the FE solver, with error bars) or "
             "'auto' (corlab2026p where accurate, else the FE)")
          ->required();
      sub.add_option("--sphere", o->sphere,
                     "sphere material: database name or E=..,nu=..,rho=..[,sy=..]")
          ->required();
      sub.add_option("--substrate", o->substrate,
                     "substrate material (needs a yield stress sy): name or inline spec")
          ->required();
      sub.add_option("--velocity", o->velocity,
                     "impact speed V, list V1,V2,... or range START:STOP:N [m/s]")
          ->required();
      sub.add_option("--spacing", o->spacing, "range spacing: lin|log")
          ->check(CLI::IsMember({"lin", "log"}));
      sub.add_option("--format", o->format, "output format: csv|json")
          ->check(CLI::IsMember({"csv", "json"}));
      sub.add_option("--clamp", o->clamp, "clamp e to [0,1]: default|on|off")
          ->check(CLI::IsMember({"default", "on", "off"}));
      sub.add_option("--radius", o->radius,
                     "sphere radius [m] for the energy models (e is R-independent)");
      sub.add_option("--radius-ratio", o->radius_ratio,
                     "R1/R2, the sphere's radius over the substrate's: the substrate is a free "
                     "second sphere at rest (0, the default: a flat; above 1 the sphere is the "
                     "larger body) [-]");
      add_fe_options(sub, o->fe);
      return [o] { return is_fe_model(o->model) ? run_predict_fe_model(*o) : run_predict(*o); };
    },
    21}};

}  // namespace
}  // namespace corlab::cli
