// Nonlinear least squares of muParser forms with GSL's Levenberg-Marquardt.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fit/fit_expression.hpp"

#include <fmt/core.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <gsl/gsl_vector.h>
#include <muParser.h>

#include <Eigen/Dense>
#include <cctype>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <set>

#include "corlab/core/error.hpp"
#include "corlab/core/number.hpp"
#include "corlab/core/text.hpp"

namespace corlab::study {
namespace {

/// `text` without blanks at either end, as a string.
std::string trimmed(std::string_view text) { return std::string(trim(text)); }

bool is_identifier(const std::string& name) {
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
  for (const char c : name) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  }
  return true;
}

/// A parsed form bound to a row of data and a parameter vector.
class BoundExpression {
 public:
  BoundExpression(const std::string& expression,
                  const std::vector<std::string>& param_names,
                  const DataColumns& data,
                  std::string_view field)
      : values_(data.size() + param_names.size(), 0.0) {
    std::size_t k = 0;
    try {
      for (const auto& [name, column] : data) {
        if (is_identifier(name)) {
          parser_.DefineVar(name, &values_[k]);
          columns_.emplace_back(&column, &values_[k]);
        }
        ++k;
      }
      for (const auto& name : param_names) {
        if (data.count(name) != 0) {
          throw_invalid("parameter " + name, name, "not also a data column name");
        }
        parser_.DefineVar(name, &values_[k]);
        params_.push_back(&values_[k]);
        ++k;
      }
      parser_.SetExpr(expression);
      used_ = parser_.GetUsedVar();  // lists every name, unknown ones included
      const auto& defined = parser_.GetVar();
      for (const auto& [name, ptr] : used_) {
        if (defined.count(name) == 0) {
          throw_invalid(field, expression,
                        "a form over the columns and parameters (unknown name '" + name + "')");
        }
      }
    } catch (const mu::Parser::exception_type& err) {
      throw_invalid(field, expression,
                    "a valid form over the columns and parameters (" + err.GetMsg() + ")");
    }
  }

  bool uses(const std::string& name) const { return used_.count(name) != 0; }

  double eval(std::size_t row, const double* params) {
    for (auto& [column, slot] : columns_) *slot = (*column)[row];
    for (std::size_t j = 0; j < params_.size(); ++j) *params_[j] = params[j];
    try {
      return parser_.Eval();
    } catch (const mu::Parser::exception_type&) {
      return std::numeric_limits<double>::quiet_NaN();
    }
  }

