// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file fit_expression.hpp
/// Nonlinear least squares for user model forms written as text, e.g.
///   "e ~ a + s*ln(k1) + b*ln(k2)"        (response ~ model)
/// over named data columns (a results table). The form is parsed with muParser (functions ln,
/// log (= ln), log10, exp, sqrt, pow via ^, sin, ...), minimised with the GSL trust-region
/// Levenberg-Marquardt solver (gsl_multifit_nlinear, geodesic-free LM with More scaling) and a
/// central-difference Jacobian. Inference is the usual linearisation at the optimum:
/// cov = s^2 (J^T J)^-1 (Bates & Watts 1988, Nonlinear Regression Analysis, ch. 2), verified
/// against the NIST StRD problem Misra1a.

#include <map>
#include <string>
#include <vector>

#include "corlab/fit/linear_regression.hpp"

namespace corlab::study {

/// Named data columns of equal length (e.g. the columns of results.csv).
using DataColumns = std::map<std::string, std::vector<double>>;

/// One parameter of a user form and its start value.
struct ParameterStart {
  std::string name;    ///< identifier used in the form
  double start = 0.0;  ///< start value of the iteration
};

/// Options of fit_expression().
struct NonlinearFitOptions {
  double confidence = 0.95;  ///< two-sided level of the confidence intervals [-]
  int max_iterations = 500;  ///< Levenberg-Marquardt iterations
  double xtol = 1e-12;       ///< relative step tolerance
  double gtol = 1e-12;       ///< scaled-gradient tolerance
  double ftol = 0.0;         ///< relative change of the cost (0 = off)
  /// Optional row filter, a muParser expression over the columns; rows where it is 0 are
  /// skipped (e.g. "e < 0.999" keeps the plastic points).
  std::string where;
};

/// A data row fit_expression() did not use, and why ("e = nan", "where: e < 0.999 is false").
struct LeftOutRow {
  std::size_t row = 0;  ///< index into the data columns (0-based)
  std::string reason;
};

/// Result of fit_expression().
struct NonlinearFit {
  std::string response;            ///< response column (left of '~')
  std::string model;               ///< model expression (right of '~')
  std::vector<std::string> names;  ///< parameter names, in the order given
  std::vector<double> start;       ///< start values
  std::vector<double> coefficients;
  std::vector<double> standard_errors;
  std::vector<double> ci_lower;
  std::vector<double> ci_upper;
  std::vector<std::vector<double>> covariance;
  GoodnessOfFit goodness;
  int observations = 0;
  int parameters = 0;
  int dof = 0;
  int iterations = 0;
  bool converged = false;
  std::string message;  ///< why the iteration stopped
  double confidence = 0.95;
  double t_quantile = 0.0;
  /// Every row not fitted: a non-finite response, or the `where` filter (never dropped silently).
  std::vector<LeftOutRow> left_out;
};

/// Splits "y ~ f(...)" (or "y = f(...)") into response and model. Throws InputError if there is
/// neither separator.
std::pair<std::string, std::string> split_formula(const std::string& formula);

/// Fits `formula` ("response ~ model") to `data` for the parameters `params`. Every name in the
/// model must be a parameter or a column; every parameter must occur in the model. Throws
/// InputError for bad input (unknown name, parse error, too few rows, non-finite model values at
/// the start).
NonlinearFit fit_expression(const std::string& formula,
                            const std::vector<ParameterStart>& params,
                            const DataColumns& data,
                            const NonlinearFitOptions& options = {});

/// Parses "a=1.0,b=0.05" (or the list {"a=1.0", "b=0.05"}) into parameter starts.
std::vector<ParameterStart> parse_parameter_starts(const std::vector<std::string>& items);

}  // namespace corlab::study
