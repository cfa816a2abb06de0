// Validation and text input (--set key=value, TOML) of ImpactConfig.
#include "corlab/fem/impact_config.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

#include <charconv>
#include <cmath>
#include <functional>
#include <map>
#include <string>

#include "corlab/core/error.hpp"
#include "corlab/materials/material_database.hpp"

namespace corlab::fem {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

double parse_double(std::string_view key, std::string_view text) {
  text = trim(text);
  double value = 0.0;
  const auto* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) {
    throw_invalid(key, text, "a finite number");
  }
  return value;
}

int parse_int(std::string_view key, std::string_view text) {
  text = trim(text);
  int value = 0;
  const auto* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end) throw_invalid(key, text, "an integer");
  return value;
}

std::vector<double> parse_list(std::string_view key, std::string_view text) {
  std::vector<double> out;
  text = trim(text);
  if (!text.empty() && text.front() == '[' && text.back() == ']') {
    text = trim(text.substr(1, text.size() - 2));
  }
  if (text.empty()) return out;
  while (true) {
    const auto comma = text.find(',');
    out.push_back(parse_double(key, text.substr(0, comma)));
    if (comma == std::string_view::npos) break;
    text.remove_prefix(comma + 1);
  }
  return out;
}

// "none" / "" / "elastic" clears the yield stress.
std::optional<double> parse_yield(std::string_view key, std::string_view text) {
  const auto t = trim(text);
  if (t.empty() || t == "none" || t == "elastic") return std::nullopt;
  return parse_double(key, t);
}

using Setter = std::function<void(ImpactConfig&, std::string_view key, std::string_view value)>;

template <typename Get>
Setter number_setter(Get get) {
  return [get](ImpactConfig& c, std::string_view key, std::string_view value) {
    get(c) = parse_double(key, value);
  };
}

const std::map<std::string, Setter, std::less<>>& setters() {
  static const std::map<std::string, Setter, std::less<>> table = [] {
    std::map<std::string, Setter, std::less<>> m;
    auto material = [](bool sphere) -> Material& (*)(ImpactConfig&) {
      return sphere ? +[](ImpactConfig& c) -> Material& { return c.sphere.material; }
                    : +[](ImpactConfig& c) -> Material& { return c.substrate.material; };
    };
    for (const bool sphere : {true, false}) {
      const std::string body = sphere ? "sphere" : "substrate";
      auto mat = material(sphere);
      m[body + ".material"] = [mat, body](ImpactConfig& c, std::string_view, std::string_view v) {
        mat(c) = parse_material_spec(trim(v), body);
      };
      m[body + ".E"] = [mat](ImpactConfig& c, std::string_view k, std::string_view v) {
        mat(c).youngs_modulus = parse_double(k, v);
      };
      m[body + ".nu"] = [mat](ImpactConfig& c, std::string_view k, std::string_view v) {
        mat(c).poisson_ratio = parse_double(k, v);
      };
      m[body + ".rho"] = [mat](ImpactConfig& c, std::string_view k, std::string_view v) {
        mat(c).density = parse_double(k, v);
      };
      m[body + ".sigma_y"] = [mat](ImpactConfig& c, std::string_view k, std::string_view v) {
        mat(c).yield_stress = parse_yield(k, v);
      };
      m[body + ".hardening"] = [mat](ImpactConfig& c, std::string_view k, std::string_view v) {
        mat(c).hardening_modulus = parse_double(k, v);
      };
    }
    m["sphere.radius"] = number_setter([](ImpactConfig& c) -> double& { return c.sphere.radius; });
    m["substrate.radius"] =
        number_setter([](ImpactConfig& c) -> double& { return c.substrate.radius; });
    m["substrate.depth"] =
        number_setter([](ImpactConfig& c) -> double& { return c.substrate.depth; });
    m["impact.velocity"] =
        number_setter([](ImpactConfig& c) -> double& { return c.impact.velocity; });
    m["impact.gap"] = number_setter([](ImpactConfig& c) -> double& { return c.impact.gap; });
    m["mesh.h_min"] = number_setter([](ImpactConfig& c) -> double& { return c.mesh.h_min; });
    m["mesh.growth"] = number_setter([](ImpactConfig& c) -> double& { return c.mesh.growth; });
    m["mesh.h_max"] = number_setter([](ImpactConfig& c) -> double& { return c.mesh.h_max; });
    m["mesh.refine_factor"] =
        number_setter([](ImpactConfig& c) -> double& { return c.mesh.refine_factor; });
    m["mesh.contact_elements"] =
        number_setter([](ImpactConfig& c) -> double& { return c.mesh.contact_elements; });
    m["mesh.file"] = [](ImpactConfig& c, std::string_view, std::string_view v) {
      c.mesh.file = std::string(trim(v));
    };
    m["solver.safety_factor"] =
        number_setter([](ImpactConfig& c) -> double& { return c.solver.safety_factor; });
    m["solver.hourglass"] =
        number_setter([](ImpactConfig& c) -> double& { return c.solver.hourglass; });
    m["solver.bulk_viscosity_linear"] =
        number_setter([](ImpactConfig& c) -> double& { return c.solver.bulk_viscosity_linear; });
    m["solver.bulk_viscosity_quadratic"] =
        number_setter([](ImpactConfig& c) -> double& { return c.solver.bulk_viscosity_quadratic; });
    m["solver.penalty_scale"] =
        number_setter([](ImpactConfig& c) -> double& { return c.solver.penalty_scale; });
    m["solver.t_max"] = number_setter([](ImpactConfig& c) -> double& { return c.solver.t_max; });
    m["output.times"] = [](ImpactConfig& c, std::string_view k, std::string_view v) {
      c.output.field_times = parse_list(k, v);
    };
    m["output.history_every"] = [](ImpactConfig& c, std::string_view k, std::string_view v) {
      c.output.history_every = parse_int(k, v);
    };
    return m;
  }();
  return table;
}

