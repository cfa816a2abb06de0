// Analytic CoR models: corlab.models(), corlab.predict(), corlab.yield_velocity().
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "bindings.hpp"
#include "corlab/core/error.hpp"
#include "corlab/dataset/auto_restitution.hpp"
#include "corlab/materials/material_database.hpp"
#include "corlab/restitution/corlab2026.hpp"
#include "corlab/restitution/corlab2026p.hpp"
#include "corlab/restitution/impact_pair.hpp"
#include "corlab/restitution/oblique_impact.hpp"
#include "corlab/restitution/registry.hpp"
#include "corlab/restitution/validity.hpp"
#include "corlab/study/fe_curve.hpp"
#include "corlab/study/result_cache.hpp"

namespace py = pybind11;

namespace corlab::python {

namespace {

// A Material or a spec (py::str, not std::string: a name pybind11 cannot encode, e.g. one with a
// lone surrogate, is then named in a ValueError instead of failing the overload with a TypeError).
using MaterialArg = std::variant<Material, py::str>;

Material to_material(const MaterialArg& arg, const char* field) {
  if (const auto* spec = std::get_if<py::str>(&arg)) {
    return parse_material_spec(utf8_text(*spec, field), field);
  }
  return std::get<Material>(arg);
}

// Issues a UserWarning for an unverified model so that no Python output silently contains one.
void warn_if_unverified(const restitution::Model& bound) {
  const auto& info = bound.info();
  if (info.status != restitution::Status::kUnverified) return;
  const std::string message = "corlab model '" + info.name + "' is UNVERIFIED: " + info.status_note;
  if (PyErr_WarnEx(PyExc_UserWarning, message.c_str(), 1) != 0) throw py::error_already_set();
}

// UserWarnings for velocities outside the model's validity (validity.hpp).
void warn_if_outside(const restitution::Model& bound,
                     const MaterialArg& sphere,
                     const MaterialArg& substrate,
                     std::span<const double> velocities,
                     double radius_ratio) {
  const Material other = to_material(substrate, "substrate");
  const Material reduced = pair_reduced_sphere(to_material(sphere, "sphere"), other, radius_ratio);
  auto warnings = restitution::validity_warnings(bound.info(), velocities, reduced, other);
  if (auto w = restitution::radius_ratio_warning(bound.info(), radius_ratio); !w.empty())
    warnings.push_back(std::move(w));
  for (const auto& w : warnings) {
    if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) != 0) throw py::error_already_set();
  }
}

restitution::Model bind_model(const std::string& model,
                              const MaterialArg& sphere,
                              const MaterialArg& substrate,
                              std::optional<bool> clamp,
                              double radius,
                              double radius_ratio = 0.0) {
  restitution::ModelOptions options;
  options.clamp = clamp;
  options.radius = radius;
  options.radius_ratio = radius_ratio;
  auto bound = restitution::make_model(model, to_material(sphere, "sphere"),
                                       to_material(substrate, "substrate"), options);
  warn_if_unverified(bound);
  return bound;
}

py::dict info_dict(const restitution::ModelInfo& info) {
  return json_to_python(restitution::model_info_json(info));
}

// The coefficient struct as a dict and back (names as in corlab2026.hpp).
py::dict coefficients_dict(const restitution::Corlab2026Coefficients& k) {
  py::dict d;
  for (const auto& [name, member] : restitution::kCorlab2026Coefficients) {
    d[py::str(std::string(name))] = k.*member;
  }
  return d;
}

// A finite float from `value` (a Python number), else ValueError naming dict[key].
double finite_number(const py::handle& value, std::string_view dict, std::string_view key) {
  const std::string field = fmt::format("{}[\"{}\"]", dict, key);
  double x = 0.0;
  try {
    x = value.cast<double>();
  } catch (const py::cast_error&) {
    throw_invalid(field, utf8_text(py::str(value), field), "a finite number");
  }
  if (!std::isfinite(x)) throw_invalid(field, x, "a finite number");
  return x;
}