 private:
  mu::Parser parser_;
  std::vector<double> values_;
  std::vector<std::pair<const std::vector<double>*, double*>> columns_;
  std::vector<double*> params_;
  mu::varmap_type used_;
};

struct Problem {
  BoundExpression* model = nullptr;
  std::vector<std::size_t> rows;
  std::vector<double> y;
  std::size_t p = 0;
  std::vector<double> start;  ///< start values of the parameters
};

// residual r_i = model(row_i, b) - y_i; a non-finite model value becomes a huge residual, so the
// trust-region step that produced it is rejected
int residual_cb(const gsl_vector* x, void* ctx, gsl_vector* f) {
  auto* prob = static_cast<Problem*>(ctx);
  std::vector<double> b(prob->p);
  for (std::size_t j = 0; j < prob->p; ++j) b[j] = gsl_vector_get(x, j);
  for (std::size_t i = 0; i < prob->rows.size(); ++i) {
    const double m = prob->model->eval(prob->rows[i], b.data());
    gsl_vector_set(f, i, std::isfinite(m) ? m - prob->y[i] : 1e150);
  }
  return GSL_SUCCESS;
}

Eigen::MatrixXd central_jacobian(Problem& prob, const std::vector<double>& b) {
  const std::size_t n = prob.rows.size();
  Eigen::MatrixXd jac(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(prob.p));
  const double step = std::cbrt(std::numeric_limits<double>::epsilon());
  std::vector<double> bp = b;
  std::vector<double> bm = b;
  for (std::size_t j = 0; j < prob.p; ++j) {
    const double h = step * std::max(std::abs(b[j]), 1e-8);
    bp[j] = b[j] + h;
    bm[j] = b[j] - h;
    const double width = bp[j] - bm[j];
    for (std::size_t i = 0; i < n; ++i) {
      const double fp = prob.model->eval(prob.rows[i], bp.data());
      const double fm = prob.model->eval(prob.rows[i], bm.data());
      jac(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = (fp - fm) / width;
    }
    bp[j] = b[j];
    bm[j] = b[j];
  }
  return jac;
}

int jacobian_cb(const gsl_vector* x, void* ctx, gsl_matrix* jac) {
  auto* prob = static_cast<Problem*>(ctx);
  std::vector<double> b(prob->p);
  for (std::size_t j = 0; j < prob->p; ++j) b[j] = gsl_vector_get(x, j);
  const Eigen::MatrixXd j_mat = central_jacobian(*prob, b);
  for (Eigen::Index i = 0; i < j_mat.rows(); ++i) {
    for (Eigen::Index k = 0; k < j_mat.cols(); ++k) {
      const double v = j_mat(i, k);
      gsl_matrix_set(jac, static_cast<std::size_t>(i), static_cast<std::size_t>(k),
                     std::isfinite(v) ? v : 0.0);
    }
  }
  return GSL_SUCCESS;
}

struct GslWorkspaceDeleter {
  void operator()(gsl_multifit_nlinear_workspace* w) const { gsl_multifit_nlinear_free(w); }
};
struct GslVectorDeleter {
  void operator()(gsl_vector* v) const { gsl_vector_free(v); }
};

}  // namespace

std::pair<std::string, std::string> split_formula(const std::string& formula) {
  auto pos = formula.find('~');
  if (pos == std::string::npos) {
    // "y = f": a single '=' that is not part of ==, <=, >=, !=
    for (std::size_t i = 0; i < formula.size(); ++i) {
      if (formula[i] != '=') continue;
      const char before = i > 0 ? formula[i - 1] : ' ';
      const char after = i + 1 < formula.size() ? formula[i + 1] : ' ';
      if (before != '<' && before != '>' && before != '!' && before != '=' && after != '=') {
        pos = i;
        break;
      }
    }
  }
  if (pos == std::string::npos) {
    throw_invalid("form", formula, "of the form 'response ~ model'");
  }
  std::string response = trimmed(formula.substr(0, pos));
  std::string model = trimmed(formula.substr(pos + 1));
  if (!is_identifier(response)) {
    throw_invalid("form response", response, "a column name");
  }
  if (model.empty()) throw_invalid("form", formula, "a non-empty model right of '~'");
  return {response, model};
}

std::vector<ParameterStart> parse_parameter_starts(const std::vector<std::string>& items) {
  std::vector<ParameterStart> out;
  for (const auto& item : items) {
    std::size_t begin = 0;
    while (begin <= item.size()) {
      const auto end = std::min(item.find(',', begin), item.size());
      const std::string token = trimmed(item.substr(begin, end - begin));
      begin = end + 1;
      if (token.empty()) continue;
      const auto eq = token.find('=');
      if (eq == std::string::npos) throw_invalid("parameter", token, "of the form name=start");
      ParameterStart p{trimmed(token.substr(0, eq)), 0.0};
      if (!is_identifier(p.name)) throw_invalid("parameter name", p.name, "an identifier");
      const std::string value = trimmed(token.substr(eq + 1));
      const std::optional<double> start = parse_double(value);
      if (!start || !std::isfinite(*start)) {
        throw_invalid("parameter " + p.name, value, "a finite number (start value)");
      }
      p.start = *start;
      for (const auto& q : out) {
        if (q.name == p.name) throw_invalid("parameter", p.name, "given once");
      }
      out.push_back(p);
    }
  }
  return out;
}

namespace {

void require_options(const std::vector<ParameterStart>& params,
                     const NonlinearFitOptions& options) {
  require_open_range("confidence", options.confidence, 0.0, 1.0);
  if (options.max_iterations < 1) {
    throw_invalid("max_iterations", static_cast<double>(options.max_iterations), ">= 1");
  }
  if (params.empty()) throw_invalid("parameters", 0.0, "at least one");
}

/// Every column as long as the response (`rows`); every start value finite.
void require_data(const std::vector<ParameterStart>& params,
                  const DataColumns& data,
                  std::size_t rows) {
  for (const auto& [name, column] : data) {
    if (column.size() != rows) {
      throw_invalid("column " + name, static_cast<double>(column.size()),
                    "of the same length as the others (" + std::to_string(rows) + ")");
    }
  }
  for (const auto& p : params) {
    if (!std::isfinite(p.start)) throw_invalid("parameter " + p.name, p.start, "finite");
  }
}

/// The rows the fit uses (finite response, passing the --where filter) into prob.rows / prob.y;
/// the others, with the reason, into `left_out`.
void select_rows(const std::string& response_name,
                 const std::vector<double>& response,
                 const DataColumns& data,
                 const std::string& where,
                 Problem& prob,
                 std::vector<LeftOutRow>& left_out) {
  std::unique_ptr<BoundExpression> filter;
  if (!trimmed(where).empty()) {
    filter = std::make_unique<BoundExpression>(where, std::vector<std::string>{}, data, "where");
  }
  for (std::size_t i = 0; i < response.size(); ++i) {
    const double y = response[i];
    if (!std::isfinite(y)) {
      left_out.push_back({i, fmt::format("{} = {}", response_name, y)});
      continue;
    }
    if (filter && filter->eval(i, nullptr) == 0.0) {
      left_out.push_back({i, fmt::format("where: {} is false", trimmed(where))});
      continue;
    }
    prob.rows.push_back(i);
    prob.y.push_back(y);
  }
  const std::size_t n = prob.rows.size();
  if (n <= prob.p) {
    throw_invalid("rows", static_cast<double>(n),
                  "> the number of parameters (" + std::to_string(prob.p) + ") after filtering");
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(prob.model->eval(prob.rows[i], prob.start.data()))) {
      throw_invalid("start values", fmt::format("row {}", prob.rows[i]),
                    "giving a finite model value on every row");
    }
  }
}

/// Levenberg-Marquardt (GSL) from prob.start: fills coefficients, iterations, converged, message.
void levenberg_marquardt(Problem& prob, const NonlinearFitOptions& options, NonlinearFit& fit) {
  const std::size_t n = prob.rows.size();
  gsl_set_error_handler_off();
  gsl_multifit_nlinear_fdf fdf;
  fdf.f = residual_cb;
  fdf.df = jacobian_cb;
  fdf.fvv = nullptr;
  fdf.n = n;
  fdf.p = prob.p;
  fdf.params = &prob;
  gsl_multifit_nlinear_parameters fit_params = gsl_multifit_nlinear_default_parameters();
  fit_params.trs = gsl_multifit_nlinear_trs_lm;
  std::unique_ptr<gsl_multifit_nlinear_workspace, GslWorkspaceDeleter> work(
      gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &fit_params, n, prob.p));
  std::unique_ptr<gsl_vector, GslVectorDeleter> x0(gsl_vector_alloc(prob.p));
  for (std::size_t j = 0; j < prob.p; ++j) gsl_vector_set(x0.get(), j, prob.start[j]);
  gsl_multifit_nlinear_init(x0.get(), &fdf, work.get());
  int info = 0;
  const int status =
      gsl_multifit_nlinear_driver(static_cast<std::size_t>(options.max_iterations), options.xtol,
                                  options.gtol, options.ftol, nullptr, nullptr, &info, work.get());
  fit.iterations = static_cast<int>(gsl_multifit_nlinear_niter(work.get()));
  fit.converged = status == GSL_SUCCESS;
  fit.message = fit.converged ? (info == 1   ? "converged: small step"
                                 : info == 2 ? "converged: small gradient"
                                             : "converged")
                              : std::string("not converged: ") + gsl_strerror(status);
  const gsl_vector* xs = gsl_multifit_nlinear_position(work.get());
  fit.coefficients.reserve(prob.p);
  for (std::size_t j = 0; j < prob.p; ++j) fit.coefficients.push_back(gsl_vector_get(xs, j));
}

