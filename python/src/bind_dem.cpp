// DEM hand-off (issue 11): corlab.dem.* - contact laws, exact chi(e), impact integration, exports.
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/format.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <map>
#include <nlohmann/json.hpp>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>

#include "bindings.hpp"
#include "corlab/core/error.hpp"
#include "corlab/dataset/dem_fe_targets.hpp"
#include "corlab/dem/calibration.hpp"
#include "corlab/dem/contact_ode.hpp"
#include "corlab/dem/dem_export.hpp"
#include "corlab/dem/hysteresis_chi.hpp"
#include "corlab/dem/lammps_mapping.hpp"
#include "corlab/dem/law_info.hpp"
#include "corlab/dem/viscoelastic_restitution.hpp"
#include "corlab/materials/material_database.hpp"
#include "corlab/study/result_cache.hpp"
#include "interruptible.hpp"

namespace py = pybind11;

namespace corlab::python {
namespace {

dem::ChiFormula formula_by_name(const std::string& name) {
  for (const auto f : dem::kChiFormulas) {
    if (dem::to_string(f) == name) return f;
  }
  throw_invalid("formula", name,
                "one of [hunt_crossley, lankarani_nikravesh, flores, gonthier, hu_guo, "
                "carvalho_martins]");
}

// The bounds of a law parameter (contact_laws.hpp): > 0, or >= 0 where 0 means none.
struct ParamRule {
  std::string_view name;
  bool zero_allowed;
  std::string_view unit;
};
constexpr std::array<ParamRule, 10> kParamRules{{{"stiffness", false, "[N/m^n]"},
                                                 {"chi", true, "[-]"},
                                                 {"impact_velocity", false, "[m/s]"},
                                                 {"exponent", false, "[-]"},
                                                 {"alpha", true, "[-]"},
                                                 {"effective_mass", false, "[kg]"},
                                                 {"damping", true, "[N s/m^1.5 or N s/m]"},
                                                 {"effective_modulus", false, "[Pa]"},
                                                 {"radius", false, "[m]"},
                                                 {"limiting_pressure", false, "[Pa]"}}};

double param(const std::map<std::string, double>& p, const std::string& key) {
  const auto it = p.find(key);
  if (it == p.end()) throw_invalid("params", key, "present for this law");
  const std::string field = "params['" + key + "']";
  for (const auto& rule : kParamRules) {
    if (rule.name != key) continue;
    if (rule.zero_allowed) {
      require_non_negative(field, it->second, rule.unit);
    } else {
      require_positive(field, it->second, rule.unit);
    }
  }
  return it->second;
}

// A dict of numbers (law parameters, pair restitutions) with each value checked to be one:
// ValueError naming `field`['key'] for a string or another non-number.
std::map<std::string, double> number_dict(const py::dict& d, std::string_view field) {
  std::map<std::string, double> out;
  for (const auto& [key, value] : d) {
    const auto name = py::str(key).cast<std::string>();
    const std::string where = fmt::format("{}['{}']", field, name);
    if (py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value)) {
      throw_invalid(where, py::repr(value).cast<std::string>(), "a number");
    }
    try {
      out[name] = value.cast<double>();
    } catch (const py::cast_error&) {
      throw_invalid(where, py::repr(value).cast<std::string>(), "a number");
    }
  }
  return out;
}

// A ForceLaw from a law name and its parameters (SI units, see contact_laws.hpp).
dem::ForceLaw make_law(const std::string& law, const std::map<std::string, double>& p) {
  using dem::ContactHistory;
  if (law == "hertz") {
    const dem::HertzLaw l{param(p, "stiffness")};
    return [l](double d, double, const ContactHistory&) { return l.force(d); };
  }
  if (law == "hysteresis") {
    const dem::HysteresisLaw l{param(p, "stiffness"), param(p, "chi"), param(p, "impact_velocity"),
                               p.count("exponent") ? p.at("exponent") : 1.5};
    return [l](double d, double r, const ContactHistory&) { return l.force(d, r); };
  }
  if (law == "tsuji") {
    const dem::TsujiLaw l{param(p, "stiffness"), param(p, "alpha"), param(p, "effective_mass")};
    return [l](double d, double r, const ContactHistory&) { return l.force(d, r); };
  }
  if (law == "viscoelastic") {
    const dem::ViscoelasticHertzLaw l{param(p, "stiffness"), param(p, "damping")};
    return [l](double d, double r, const ContactHistory&) { return l.force(d, r); };
  }
  if (law == "linear") {
    const dem::LinearSpringDashpotLaw l{param(p, "stiffness"), param(p, "damping")};
    return [l](double d, double r, const ContactHistory&) { return l.force(d, r); };
  }
  const restitution::ThorntonContact c{param(p, "effective_modulus"), param(p, "radius"),
                                       param(p, "limiting_pressure")};
  if (law == "thornton") {
    const dem::ThorntonNingLaw l{c};
    return [l](double d, double, const ContactHistory& h) { return l.force(d, h); };
  }
  if (law == "liggghts_thornton_ning") {
    const dem::LiggghtsThorntonNingLaw l{c};
    return [l](double d, double, const ContactHistory& h) { return l.force(d, h); };
  }
  throw_invalid("law", law,
                "one of [hertz, hysteresis, tsuji, viscoelastic, linear, thornton, "
                "liggghts_thornton_ning]");
}

// corlab.dem.simulate_impact: one impact of a law given by name and parameters; a bad parameter,
// or a law that never separates the bodies or whose force stops being finite, is a ValueError.
py::dict simulate_impact_py(const std::string& law,
                            const py::dict& params_dict,
                            double mass,
                            double velocity) {
  const auto params = number_dict(params_dict, "params");
  const auto force = make_law(law, params);
  std::string shown;
  for (const auto& [k, v] : params)
    shown += fmt::format("{}{}={}", shown.empty() ? "" : ", ", k, v);
  dem::ImpactOutcome out;
  try {
    out = dem::simulate_impact(force, mass, velocity);
  } catch (const dem::NotSeparated&) {
    throw_invalid("params of law " + law, shown,
                  fmt::format("a law that separates the bodies (e >= {}); at m* = {} kg, v = {} "
                              "m/s it is overdamped or sticks",
                              dem::kMinRestitution, mass, velocity));
  } catch (const std::runtime_error& e) {
    throw_invalid("params of law " + law, shown,
                  fmt::format("a law with a finite force through the impact ({})", e.what()));
  }
  py::dict r;
  r["e"] = out.restitution;
  r["contact_time"] = out.contact_time;
  r["max_overlap"] = out.max_overlap;
  return r;
}

using VelocityTable = std::pair<std::vector<double>, std::vector<double>>;

// The e(v) of table = (velocities [m/s], e [-]), sorted by speed as the CLI's --table (FE
// results rows come in finishing order).
dem::RestitutionCurve sorted_table(const VelocityTable& table) {
  if (table.first.size() != table.second.size()) {
    throw_invalid("table", static_cast<double>(table.second.size()),
                  fmt::format("{} restitution values (one per velocity)", table.first.size()));
  }
  std::vector<std::size_t> order(table.first.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return table.first[a] < table.first[b]; });
  std::vector<double> v, e;
  for (const std::size_t i : order) {
    v.push_back(table.first[i]);
    e.push_back(table.second[i]);
  }
  return dem::tabulated_curve(v, e);
}