restitution::Corlab2026Coefficients coefficients_from(const py::dict& d) {
  restitution::Corlab2026Coefficients k;
  for (const auto& [name, member] : restitution::kCorlab2026Coefficients) {
    const py::str key{std::string(name)};
    if (!d.contains(key)) throw_invalid("coefficients", name, "a key of the dict (missing)");
    k.*member = finite_number(d[key], "coefficients", name);
  }
  return k;
}

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// inputs[name] as a 1-D array of finite numbers of `size` elements (the first array's, named
// `first`); ValueError naming the array otherwise (arrays of different lengths read past the end).
Array input_column(const py::dict& inputs,
                   std::string_view name,
                   std::optional<std::pair<std::string_view, py::ssize_t>> first) {
  const py::str key{std::string(name)};
  const std::string field = fmt::format("inputs[\"{}\"]", name);
  if (!inputs.contains(key)) throw_invalid("inputs", name, "a key of the dict (missing)");
  Array column;
  try {
    column = inputs[key].cast<Array>();
  } catch (const py::cast_error&) {
    throw_invalid(field, utf8_text(py::str(inputs[key]), field), "an array of numbers");
  } catch (const py::error_already_set& err) {
    throw_invalid(field, utf8_text(py::str(inputs[key]), field),
                  fmt::format("an array of numbers ({})", err.what()));
  }
  if (column.ndim() != 1) {
    throw_invalid(fmt::format("{}.ndim", field), static_cast<double>(column.ndim()), "1");
  }
  if (first && column.size() != first->second) {
    throw_invalid(fmt::format("len({})", field), static_cast<double>(column.size()),
                  fmt::format("len(inputs[\"{}\"]) = {} (the arrays of one call have one length)",
                              first->first, first->second));
  }
  for (py::ssize_t i = 0; i < column.size(); ++i) {
    if (!std::isfinite(column.data()[i])) {
      throw_invalid(fmt::format("{}[{}]", field, i), column.data()[i], "a finite number");
    }
  }
  return column;
}

// corlab2026_restitution over arrays of inputs (the fit's inner loop): every array 1-D, of one
// length and finite (a NaN velocity ratio returned e = 1; unequal lengths read past the end).
py::array_t<double> corlab2026_over(const py::dict& inputs, const py::dict& coefficients) {
  const auto k = coefficients_from(coefficients);
  const Array other_is_sphere = input_column(inputs, "other_is_sphere", std::nullopt);
  const std::pair<std::string_view, py::ssize_t> first{"other_is_sphere", other_is_sphere.size()};
  std::vector<Array> columns;
  columns.reserve(std::size(restitution::kCorlab2026Inputs));
  for (const auto& [name, member] : restitution::kCorlab2026Inputs) {
    columns.push_back(input_column(inputs, name, first));
  }
  py::array_t<double> out(other_is_sphere.size());
  double* e = out.mutable_data();
  for (py::ssize_t i = 0; i < other_is_sphere.size(); ++i) {
    restitution::Corlab2026Inputs in{.other_is_sphere = other_is_sphere.data()[i] != 0.0};
    for (std::size_t j = 0; j < columns.size(); ++j) {
      in.*restitution::kCorlab2026Inputs[j].second = columns[j].data()[i];
    }
    e[i] = restitution::corlab2026_restitution(in, k);
  }
  return out;
}

// The inputs struct as a dict (names as in corlab2026.hpp; other_is_sphere 1 or 0).
py::dict inputs_dict(const restitution::Corlab2026Inputs& in) {
  py::dict d;
  for (const auto& [name, member] : restitution::kCorlab2026Inputs) {
    d[py::str(std::string(name))] = in.*member;
  }
  d["other_is_sphere"] = in.other_is_sphere ? 1.0 : 0.0;
  return d;
}

// corlab2026p (particle pairs, corlab2026p.hpp): its inputs and its fitted coefficients; the
// kernel is corlab2026_restitution.
void bind_corlab2026p(py::module_& m) {
  m.def(
      "corlab2026p_inputs",
      [](const MaterialArg& sphere, const MaterialArg& other, double v, double radius_ratio) {
        restitution::require_velocity(v);
        return inputs_dict(restitution::corlab2026_inputs(
            restitution::corlab2026p_pair(to_material(sphere, "sphere"),
                                          to_material(other, "other"), radius_ratio),
            v));
      },
      py::arg("sphere"), py::arg("other"), py::arg("v"), py::arg("radius_ratio") = 0.0,
      "The dimensionless inputs of corlab's pair model (corlab2026p) for a sphere hitting "
      "`other` at v [m/s]: a flat for radius_ratio = R1/R2 = 0, else a free sphere at rest (rho* "
      "of the pair, the damage number on the density of the body that yields first). Same keys "
      "as corlab2026_inputs.");
  m.def(
      "corlab2026p_fitted", [] { return coefficients_dict(restitution::corlab2026p_fitted()); },
      "The coefficients of corlab's pair model, fitted to the flat and pair datasets "
      "(data/fe_restitution_pairs/model_fit.json).");
}

