// Bindings for the explicit impact solver: corlab.simulate(settings, config_file) -> dict.
// SPDX-License-Identifier: BSD-3-Clause
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>

#include "bindings.hpp"
#include "corlab/core/error.hpp"
#include "corlab/fem/config/config_keys.hpp"
#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/output/impact_output.hpp"
#include "corlab/fem/solver/discretisation_error.hpp"
#include "corlab/fem/solver/error_bar.hpp"
#include "corlab/fem/solver/history_columns.hpp"
#include "corlab/fem/solver/result_fields.hpp"
#include "corlab/fem/solver/simulate.hpp"
#include "interruptible.hpp"

namespace py = pybind11;

namespace corlab::python {

namespace {

py::array_t<double> to_numpy(const std::vector<double>& v) {
  py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

// A setting value: text, or a number (formatted with full precision); a list only for a list key
// (output.times), never a bool or None (ambiguous: refused, not guessed).
std::string setting_text(const std::string& key, const py::handle& value) {
  if (py::isinstance<py::str>(value)) return utf8_text(value, key);
  if (value.is_none() || py::isinstance<py::bool_>(value)) {
    throw_invalid(key, py::repr(value).cast<std::string>(),
                  "a number or a string (`none` for an elastic body)");
  }
  // an int as its exact decimal text: 10**400 is then refused by the key's range (ValueError),
  // not by a failed cast to a C++ integer (RuntimeError)
  if (py::isinstance<py::int_>(value)) return py::str(value).cast<std::string>();
  if (py::isinstance<py::float_>(value)) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", value.cast<double>());
    return buf;
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    const fem::ConfigKeyInfo* info = fem::find_config_key(key);
    if (info != nullptr && info->kind != fem::KeyKind::number_list) {
      throw_invalid(key, py::repr(value).cast<std::string>(), "a single value, not a list");
    }
    std::string out;
    for (const auto& item : value) {
      if (!out.empty()) out += ",";
      out += setting_text(key, item);
    }
    return out;
  }
  return py::str(value).cast<std::string>();
}

py::list result_fields_list() {
  py::list fields;
  for (const auto& f : fem::result_fields()) {
    py::dict d;
    d["name"] = std::string(f.name);
    d["unit"] = std::string(f.unit);
    d["description"] = std::string(f.description);
    d["kind"] = std::string(fem::to_string(f.kind));
    d["in_summary"] = (f.outputs & fem::kSummary) != 0;
    d["in_csv"] = (f.outputs & fem::kCsv) != 0;
    d["machine_dependent"] = f.machine_dependent;
    fields.append(d);
  }
  return fields;
}

py::list history_columns_list() {
  py::list columns;
  for (const auto& c : fem::history_columns()) {
    py::dict d;
    d["name"] = std::string(c.name);
    d["unit"] = std::string(c.unit);
    d["description"] = std::string(c.description);
    d["csv_header"] = fem::history_csv_header(c);
    columns.append(d);
  }
  return columns;
}

/// A field's value as Python: None-like NaN for an empty value (e of a failed run), else the
/// value itself.
py::object field_object(const fem::FieldValue& value) {
  return std::visit(
      [](const auto& v) -> py::object {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::monostate>) {
          return py::float_(std::numeric_limits<double>::quiet_NaN());
        } else {
          return py::cast(v);
        }
      },
      value);
}

/// simulate()'s dict: the summary fields of the result-field table, "config" (the echo of every
/// config key) and "history" (one numpy array per history column).
py::dict result_dict(const fem::ImpactResult& result, const fem::ImpactConfig& config) {
  py::dict out;
  const fem::FieldInput in{&result, &config, result.wall_s};
  for (const auto& f : fem::result_fields()) {
    if ((f.outputs & fem::kSummary) != 0)
      out[py::str(std::string(f.name))] = field_object(f.value(in));
  }
  out["config"] = json_to_python(fem::config_to_json(config));
  py::dict history;
  for (const auto& c : fem::history_columns()) {
    history[py::str(std::string(c.name))] = to_numpy(result.history.*c.series);
  }
  out["history"] = history;
  return out;
}

}  // namespace

py::object json_to_python(const nlohmann::json& j) {
  if (j.is_object()) {
    py::dict d;
    for (const auto& [key, value] : j.items()) d[py::str(key)] = json_to_python(value);
    return d;
  }
  if (j.is_array()) {
    py::list l;
    for (const auto& value : j) l.append(json_to_python(value));
    return l;
  }
  if (j.is_boolean()) return py::bool_(j.get<bool>());
  if (j.is_number_integer()) return py::int_(j.get<long long>());
  if (j.is_number()) return py::float_(j.get<double>());
  if (j.is_string()) return py::str(j.get<std::string>());
  return py::none();
}