/// Goodness of fit, covariance s^2 (J^T J)^-1 (from the SVD of the column-equilibrated
/// Jacobian), standard errors and confidence intervals.
void add_inference(Problem& prob, const NonlinearFitOptions& options, NonlinearFit& fit) {
  const auto n = static_cast<Eigen::Index>(prob.rows.size());
  Eigen::VectorXd observed(n);
  Eigen::VectorXd fitted(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto row = static_cast<std::size_t>(i);
    observed[i] = prob.y[row];
    fitted[i] = prob.model->eval(prob.rows[row], fit.coefficients.data());
  }
  fit.goodness = goodness_of_fit(observed, fitted, fit.parameters);
  const Eigen::MatrixXd jac = central_jacobian(prob, fit.coefficients);
  const auto p = static_cast<Eigen::Index>(prob.p);
  Eigen::VectorXd scale(p);
  for (Eigen::Index j = 0; j < p; ++j) {
    const double norm = jac.col(j).norm();
    scale[j] = norm > 0 ? 1.0 / norm : 1.0;
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(jac * scale.asDiagonal(), Eigen::ComputeThinV);
  const Eigen::VectorXd& sv = svd.singularValues();
  const double s2 = fit.goodness.residual_sum_squares / static_cast<double>(fit.dof);
  fit.t_quantile = student_t_quantile(0.5 * (1.0 + options.confidence), fit.dof);
  Eigen::MatrixXd cov = Eigen::MatrixXd::Constant(p, p, std::numeric_limits<double>::quiet_NaN());
  if (sv[p - 1] > 1e-13 * sv[0]) {
    const Eigen::MatrixXd vs = svd.matrixV() * sv.cwiseInverse().asDiagonal();
    cov = s2 * (scale.asDiagonal() * (vs * vs.transpose()) * scale.asDiagonal());
  } else if (fit.converged) {
    fit.message += "; Jacobian rank deficient at the optimum: no standard errors";
  }
  for (Eigen::Index j = 0; j < p; ++j) {
    const double se = std::sqrt(cov(j, j));
    fit.standard_errors.push_back(se);
    fit.ci_lower.push_back(fit.coefficients[static_cast<std::size_t>(j)] - fit.t_quantile * se);
    fit.ci_upper.push_back(fit.coefficients[static_cast<std::size_t>(j)] + fit.t_quantile * se);
    std::vector<double> row;
    row.reserve(static_cast<std::size_t>(p));
    for (Eigen::Index k = 0; k < p; ++k) row.push_back(cov(j, k));
    fit.covariance.push_back(row);
  }
}

}  // namespace