// corlab's model: its inputs, its kernel over arrays and its shipped coefficients.
void bind_corlab2026(py::module_& m) {
  m.def(
      "corlab2026_inputs",
      [](const MaterialArg& sphere, const MaterialArg& substrate, double v) {
        restitution::require_velocity(v);
        return inputs_dict(restitution::corlab2026_inputs(to_material(sphere, "sphere"),
                                                          to_material(substrate, "substrate"), v));
      },
      py::arg("sphere"), py::arg("substrate"), py::arg("v"),
      "The dimensionless inputs of corlab's model (corlab2026) for one impact at v [m/s]: "
      "the real-valued inputs of corlab2026.hpp's kCorlab2026Inputs and other_is_sphere (1 or "
      "0).");
  m.def("corlab2026_restitution", &corlab2026_over, py::arg("inputs"), py::arg("coefficients"),
        "e of corlab's model for inputs (a dict of equal-length arrays, keys of "
        "corlab2026_inputs) and coefficients (a dict with the names of corlab2026_fitted()); "
        "the fit's inner loop (python/corlab/model_fit.py).");
  m.def(
      "corlab2026_fitted", [] { return coefficients_dict(restitution::corlab2026_fitted()); },
      "The shipped coefficients of corlab's model (data/fe_restitution/model_fit.json).");
}

/// corlab.oblique_rebound: the rigid-body theory of an oblique impact (oblique_impact.hpp).
void bind_oblique_rebound(py::module_& m) {
  m.def(
      "oblique_rebound",
      [](double normal_velocity, double tangential_velocity, double radius, double spin,
         double normal_restitution, double friction, double tangential_restitution,
         double gyration) {
        const restitution::ObliqueRebound r = restitution::rigid_body_rebound(
            {normal_velocity, tangential_velocity, spin, radius},
            {normal_restitution, friction, tangential_restitution, gyration});
        py::dict d;
        d["normal_velocity"] = r.normal_velocity;
        d["tangential_velocity"] = r.tangential_velocity;
        d["spin"] = r.spin;
        d["tangential_restitution"] = r.tangential_restitution;
        d["rebound_angle"] = r.rebound_angle;
        d["slides"] = r.slides;
        return d;
      },
      py::arg("normal_velocity"), py::arg("tangential_velocity"), py::arg("radius"),
      py::arg("spin") = 0.0, py::arg("normal_restitution") = 1.0, py::arg("friction") = 0.0,
      py::arg("tangential_restitution") = 0.0, py::arg("gyration") = 0.4,
      "Rigid-body rebound of a sphere from a fixed flat with Coulomb friction "
      "(corlab/restitution/oblique_impact.hpp): velocities [m/s] (normal > 0 towards the flat), "
      "radius [m], spin [rad/s] (positive in the rolling sense), e_n, mu, the sticking contact "
      "point's tangential restitution beta and I/(m R^2). Returns a dict: normal_velocity, "
      "tangential_velocity, spin, tangential_restitution (e_t), rebound_angle [deg from the "
      "normal], slides. Bad input raises ValueError.");
}

bool is_fe_model(const std::string& model) { return model == "fe" || model == "auto"; }