// corlab.simulate's docstring.
constexpr const char* kSimulateDoc =
    R"(Runs one explicit FE impact (elastic sphere on an elastic-plastic substrate).

settings: {key: value} with the keys of `corlab simulate --set` (SI units), e.g.
  {"impact.velocity": 2.0, "substrate.material": "steel_ma2023,sy=700e6"}.
config_file: optional TOML case file applied before `settings`.
mesh_ratio: the built-in mesh that many times coarser everywhere (0.5: twice as fine), as the
  error estimate's companions are (corlab::fem::coarsened); 1 = as configured.
error_estimate: also run the companions and set e_error, e_coarse (corlab simulate
  --error-estimate).
e_only: end one short window after the last contact, as the error estimate's companions do
  (SimulationControl::e_only): e, e_t and omega final, the energies and history cut short.
Returns a dict: e, e_energy, F_max [N], delta_max [m], t_contact [s], energy_* [J], ...,
"config" (the case), "history" (numpy arrays: time [s], contact_force [N], indentation [m], ...).
The GIL is released during the run; Ctrl-C stops it (KeyboardInterrupt). Bad input raises
ValueError.)";

void bind_simulate(py::module_& m) {
  // pybind11 keeps its NumPy API in a function-local static that imports numpy on first use: two
  // threads calling simulate() first at once deadlocked (one inside the static's guard, waiting
  // for the GIL the other holds while it waits for the guard). Made here, at import, under the GIL.
  (void)py::array_t<double>(0);
  m.def("result_fields", &result_fields_list,
        "The result fields (one table in C++, src/fem/solver/result_fields.cpp): a list of dicts "
        "with name, unit (SI; '-' dimensionless), description, kind (real | integer | boolean | "
        "text), in_summary (simulate()'s dict, summary.json), in_csv (a sweep's results.csv, in "
        "column order) and machine_dependent (timings).");

  m.def("history_columns", &history_columns_list,
        "The time histories' columns (one table in C++, src/fem/solver/history_columns.cpp): a "
        "list of dicts with name (simulate()['history'] key), unit (SI; '-' dimensionless), "
        "description and csv_header (history.csv's column).");

  m.def(
      "error_bar",
      [](const std::string& name, const std::vector<double>& e, const std::vector<double>& ratios) {
        return fem::error_bar(name, e, ratios);
      },
      py::arg("name"), py::arg("e"), py::arg("ratios"),
      "The error bar U [-] of e[0] (e[0] +/- U) from the same case's e on meshes `ratios` times "
      "coarser (ratios[0] = 1), by the estimator `name` (error_bar_estimators(); "
      "corlab/fem/solver/error_bar.hpp). NaN where a value is not finite.");
  m.def(
      "error_bar_estimators",
      [] {
        std::vector<std::string> names;
        for (const auto n : fem::error_bar_estimators()) names.emplace_back(n);
        return names;
      },
      "The error-bar estimators' names (corlab/fem/solver/error_bar.hpp).");

  m.def(
      "simulate",
      [](const py::dict& settings, std::optional<std::string> config_file, double mesh_ratio,
         bool error_estimate, bool e_only) {
        fem::ImpactConfig config;
        if (config_file) config = fem::load_impact_config(*config_file);
        std::vector<std::string> items;
        for (const auto& [key, value] : settings) {
          const auto name = utf8_text(py::str(key), "settings key");
          items.push_back(name + "=" + setting_text(name, value));
        }
        fem::apply_settings(config, items, "settings");
        if (!(mesh_ratio > 0.0) || !std::isfinite(mesh_ratio)) {
          throw_invalid("mesh_ratio", mesh_ratio, "a finite number > 0");
        }
        if (mesh_ratio != 1.0) config = fem::coarsened(config, mesh_ratio);
        fem::validate(config);
        std::atomic<bool> cancel{false};
        fem::SimulationControl control;
        control.cancel = &cancel;
        control.config_validated = true;  // above
        control.e_only = e_only;
        const fem::ImpactResult result = run_interruptible(cancel, [&] {
          return error_estimate ? fem::simulate_with_error_estimate(config, control)
                                : fem::simulate(config, control);
        });
        if (const std::string late = fem::unreached_output_times(config, result); !late.empty()) {
          py::module_::import("warnings").attr("warn")(late);
        }
        return result_dict(result, config);
      },
      py::arg("settings") = py::dict(), py::arg("config_file") = py::none(),
      py::arg("mesh_ratio") = 1.0, py::arg("error_estimate") = false, py::arg("e_only") = false,
      kSimulateDoc);
}

}  // namespace corlab::python