// The walls (wall, then walls, each as the CLI's --wall [LABEL=]MATERIAL[@SHAPE]), the pairs'
// constant e (--pair A/B=E) and the pairs' mu (--friction A/B=MU) of the Python arguments.
void add_named(dem::ExportSpec& spec,
               const std::string& wall,
               const std::vector<std::string>& walls,
               const py::dict& pairs_dict,
               const py::dict& pair_friction_dict) {
  if (!wall.empty()) dem::add_wall(spec, wall);
  for (const auto& w : walls) dem::add_wall(spec, w);
  for (const auto& [pair, e] : number_dict(pairs_dict, "pairs")) {
    spec.pair_restitution.push_back(dem::parse_pair_restitution(fmt::format("{}={}", pair, e)));
  }
  for (const auto& [pair, mu] : number_dict(pair_friction_dict, "pair_friction")) {
    spec.pair_friction.push_back(dem::parse_pair_value(fmt::format("{}={}", pair, mu), "friction"));
  }
}

// Every text `corlab dem` writes, by name (stl: file name -> LIGGGHTS's mesh of each oblique
// plane, the name liggghts.in reads).
py::dict export_texts(const dem::ExportSpec& spec, const std::vector<dem::PairCalibration>& pairs) {
  py::dict out;
  out["lammps"] = dem::write_lammps(spec, pairs);
  out["lammps_nopython"] = dem::write_lammps(spec, pairs, false);
  out["liggghts"] = dem::write_liggghts(spec, pairs);
  out["yade"] = dem::write_yade(spec, pairs);
  out["csv"] = dem::write_table_csv(spec, pairs);
  out["json"] = dem::write_json(spec, pairs);
  py::dict meshes;
  for (const auto& [name, stl] : dem::wall_meshes(spec)) meshes[py::str(name)] = stl;
  out["stl"] = meshes;
  return out;
}

