// Bindings for the fit area: corlab.fit_linear, corlab.fit_expression, corlab.fit_paper,
// corlab.relative_errors, corlab.relative_error_stats. Results are plain dicts (the JSON forms of
// fit_io.hpp, the same as `corlab fit --json`).
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/format.h>
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <span>

#include "bindings.hpp"
#include "corlab/core/error.hpp"
#include "corlab/fit/fit_expression.hpp"
#include "corlab/fit/linear_regression.hpp"
#include "corlab/fit/relative_error.hpp"
#include "corlab/paper/fit_io.hpp"
#include "corlab/study/results_table.hpp"

namespace corlab::python {
namespace {

namespace py = pybind11;

py::object to_python(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// A row fit_expression left out for its value (not by `where`) is said at once, not only listed.
void warn_left_out(const study::NonlinearFit& fit) {
  std::size_t not_finite = 0;
  std::string first;
  for (const auto& r : fit.left_out) {
    if (r.reason.starts_with("where:")) continue;
    if (not_finite++ == 0) first = fmt::format("row {}: {}", r.row, r.reason);
  }
  if (not_finite == 0) return;
  py::module_::import("warnings")
      .attr("warn")(fmt::format("fit_expression left out {} row(s) with a non-finite response "
                                "(first {}); the result's 'left_out' lists them",
                                not_finite, first));
}

std::span<const double> values(const Array& a, const char* field) {
  if (a.ndim() != 1) throw_invalid(field, static_cast<double>(a.ndim()), "1 dimension");
  return {a.data(), static_cast<std::size_t>(a.size())};
}

// Model and reference values against each other: the relative errors and their statistics.
void bind_relative_error(py::module_& m) {
  m.def(
      "relative_errors",
      [](const Array& model, const Array& reference) {
        const auto r = study::relative_errors(values(model, "model values"),
                                              values(reference, "reference values"));
        return py::array_t<double>(static_cast<py::ssize_t>(r.size()), r.data());
      },
      py::arg("model"), py::arg("reference"),
      "(model - reference) / reference, element by element [-] (not finite where the reference "
      "is 0 or a value is not finite); ValueError for arrays of different sizes.");
  m.def(
      "relative_error_stats",
      [](const Array& model, const Array& reference) {
        const study::RelativeErrorStats s = study::relative_error_stats(
            values(model, "model values"), values(reference, "reference values"));
        py::dict d;
        d["n"] = s.n;
        d["rms"] = s.rms;
        d["worst"] = s.worst;
        d["bias"] = s.bias;
        return d;
      },
      py::arg("model"), py::arg("reference"),
      R"doc(Statistics of the relative errors (model - reference) / reference [-] (relative_error.hpp).

Returns {"n": pairs counted, "rms": sqrt(mean r^2), "worst": the r of the largest magnitude,
signed, "bias": mean r}; pairs whose r is not finite are left out (NaN statistics when none is
left). The sums run in numpy's order: numpy's mean of the same errors is the same double.)doc");
}

}  // namespace

void bind_fit(py::module_& m) {
  bind_relative_error(m);
  m.def(
      "fit_linear",
      [](const Eigen::MatrixXd& X, const Eigen::VectorXd& y, std::vector<std::string> names,
         double confidence) {
        study::LinearFitOptions options;
        options.names = std::move(names);
        options.confidence = confidence;
        return to_python(study::to_json(study::fit_linear(X, y, options)));
      },
      py::arg("X"), py::arg("y"), py::arg("names") = std::vector<std::string>{},
      py::arg("confidence") = 0.95,
      R"doc(Linear least squares y = X b by SVD (never the normal equations).

Returns a dict: coefficients (name, value, standard_error, ci_lower, ci_upper), covariance,
goodness (residual_sum_squares, residual_std_error, r_squared, max/rms_relative_error),
observations, parameters, dof, confidence, t_quantile (Student t), condition_number, fitted,
residuals. Raises ValueError for rank-deficient X, n <= p or non-finite input.)doc");

  m.def(
      "fit_expression",
      [](const std::string& expr, const py::dict& params,
         const std::map<std::string, std::vector<double>>& data, const std::string& where,
         double confidence, int max_iterations) {
        std::vector<study::ParameterStart> starts;  // in the dict's order
        for (const auto& item : params) {
          starts.push_back({py::cast<std::string>(item.first), py::cast<double>(item.second)});
        }
        study::NonlinearFitOptions options;
        options.where = where;
        options.confidence = confidence;
        options.max_iterations = max_iterations;
        const study::NonlinearFit fit = study::fit_expression(expr, starts, data, options);
        warn_left_out(fit);
        return to_python(study::to_json(fit));
      },
      py::arg("expr"), py::arg("params"), py::arg("data"), py::arg("where") = "",
      py::arg("confidence") = 0.95, py::arg("max_iterations") = 500,
      R"doc(Nonlinear least squares (GSL Levenberg-Marquardt) of a user form.

expr: "response ~ model" over the columns of `data`, e.g. "e ~ a + s*ln(k1) + b*ln(k2)"
(muParser syntax: ln, log (= ln), log10, exp, sqrt, ^). params: {name: start value}.
data: {column: sequence of float}, all of equal length. where: optional row filter,
e.g. "e < 0.999". Returns a dict with coefficients (value, standard_error, ci_lower,
ci_upper, start), covariance, goodness, iterations, converged, message, and left_out: every
row not fitted ({row, reason}: a non-finite response, warned about, or the `where` filter).)doc");

  m.def(
      "fit_paper",
      [](const std::string& results_csv, double confidence, double plastic_tolerance,
         bool include_suspect) {
        study::PaperFitOptions options;
        options.confidence = confidence;
        options.plastic_tolerance = plastic_tolerance;
        options.include_suspect = include_suspect;
        const study::ResultsTable table = study::read_results(results_csv);
        for (const auto& note : table.notes()) {
          py::module_::import("warnings").attr("warn")(note);
        }
        return to_python(study::fit_paper_forms(table, options));
      },
      py::arg("results_csv"), py::arg("confidence") = 0.95, py::arg("plastic_tolerance") = 1e-3,
      py::arg("include_suspect") = false,
      R"doc(The model forms of Ma et al. (2023) fitted to a sweep's results.csv.

Returns {"restitution_law": forms (i) e = a_i + s ln k1 and (ii) a = alpha + beta ln k2,
 "yield_velocity": forms (iii) rho v_y^2 = b sigma_bar^n and (iv) b = c E_bar^m on the
 per-case e = 1 crossings, or None when the table has < 3 E* values or < 2 yield stresses}.
Each coefficient has value, standard_error, ci_lower, ci_upper and the paper's value.
"excluded" lists every row left out ({case_id, reason}): failed runs, and runs flagged suspect
unless include_suspect=True; what the reader repaired (a cut
last line, a repeated row) is also issued as a UserWarning.)doc");
}

}  // namespace corlab::python