// `corlab predict --model fe|auto` for Python: the points, the GIL released while the solver runs;
// a cache that cannot be written is one UserWarning.
std::vector<study::FePoint> fe_points(const std::string& model,
                                      const MaterialArg& sphere,
                                      const MaterialArg& substrate,
                                      std::span<const double> velocities,
                                      double radius_ratio,
                                      const std::string& shape,
                                      int jobs,
                                      bool cache,
                                      double tolerance = 0.0) {
  if (!is_fe_model(model)) throw_invalid("model", model, "fe or auto");
  const study::FePair pair{.sphere = to_material(sphere, "sphere"),
                           .substrate = to_material(substrate, "substrate"),
                           .shape = study::resolve_fe_shape(shape, radius_ratio),
                           .radius_ratio = radius_ratio};
  if (tolerance != 0.0 && model != "fe") {
    throw_invalid("tolerance", tolerance, "0 (unset) with model 'auto'");
  }
  if (velocities.empty()) throw_invalid("v", "[]", "at least one speed [m/s]");
  for (const double v : velocities) restitution::require_velocity(v);
  std::vector<std::string> warnings;
  std::optional<study::ResultCache> store;
  if (cache) {
    store.emplace(study::default_cache_directory(), study::cache_build_id(),
                  [&warnings](const std::string& w) { warnings.push_back(w); });
  }
  const study::FeCurveOptions options{.jobs = jobs, .cache = store ? &*store : nullptr};
  const std::vector<double> speeds(velocities.begin(), velocities.end());
  std::vector<study::FePoint> points;
  {
    py::gil_scoped_release release;
    points = model == "auto"    ? dataset::auto_curve(pair, speeds, options)
             : tolerance != 0.0 ? study::fe_curve_refined(pair, speeds, tolerance, options)
                                : study::fe_curve(pair, speeds, options);
  }
  for (const auto& w : warnings) {
    if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) != 0) throw py::error_already_set();
  }
  return points;
}

py::dict curve_dict(const std::vector<study::FePoint>& points) {
  py::array_t<double> v(static_cast<py::ssize_t>(points.size()));
  py::array_t<double> e(v.size());
  py::array_t<double> e_error(v.size());
  py::array_t<bool> cached(v.size());
  py::list status;
  py::list answered_by;
  py::list detail;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto j = static_cast<py::ssize_t>(i);
    v.mutable_at(j) = points[i].velocity;
    e.mutable_at(j) = points[i].e;
    e_error.mutable_at(j) = points[i].e_error;
    cached.mutable_at(j) = points[i].cached;
    status.append(points[i].status);
    answered_by.append(points[i].answered_by);
    detail.append(points[i].detail);
  }
  py::dict d;
  d["velocity"] = v;
  d["e"] = e;
  d["e_error"] = e_error;
  d["status"] = status;
  d["answered_by"] = answered_by;
  d["detail"] = detail;
  d["cached"] = cached;
  return d;
}

using Speeds = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::span<const double> speeds_of(const Speeds& v) {
  return {v.data(), static_cast<std::size_t>(v.size())};
}

void bind_predict_curve(py::module_& m) {
  m.def(
      "predict_curve",
      [](const std::string& model, const MaterialArg& sphere, const MaterialArg& substrate,
         const Speeds& v, double radius_ratio, const std::string& shape, int jobs, bool cache,
         double tolerance) {
        return curve_dict(fe_points(model, sphere, substrate, speeds_of(v), radius_ratio, shape,
                                    jobs, cache, tolerance));
      },
      py::arg("model"), py::arg("sphere"), py::arg("substrate"), py::arg("v"),
      py::arg("radius_ratio") = 0.0, py::arg("shape") = "", py::arg("jobs") = 0,
      py::arg("cache") = true, py::arg("tolerance") = 0.0,
      "e(v) with its uncertainty, as `corlab predict --model fe|auto`: model 'fe' (the FE "
      "solver with its discretisation error bar at each speed, from the result cache when it was "
      "computed before) or 'auto' (corlab2026p with its 95 % prediction interval where it is "
      "accurate, else the FE). v [m/s]: a float or an array; shape 'flat', 'sphere' (R1/R2 = "
      "radius_ratio) or 'rigid' ('' : sphere for radius_ratio > 0, else flat); jobs: speeds run "
      "at once (0: one per core); cache=False computes all and stores nothing; tolerance > 0 "
      "(model 'fe'): the FE at fewer speeds, refined until the interpolation between them is "
      "within it, the others interpolated (answered_by 'fe-interpolated'). Returns a dict: "
      "velocity, e, e_error (arrays; nan where there is none), cached (bool array), status, "
      "answered_by, detail (lists: the run's status, 'model' for corlab2026p, and why a speed "
      "has no e or no error bar). Bad input raises ValueError.");
  m.attr("CORLAB2026P_ACCURATE_INTERVAL_95") = dataset::kCorlab2026pAccurateInterval95;
  m.attr("CORLAB2026P_ACCURATE_VELOCITY_RATIO") = dataset::kCorlab2026pAccurateVelocityRatio;
}

}  // namespace