py::dict export_dem(const std::vector<std::pair<std::string, double>>& types,
                    const std::string& wall,
                    std::optional<double> restitution,
                    const std::string& model,
                    double v_min,
                    double v_max,
                    bool wall_only,
                    int fit_points,
                    const std::optional<VelocityTable>& table,
                    const std::string& table_source,
                    const py::dict& pairs_dict,
                    double friction,
                    int jobs,
                    bool cache,
                    const std::vector<std::string>& walls,
                    const py::dict& pair_friction_dict,
                    double rolling) {
  dem::ExportSpec spec;
  spec.friction = friction;  // Coulomb mu [-] of every pair
  spec.rolling = rolling;    // rolling resistance mu_r [-] of every pair
  for (const auto& [material, radius] : types) {
    auto labelled = dem::parse_labelled_material(material, "type");
    spec.types.push_back({std::move(labelled.material), radius, std::move(labelled.label)});
  }
  add_named(spec, wall, walls, pairs_dict, pair_friction_dict);
  spec.restitution = restitution;
  spec.model = model;
  spec.v_min = v_min;
  spec.v_max = v_max;
  spec.wall_only = wall_only;
  spec.fit_points = fit_points;
  if (table) {
    spec.table = sorted_table(*table);
    spec.table_source = table_source.empty() ? "table given in Python" : table_source;
  }
  // model "fe" or "auto": each pair's e(v) from the FE solver (dem_fe_targets.hpp), cached.
  std::vector<std::string> warnings;
  std::optional<study::ResultCache> store;
  if (dem::is_external_model(spec.model)) {
    if (cache) {
      store.emplace(study::default_cache_directory(), study::cache_build_id(),
                    [&warnings](const std::string& w) { warnings.push_back(w); });
    }
  }
  // Ctrl-C stops the FE runs (KeyboardInterrupt; finished speeds stay cached), as in simulate().
  std::atomic<bool> cancel{false};
  if (dem::is_external_model(spec.model)) {
    spec.target_source = dataset::fe_pair_targets(
        spec.model, {.jobs = jobs, .cache = store ? &*store : nullptr, .cancel = &cancel});
  }
  const std::vector<dem::PairCalibration> calibrated = run_interruptible(cancel, [&] {
    try {
      return dem::calibrate_export(spec);  // as `corlab dem`: every wall material, each pair's mu
    } catch (const InputError&) {
      if (cancel.load()) return std::vector<dem::PairCalibration>{};  // a cancelled run's row
      throw;
    }
  });
  for (const auto& p : calibrated) {
    for (const auto& w : p.warnings) warnings.push_back("pair " + p.name() + ": " + w);
  }
  for (const auto& w : warnings) {
    if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) != 0) throw py::error_already_set();
  }
  return export_texts(spec, calibrated);
}

}  // namespace

