// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file linear_regression.hpp
/// Ordinary linear least squares y = X b + noise, solved through the singular value decomposition
/// of the column-equilibrated design matrix (never the normal equations), with the classical
/// inference of the Gauss-Markov model: standard errors, Student t confidence intervals and
/// goodness of fit (Draper & Smith 1998, Applied Regression Analysis, ch. 5; verified against the
/// NIST StRD linear problem Norris).

#include <Eigen/Dense>
#include <limits>
#include <string>
#include <vector>

namespace corlab::study {

/// Options of fit_linear().
struct LinearFitOptions {
  double confidence = 0.95;        ///< two-sided confidence level of the intervals, in (0, 1) [-]
  std::vector<std::string> names;  ///< coefficient names (empty = b0, b1, ...)
  /// Singular values below rcond x the largest count as zero; a design matrix of lower rank than
  /// its column count is rejected (InputError), since its coefficients are not identifiable.
  double rcond = 1e-13;
};

/// Goodness of fit of fitted values against observations. NaN (null in JSON, "-" in text) for a
/// form that was not fitted (too few cases or groups): a 0 there read as a perfect fit.
struct GoodnessOfFit {
  static constexpr double kNotFitted = std::numeric_limits<double>::quiet_NaN();
  double residual_sum_squares = kNotFitted;  ///< SSE = sum (y - y_hat)^2
  double residual_std_error = kNotFitted;    ///< s = sqrt(SSE / dof)
  double r_squared = kNotFitted;  ///< 1 - SSE / sum (y - mean y)^2 (centred; with an intercept)
  /// Over y != 0 (relative_error_stats; 0 when there is none):
  double max_relative_error = kNotFitted;  ///< max |y_hat - y| / |y| [-]
  double rms_relative_error = kNotFitted;  ///< sqrt(mean ((y_hat - y) / y)^2) [-]
};

/// Result of fit_linear(): coefficients and their inference.
struct LinearFit {
  std::vector<std::string> names;   ///< coefficient names
  Eigen::VectorXd coefficients;     ///< b
  Eigen::VectorXd standard_errors;  ///< sqrt(diag(covariance))
  Eigen::VectorXd ci_lower;         ///< b - t * se
  Eigen::VectorXd ci_upper;         ///< b + t * se
  Eigen::MatrixXd covariance;       ///< s^2 (X^T X)^-1, computed from the SVD
  Eigen::VectorXd fitted;           ///< X b
  Eigen::VectorXd residuals;        ///< y - X b
  GoodnessOfFit goodness;
  int observations = 0;           ///< n
  int parameters = 0;             ///< p
  int dof = 0;                    ///< n - p
  double confidence = 0.95;       ///< level of the intervals [-]
  double t_quantile = 0.0;        ///< Student t quantile t_{(1+confidence)/2, dof}
  double condition_number = 0.0;  ///< of the column-equilibrated design matrix [-]
};

/// Fits y = X b. Requires n > p, finite inputs and full column rank; throws InputError otherwise.
LinearFit fit_linear(const Eigen::MatrixXd& design,
                     const Eigen::VectorXd& response,
                     const LinearFitOptions& options = {});

/// Quantile of Student's t distribution: the t with P(T <= t) = probability, for dof > 0 degrees
/// of freedom (GSL gsl_cdf_tdist_Pinv). Throws InputError for probability outside (0, 1).
double student_t_quantile(double probability, double dof);

/// Goodness of fit of `fitted` against `observed`, with `parameters` fitted parameters.
GoodnessOfFit goodness_of_fit(const Eigen::VectorXd& observed,
                              const Eigen::VectorXd& fitted,
                              int parameters);

}  // namespace corlab::study
