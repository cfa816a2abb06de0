// Linear least squares by SVD of the column-equilibrated design matrix, with inference.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fit/linear_regression.hpp"

#include <fmt/core.h>
#include <gsl/gsl_cdf.h>

#include <cmath>
#include <span>
#include <string>

#include "corlab/core/error.hpp"
#include "corlab/fit/relative_error.hpp"

namespace corlab::study {

double student_t_quantile(double probability, double dof) {
  require_open_range("probability", probability, 0.0, 1.0);
  require_positive("dof", dof);
  return gsl_cdf_tdist_Pinv(probability, dof);
}

GoodnessOfFit goodness_of_fit(const Eigen::VectorXd& observed,
                              const Eigen::VectorXd& fitted,
                              int parameters) {
  GoodnessOfFit g;
  const Eigen::Index n = observed.size();
  if (n == 0) return g;  // nothing fitted
  g.max_relative_error = 0.0;
  g.rms_relative_error = 0.0;
  const Eigen::VectorXd residuals = observed - fitted;
  g.residual_sum_squares = residuals.squaredNorm();
  const auto dof = static_cast<double>(n - parameters);
  g.residual_std_error = dof > 0 ? std::sqrt(g.residual_sum_squares / dof) : 0.0;
  const double mean = observed.mean();
  const double total = (observed.array() - mean).square().sum();
  g.r_squared = total > 0 ? 1.0 - g.residual_sum_squares / total : 1.0;
  const RelativeErrorStats rel =
      relative_error_stats(std::span(fitted.data(), static_cast<std::size_t>(fitted.size())),
                           std::span(observed.data(), static_cast<std::size_t>(n)));
  if (rel.n > 0) {
    g.max_relative_error = std::abs(rel.worst);
    g.rms_relative_error = rel.rms;
  }
  return g;
}

LinearFit fit_linear(const Eigen::MatrixXd& design,
                     const Eigen::VectorXd& response,
                     const LinearFitOptions& options) {
  const Eigen::Index n = design.rows();
  const Eigen::Index p = design.cols();
  if (response.size() != n) {
    throw_invalid("response size", static_cast<double>(response.size()),
                  "equal to the number of design rows (" + std::to_string(n) + ")");
  }
  if (p < 1) throw_invalid("parameters", static_cast<double>(p), ">= 1");
  if (n <= p) {
    throw_invalid("observations", static_cast<double>(n),
                  "> the number of parameters (" + std::to_string(p) + ")");
  }
  if (!design.allFinite()) throw_invalid("design matrix", "non-finite entry", "finite");
  if (!response.allFinite()) throw_invalid("response", "non-finite entry", "finite");
  require_open_range("confidence", options.confidence, 0.0, 1.0);
  if (!options.names.empty() && static_cast<Eigen::Index>(options.names.size()) != p) {
    throw_invalid("names", static_cast<double>(options.names.size()),
                  "one per column (" + std::to_string(p) + ")");
  }

  // equilibrate the columns (unit 2-norm): the SVD of X D is better conditioned than that of X
  Eigen::VectorXd scale(p);
  for (Eigen::Index j = 0; j < p; ++j) {
    const double norm = design.col(j).norm();
    if (norm == 0.0) {
      throw_invalid("design column " + std::to_string(j), 0.0, "not identically zero");
    }
    scale[j] = 1.0 / norm;
  }
  const Eigen::MatrixXd scaled = design * scale.asDiagonal();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(scaled, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& sv = svd.singularValues();
  const double smax = sv[0];
  const double smin = sv[p - 1];
  if (!(smin > options.rcond * smax)) {
    throw_invalid("design matrix", "rank deficient (collinear columns)",
                  "of full column rank (condition number < 1/rcond)");
  }

  LinearFit fit;
  fit.observations = static_cast<int>(n);
  fit.parameters = static_cast<int>(p);
  fit.dof = static_cast<int>(n - p);
  fit.confidence = options.confidence;
  fit.condition_number = smax / smin;
  for (Eigen::Index j = 0; j < p; ++j) {
    fit.names.push_back(options.names.empty() ? fmt::format("b{}", j)
                                              : options.names[static_cast<std::size_t>(j)]);
  }
  // b = D V S^-1 U^T y
  const Eigen::VectorXd uty = svd.matrixU().transpose() * response;
  const Eigen::VectorXd z = uty.cwiseQuotient(sv);
  fit.coefficients = scale.asDiagonal() * (svd.matrixV() * z);
  fit.fitted = design * fit.coefficients;
  fit.residuals = response - fit.fitted;
  fit.goodness = goodness_of_fit(response, fit.fitted, fit.parameters);

  // (X^T X)^-1 = D V S^-2 V^T D
  const Eigen::MatrixXd vs = svd.matrixV() * sv.cwiseInverse().asDiagonal();
  const Eigen::MatrixXd unscaled_cov =
      scale.asDiagonal() * (vs * vs.transpose()) * scale.asDiagonal();
  const double s2 = fit.goodness.residual_sum_squares / static_cast<double>(fit.dof);
  fit.covariance = s2 * unscaled_cov;
  fit.standard_errors = fit.covariance.diagonal().cwiseSqrt();
  fit.t_quantile = student_t_quantile(0.5 * (1.0 + options.confidence), fit.dof);
  fit.ci_lower = fit.coefficients - fit.t_quantile * fit.standard_errors;
  fit.ci_upper = fit.coefficients + fit.t_quantile * fit.standard_errors;
  return fit;
}

}  // namespace corlab::study