void bind_models(py::module_& m) {
  bind_predict_curve(m);
  bind_corlab2026(m);
  bind_corlab2026p(m);
  m.def(
      "models",
      [] {
        py::list out;
        for (const auto& info : restitution::model_catalog()) out.append(info_dict(info));
        return out;
      },
      "List of dicts (name, title, citation, equation, validity, status, status_note, "
      "clamped_by_default, calibrated: the (k1, k2) calibration box {k1_min, k1_max, k2_min, "
      "k2_max} or None) of every analytic CoR model. status is 'verified-paper', "
      "'verified-second-source', 'verified-dataset' (corlab's own model, scored on held-out FE "
      "runs) or 'unverified'.");
  m.def("model_names", &restitution::model_names, "Names of the analytic CoR models.");
  m.def(
      "predict",
      [](const std::string& model, const MaterialArg& sphere, const MaterialArg& substrate,
         double v, std::optional<bool> clamp, double radius, double radius_ratio) {
        if (is_fe_model(model)) {
          return fe_points(model, sphere, substrate, {&v, 1}, radius_ratio, "", 0, true)[0].e;
        }
        const auto bound = bind_model(model, sphere, substrate, clamp, radius, radius_ratio);
        const double e = bound.cor(v);
        warn_if_outside(bound, sphere, substrate, std::span<const double>(&v, 1), radius_ratio);
        return e;
      },
      py::arg("model"), py::arg("sphere"), py::arg("substrate"), py::arg("v"),
      py::arg("clamp") = py::none(), py::arg("radius") = 1.0, py::arg("radius_ratio") = 0.0,
      "CoR e [-] of `model` for a sphere hitting a substrate at speed v [m/s]. sphere and "
      "substrate are Material objects or specs ('alumina_ma2023', 'E=..,nu=..,rho=..,sy=..'). "
      "radius_ratio = R1/R2 > 0: the substrate is a free second sphere at rest (0: a flat). "
      "v may be a float (returns a float) or a numpy array (returns an array of the same "
      "shape). model 'fe' or 'auto': e of predict_curve (nan where a speed has none). clamp: None "
      "= model default. Raises ValueError on bad input; warns "
      "(UserWarning) when the model is unverified.");
  m.def(
      "predict",
      [](const std::string& model, const MaterialArg& sphere, const MaterialArg& substrate,
         const py::array_t<double, py::array::c_style | py::array::forcecast>& v,
         std::optional<bool> clamp, double radius, double radius_ratio) {
        py::array_t<double> out(v.request().shape);
        if (is_fe_model(model)) {
          const auto points =
              fe_points(model, sphere, substrate, speeds_of(v), radius_ratio, "", 0, true);
          for (std::size_t i = 0; i < points.size(); ++i) out.mutable_data()[i] = points[i].e;
          return out;
        }
        const auto bound = bind_model(model, sphere, substrate, clamp, radius, radius_ratio);
        const std::span<const double> in(v.data(), static_cast<std::size_t>(v.size()));
        const std::span<double> res(out.mutable_data(), static_cast<std::size_t>(out.size()));
        {
          py::gil_scoped_release release;
          bound.cor(in, res);
        }
        warn_if_outside(bound, sphere, substrate, in, radius_ratio);
        return out;
      },
      py::arg("model"), py::arg("sphere"), py::arg("substrate"), py::arg("v"),
      py::arg("clamp") = py::none(), py::arg("radius") = 1.0, py::arg("radius_ratio") = 0.0);
  m.def(
      "yield_velocity",
      [](const std::string& model, const MaterialArg& sphere, const MaterialArg& substrate) {
        return bind_model(model, sphere, substrate, std::nullopt, 1.0).yield_velocity();
      },
      py::arg("model"), py::arg("sphere"), py::arg("substrate"),
      "The model's yield velocity [m/s] (e = 1 below it); warns for an unverified model.");
  bind_oblique_rebound(m);
}

}  // namespace corlab::python