NonlinearFit fit_expression(const std::string& formula,
                            const std::vector<ParameterStart>& params,
                            const DataColumns& data,
                            const NonlinearFitOptions& options) {
  require_options(params, options);
  const auto [response, model_text] = split_formula(formula);
  const auto ycol = data.find(response);
  if (ycol == data.end()) throw_invalid("form response", response, "a data column");
  require_data(params, data, ycol->second.size());
  NonlinearFit fit;
  for (const auto& p : params) {
    fit.names.push_back(p.name);
    fit.start.push_back(p.start);
  }
  BoundExpression model(model_text, fit.names, data, "form");
  for (const auto& name : fit.names) {
    if (!model.uses(name)) throw_invalid("parameter", name, "used in the form");
  }
  Problem prob;
  prob.model = &model;
  prob.p = fit.names.size();
  prob.start = fit.start;
  select_rows(response, ycol->second, data, options.where, prob, fit.left_out);
  fit.response = response;
  fit.model = model_text;
  fit.observations = static_cast<int>(prob.rows.size());
  fit.parameters = static_cast<int>(prob.p);
  fit.dof = fit.observations - fit.parameters;
  fit.confidence = options.confidence;
  levenberg_marquardt(prob, options, fit);
  add_inference(prob, options, fit);
  return fit;
}

}  // namespace corlab::study
