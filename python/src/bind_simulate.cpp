// Bindings for the explicit impact solver: corlab.simulate(settings, config_file) -> dict.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <limits>
#include <optional>
#include <string>
#include <variant>

#include "bindings.hpp"
#include "corlab/core/error.hpp"
#include "corlab/fem/config/config_keys.hpp"
#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/output/impact_output.hpp"
#include "corlab/fem/solver/result_fields.hpp"
#include "corlab/fem/solver/simulate.hpp"

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
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (value.is_none() || py::isinstance<py::bool_>(value)) {
    throw_invalid(key, py::repr(value).cast<std::string>(),
                  "a number or a string (`none` for an elastic body)");
  }
  if (py::isinstance<py::int_>(value)) return std::to_string(value.cast<long long>());
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

}  // namespace

void bind_simulate(py::module_& m) {
  m.def("result_fields", &result_fields_list,
        "The result fields (one table in C++, src/fem/solver/result_fields.cpp): a list of dicts "
        "with name, unit (SI; '-' dimensionless), description, kind (real | integer | boolean | "
        "text), in_summary (simulate()'s dict, summary.json), in_csv (a sweep's results.csv, in "
        "column order) and machine_dependent (timings).");

  m.def(
      "simulate",
      [](const py::dict& settings, std::optional<std::string> config_file) {
        fem::ImpactConfig config;
        if (config_file) config = fem::load_impact_config(*config_file);
        std::vector<std::string> items;
        for (const auto& [key, value] : settings) {
          const auto name = py::str(key).cast<std::string>();
          items.push_back(name + "=" + setting_text(name, value));
        }
        fem::apply_settings(config, items, "settings");
        fem::validate(config);
        fem::ImpactResult result;
        {
          py::gil_scoped_release release;
          result = fem::simulate(config);
        }
        const nlohmann::json summary = fem::summary_to_json(result, config);
        py::dict out;
        for (const auto& [key, value] : summary.items()) {
          if (value.is_number_float()) {
            out[py::str(key)] = value.get<double>();
          } else if (value.is_number_integer()) {
            out[py::str(key)] = value.get<long long>();
          } else if (value.is_boolean()) {
            out[py::str(key)] = value.get<bool>();
          } else if (value.is_string()) {
            out[py::str(key)] = value.get<std::string>();
          } else if (value.is_null()) {
            out[py::str(key)] = std::numeric_limits<double>::quiet_NaN();  // e of a failed run
          }
        }
        out["config"] = py::module_::import("json").attr("loads")(summary["config"].dump());
        const fem::ImpactHistory& h = result.history;
        py::dict hist;
        hist["time"] = to_numpy(h.time);
        hist["contact_force"] = to_numpy(h.contact_force);
        hist["indentation"] = to_numpy(h.indentation);
        hist["sphere_velocity"] = to_numpy(h.sphere_velocity);
        hist["kinetic_energy"] = to_numpy(h.kinetic_energy);
        hist["strain_energy"] = to_numpy(h.strain_energy);
        hist["plastic_dissipation"] = to_numpy(h.plastic_dissipation);
        hist["hourglass_energy"] = to_numpy(h.hourglass_energy);
        hist["viscous_dissipation"] = to_numpy(h.viscous_dissipation);
        hist["contact_energy"] = to_numpy(h.contact_energy);
        hist["energy_balance_error"] = to_numpy(h.energy_balance_error);
        out["history"] = hist;
        return out;
      },
      py::arg("settings") = py::dict(), py::arg("config_file") = py::none(),
      R"(Runs one explicit FE impact (elastic sphere on an elastic-plastic substrate).

settings: {key: value} with the keys of `corlab simulate --set` (SI units), e.g.
  {"impact.velocity": 2.0, "substrate.material": "steel_ma2023,sy=700e6"}.
config_file: optional TOML case file applied before `settings`.
Returns a dict: e, e_energy, F_max [N], delta_max [m], t_contact [s], energy_* [J], ...,
"config" (the case), "history" (numpy arrays: time [s], contact_force [N], indentation [m], ...).
The GIL is released during the run. Bad input raises ValueError.)");
}

}  // namespace corlab::python