std::vector<std::string> known_keys() {
  std::vector<std::string> keys;
  for (const auto& [k, s] : setters()) keys.push_back(k);
  return keys;
}

}  // namespace

void validate(const ImpactConfig& c) {
  require_positive("sphere.radius", c.sphere.radius, "[m]");
  validate(c.sphere.material, "sphere");
  require_positive("substrate.radius", c.substrate.radius, "[m]");
  require_positive("substrate.depth", c.substrate.depth, "[m]");
  validate(c.substrate.material, "substrate");
  require_positive("impact.velocity", c.impact.velocity, "[m/s]");
  require_non_negative("impact.gap", c.impact.gap, "[m]");
  require_positive("mesh.h_min", c.mesh.h_min, "[m]");
  if (!(std::isfinite(c.mesh.growth) && c.mesh.growth >= 1.0)) {
    throw_invalid("mesh.growth", c.mesh.growth, ">= 1");
  }
  if (!(std::isfinite(c.mesh.h_max) && c.mesh.h_max >= c.mesh.h_min)) {
    throw_invalid("mesh.h_max", c.mesh.h_max, fmt::format(">= mesh.h_min = {} [m]", c.mesh.h_min));
  }
  require_positive("mesh.refine_factor", c.mesh.refine_factor);
  require_non_negative("mesh.contact_elements", c.mesh.contact_elements);
  if (!(std::isfinite(c.solver.safety_factor) && c.solver.safety_factor > 0.0 &&
        c.solver.safety_factor <= 1.0)) {
    throw_invalid("solver.safety_factor", c.solver.safety_factor, "in (0, 1]");
  }
  require_non_negative("solver.hourglass", c.solver.hourglass);
  require_non_negative("solver.bulk_viscosity_linear", c.solver.bulk_viscosity_linear);
  require_non_negative("solver.bulk_viscosity_quadratic", c.solver.bulk_viscosity_quadratic);
  if (!(std::isfinite(c.solver.penalty_scale) && c.solver.penalty_scale > 0.0 &&
        c.solver.penalty_scale <= 1.0)) {
    throw_invalid("solver.penalty_scale", c.solver.penalty_scale, "in (0, 1]");
  }
  require_non_negative("solver.t_max", c.solver.t_max, "[s]");
  for (double t : c.output.field_times) require_non_negative("output.times", t, "[s]");
  if (c.output.history_every < 1) {
    throw_invalid("output.history_every", c.output.history_every, ">= 1");
  }
}

void apply_setting(ImpactConfig& config, std::string_view key, std::string_view value) {
  key = trim(key);
  const auto& table = setters();
  const auto it = table.find(key);
  if (it == table.end()) {
    throw_invalid("config key", key, fmt::format("one of {}", fmt::join(known_keys(), ", ")));
  }
  it->second(config, key, value);
}

ImpactConfig load_impact_config(const std::filesystem::path& file) {
  toml::table root;
  try {
    root = toml::parse_file(file.string());
  } catch (const toml::parse_error& err) {
    throw InputError(fmt::format("invalid config file '{}': {} (line {})", file.string(),
                                 err.description(), err.source().begin.line));
  }
  ImpactConfig config;
  for (const auto& [group_key, group] : root) {
    const std::string group_name(group_key.str());
    const auto* table = group.as_table();
    if (table == nullptr) {
      throw_invalid("config key", group_name,
                    "a [table] (sphere, substrate, impact, mesh, solver, output)");
    }
    for (const auto& [key, node] : *table) {
      const std::string full = group_name + "." + std::string(key.str());
      std::string text;
      if (auto s = node.value<std::string>(); s && node.is_string()) {
        text = *s;
      } else if (node.is_integer()) {
        text = fmt::format("{}", *node.value<long long>());
      } else if (node.is_floating_point()) {
        text = fmt::format("{}", *node.value<double>());
      } else if (const auto* arr = node.as_array()) {
        std::vector<std::string> items;
        for (const auto& item : *arr) {
          if (auto d = item.value<double>()) {
            items.push_back(fmt::format("{}", *d));
          } else {
            throw_invalid(full, "non-number array item", "a list of numbers");
          }
        }
        text = fmt::format("{}", fmt::join(items, ","));
      } else {
        throw_invalid(full, "unsupported value", "a number, a string or a list of numbers");
      }
      apply_setting(config, full, text);
    }
  }
  validate(config);
  return config;
}

}  // namespace corlab::fem