void bind_dem(py::module_& m) {
  auto d = m.def_submodule("dem", "DEM contact laws calibrated to e or e(v) (SI units)");
  d.def("exact_chi", py::vectorize(&dem::exact_chi), py::arg("e"),
        "Exact hysteresis chi: chi (1 + e) = ln[(1 + chi)/(1 - e chi)]");
  d.def("exact_restitution", py::vectorize(&dem::exact_restitution), py::arg("chi"),
        "Exact e delivered by chi (Lambert W)");
  d.def(
      "published_chi",
      [](const std::string& formula, double e) {
        return dem::published_chi(formula_by_name(formula), e);
      },
      py::arg("formula"), py::arg("e"), "Published chi(e) approximation by name");
  d.def("chi_formulas", [] {
    std::vector<std::string> names;
    names.reserve(dem::kChiFormulas.size());
    for (const auto f : dem::kChiFormulas) names.emplace_back(dem::to_string(f));
    return names;
  });
  d.def("laws", [] {
    py::list out;
    for (const auto& info : dem::law_catalog()) {
      py::dict i;
      i["name"] = info.name;
      i["citation"] = info.citation;
      i["equation"] = info.equation;
      i["status"] = std::string(restitution::to_string(info.status));
      i["status_note"] = info.status_note;
      out.append(i);
    }
    return out;
  });
  d.def(
      "schwager_poeschel",
      [](double stiffness, double damping, double mass, double velocity, const std::string& form) {
        const dem::ViscoelasticHertzLaw law{stiffness, damping};
        if (form == "pade") return dem::schwager_poeschel_pade(law, mass, velocity);
        if (form == "series") return dem::schwager_poeschel_series(law, mass, velocity);
        throw_invalid("form", form, "one of [pade, series]");
      },
      py::arg("stiffness"), py::arg("damping"), py::arg("effective_mass"), py::arg("velocity"),
      py::arg("form") = "pade",
      "Schwager-Poeschel e(v) of the viscoelastic Hertz law (K [N/m^1.5], c [N s/m^1.5], "
      "m* [kg], v [m/s]): form 'pade' (large dissipation) or 'series' (e >= 0.9)");
  d.def("tsuji_alpha", &dem::calibrate_tsuji_alpha, py::arg("e"), "Exact alpha of TsujiLaw");
  d.def("lammps_tsuji_input", &dem::lammps_tsuji_input, py::arg("e"),
        "e_in for LAMMPS damping tsuji so that it delivers e");
  d.def("simulate_impact", &simulate_impact_py, py::arg("law"), py::arg("params"),
        py::arg("effective_mass"), py::arg("velocity"),
        "Integrates one head-on impact (GSL ODE) and returns e, contact time [s], max overlap [m]");
  d.def("export", &export_dem, py::arg("types"), py::arg("wall") = "",
        py::arg("restitution") = std::nullopt, py::arg("model") = "", py::arg("v_min") = 0.1,
        py::arg("v_max") = 10.0, py::arg("wall_only") = false, py::arg("fit_points") = 9,
        py::arg("table") = std::nullopt, py::arg("table_source") = "",
        py::arg("pairs") = py::dict(), py::arg("friction") = 0.0, py::arg("jobs") = 0,
        py::arg("cache") = true, py::arg("walls") = std::vector<std::string>{},
        py::arg("pair_friction") = py::dict(), py::arg("rolling") = 0.0,
        "Calibrates and returns the LAMMPS/LIGGGHTS/YADE fragments and CSV/JSON tables. "
        "table = (velocities [m/s], e [-]): an FE e(v) table instead of `restitution` or "
        "`model` (e.g. t = corlab.read_results('results.csv'); table=(t['velocity'], t['e'])); "
        "table_source names it in the exported files. A type or wall material may carry a "
        "label ('glass=E=63e9,nu=0.22,rho=2500'); model 'fe' or 'auto': each pair's e(v) from "
        "corlab's FE solver at the fit speeds (as predict_curve; jobs: speeds at once, cache: "
        "the result cache), elastic pairs included; a pair's accuracy warnings are "
        "UserWarnings; pairs = {'glass/glass': 1.0} sets one pair's "
        "constant e (labels or type ids, 'wall'); friction = Coulomb mu of every pair (0: "
        "frictionless; above 0 the fragments add Mindlin's tangential stiffness 8 G* a), "
        "pair_friction = {'glass/wall': 0.5} one pair's mu, rolling = rolling resistance mu_r "
        "of every pair; walls = ['side=steel_ma2023@plane:0.04,0,0,-1,0,0', ...] more walls "
        "after `wall`, each as `corlab dem --wall` ([LABEL=]MATERIAL[@SHAPE]; docs/user/dem.md). "
        "Returns the texts by name: lammps, lammps_nopython, liggghts, yade, csv, json and stl "
        "(file name -> LIGGGHTS mesh of each oblique plane, to write next to liggghts.in).");
}

}  // namespace corlab::python
