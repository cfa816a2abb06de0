// Results tables -> samples, and fit results -> JSON.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/paper/fit_io.hpp"

#include <fmt/format.h>

#include <cmath>
#include <set>

#include "corlab/core/error.hpp"

namespace corlab::study {

std::string group_label(double sphere_rho, double E_star, double sigma_y) {
  return fmt::format("rho{:g}_E{:.4g}GPa_sy{:g}MPa", sphere_rho, E_star / 1e9, sigma_y / 1e6);
}

std::string row_name(const ResultsTable& table, std::size_t row) {
  return table.has_column("case_id") ? table.cell(row, "case_id") : fmt::format("row {}", row + 1);
}

std::string row_exclusion(const ResultsTable& table, std::size_t row, bool include_suspect) {
  if (table.has_column("status") && table.cell(row, "status") != "ok")
    return fmt::format("status = {}", table.cell(row, "status"));
  if (!include_suspect && table.has_column("suspect") && !table.cell(row, "suspect").empty())
    return fmt::format("suspect ({})", table.cell(row, "suspect"));
  return {};
}

std::vector<RestitutionSample> restitution_samples(const ResultsTable& table,
                                                   std::vector<ExcludedRow>* excluded,
                                                   bool include_suspect) {
  std::vector<RestitutionSample> out;
  if (table.size() == 0) return out;
  const auto e = table.numbers("e");
  const auto v = table.numbers("velocity");
  const auto rho = table.numbers("sphere_rho");
  const auto es = table.numbers("E_star");
  const auto sy = table.numbers("sigma_y");
  for (std::size_t i = 0; i < table.size(); ++i) {
    std::string reason = row_exclusion(table, i, include_suspect);
    if (reason.empty() && (!std::isfinite(sy[i]) || !(sy[i] > 0))) {
      reason = std::isnan(sy[i]) ? std::string("no sigma_y: elastic substrate")
                                 : fmt::format("sigma_y = {}: elastic substrate", sy[i]);
    }
    if (reason.empty()) {
      out.push_back({group_label(rho[i], es[i], sy[i]), v[i], e[i], rho[i], es[i], sy[i],
                     row_name(table, i)});
    } else if (excluded != nullptr) {
      excluded->push_back({row_name(table, i), std::move(reason)});
    }
  }
  return out;
}

nlohmann::json to_json(const std::vector<ExcludedRow>& rows) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& r : rows) out.push_back({{"case_id", r.case_id}, {"reason", r.reason}});
  return out;
}

std::vector<ExcludedRow> form_exclusions(const ResultsTable& table,
                                         const std::string& response,
                                         bool include_suspect) {
  std::vector<ExcludedRow> out;
  const auto y = table.is_numeric(response) ? table.numbers(response) : std::vector<double>{};
  for (std::size_t i = 0; i < table.size(); ++i) {
    std::string reason = row_exclusion(table, i, include_suspect);
    if (!reason.empty()) {
      out.push_back({row_name(table, i), std::move(reason)});
    } else if (!y.empty() && !std::isfinite(y[i])) {
      out.push_back({row_name(table, i), fmt::format("{} = {}", response, y[i])});
    }
  }
  return out;
}

ResultsTable usable_rows(const ResultsTable& table, bool include_suspect) {
  std::vector<std::vector<std::string>> rows;
  for (std::size_t i = 0; i < table.size(); ++i) {
    if (!row_exclusion(table, i, include_suspect).empty()) continue;
    std::vector<std::string> row;
    row.reserve(table.columns().size());
    for (const auto& name : table.columns()) row.push_back(table.cell(i, name));
    rows.push_back(std::move(row));
  }
  return {table.columns(), std::move(rows)};
}

DataColumns numeric_columns(const ResultsTable& table) {
  DataColumns out;
  for (const auto& name : table.columns()) {
    if (name == "case_id" || name == "status" || name == "error") continue;
    if (table.is_numeric(name)) out[name] = table.numbers(name);
  }
  return out;
}

nlohmann::json to_json(const GoodnessOfFit& g) {
  return {{"residual_sum_squares", g.residual_sum_squares},
          {"residual_std_error", g.residual_std_error},
          {"r_squared", g.r_squared},
          {"max_relative_error", g.max_relative_error},
          {"rms_relative_error", g.rms_relative_error}};
}

nlohmann::json to_json(const Coefficient& c) {
  return {{"name", c.name},         {"value", c.value},       {"standard_error", c.standard_error},
          {"ci_lower", c.ci_lower}, {"ci_upper", c.ci_upper}, {"paper", c.paper},
          {"unit", c.unit}};
}

nlohmann::json to_json(const LinearFit& fit) {
  nlohmann::json coefs = nlohmann::json::array();
  for (std::size_t j = 0; j < fit.names.size(); ++j) {
    const auto k = static_cast<Eigen::Index>(j);
    coefs.push_back({{"name", fit.names[j]},
                     {"value", fit.coefficients[k]},
                     {"standard_error", fit.standard_errors[k]},
                     {"ci_lower", fit.ci_lower[k]},
                     {"ci_upper", fit.ci_upper[k]}});
  }
  std::vector<std::vector<double>> cov;
  for (Eigen::Index i = 0; i < fit.covariance.rows(); ++i) {
    std::vector<double> row;
    for (Eigen::Index k = 0; k < fit.covariance.cols(); ++k) row.push_back(fit.covariance(i, k));
    cov.push_back(row);
  }
  return {{"coefficients", coefs},
          {"covariance", cov},
          {"goodness", to_json(fit.goodness)},
          {"observations", fit.observations},
          {"parameters", fit.parameters},
          {"dof", fit.dof},
          {"confidence", fit.confidence},
          {"t_quantile", fit.t_quantile},
          {"condition_number", fit.condition_number},
          {"fitted", std::vector<double>(fit.fitted.data(), fit.fitted.data() + fit.fitted.size())},
          {"residuals",
           std::vector<double>(fit.residuals.data(), fit.residuals.data() + fit.residuals.size())}};
}

nlohmann::json to_json(const NonlinearFit& fit) {
  nlohmann::json coefs = nlohmann::json::array();
  for (std::size_t j = 0; j < fit.names.size(); ++j) {
    coefs.push_back({{"name", fit.names[j]},
                     {"start", fit.start[j]},
                     {"value", fit.coefficients[j]},
                     {"standard_error", fit.standard_errors[j]},
                     {"ci_lower", fit.ci_lower[j]},
                     {"ci_upper", fit.ci_upper[j]}});
  }
  nlohmann::json left_out = nlohmann::json::array();
  for (const auto& r : fit.left_out) left_out.push_back({{"row", r.row}, {"reason", r.reason}});
  return {{"response", fit.response},
          {"model", fit.model},
          {"left_out", left_out},
          {"coefficients", coefs},
          {"covariance", fit.covariance},
          {"goodness", to_json(fit.goodness)},
          {"observations", fit.observations},
          {"parameters", fit.parameters},
          {"dof", fit.dof},
          {"iterations", fit.iterations},
          {"converged", fit.converged},
          {"message", fit.message},
          {"confidence", fit.confidence},
          {"t_quantile", fit.t_quantile}};
}

nlohmann::json to_json(const RestitutionLawFit& fit) {
  nlohmann::json cases = nlohmann::json::array();
  for (const auto& c : fit.cases) {
    cases.push_back({{"case", c.case_id},
                     {"sphere_rho", c.sphere_rho},
                     {"E_star", c.E_star},
                     {"sigma_y", c.sigma_y},
                     {"k2", c.k2},
                     {"a", to_json(c.a)},
                     {"points", c.points},
                     {"v_cross", c.v_cross}});
  }
  return {{"slope", to_json(fit.slope)},
          {"alpha", to_json(fit.alpha)},
          {"beta", to_json(fit.beta)},
          {"cases", cases},
          {"goodness_form_i", to_json(fit.form_i)},
          {"goodness_form_ii", to_json(fit.form_ii)},
          {"goodness_combined", to_json(fit.combined)},
          {"points_used", fit.points_used},
          {"points_excluded", fit.points_excluded},
          {"cases_excluded", fit.cases_excluded},
          {"excluded", to_json(fit.excluded)}};
}

nlohmann::json to_json(const YieldVelocityFit& fit) {
  nlohmann::json groups = nlohmann::json::array();
  for (const auto& g : fit.groups) {
    groups.push_back({{"E_star", g.E_star}, {"b", to_json(g.b)}, {"points", g.points}});
  }
  return {{"n", to_json(fit.n)},
          {"groups", groups},
          {"c", to_json(fit.c)},
          {"m", to_json(fit.m)},
          {"K", to_json(fit.combined)},
          {"K_fixed_exponents", to_json(fit.combined_fixed)},
          {"n_one_step", to_json(fit.n_joint)},
          {"m_one_step", to_json(fit.m_joint)},
          {"K_two_step", fit.combined_two_step},
          {"goodness_form_iii", to_json(fit.form_iii)},
          {"goodness_form_iv", to_json(fit.form_iv)},
          {"goodness_v_y", to_json(fit.combined_v)},
          {"points", fit.points}};
}

nlohmann::json fit_paper_forms(const ResultsTable& table, const PaperFitOptions& options) {
  std::vector<ExcludedRow> excluded;
  const auto samples = restitution_samples(table, &excluded, options.include_suspect);
  const RestitutionLawFit law = fit_restitution_law(samples, options);
  excluded.insert(excluded.end(), law.excluded.begin(), law.excluded.end());
  nlohmann::json out{{"restitution_law", to_json(law)},
                     {"yield_velocity", nullptr},
                     {"rows", table.size()},
                     {"rows_excluded", excluded.size()},
                     {"excluded", to_json(excluded)},
                     {"read_notes", table.notes()}};
  std::set<double> es;
  std::set<double> sy;
  std::vector<YieldVelocitySample> yv;
  for (const auto& c : law.cases) {
    es.insert(c.E_star);
    sy.insert(c.sigma_y);
    yv.push_back({c.case_id, c.sphere_rho, c.E_star, c.sigma_y, c.v_cross});
  }
  if (es.size() >= 3 && sy.size() >= 2) {
    out["yield_velocity"] = to_json(fit_yield_velocity(yv, options));
    nlohmann::json pts = nlohmann::json::array();
    for (const auto& s : yv) {
      pts.push_back({{"case", s.case_id},
                     {"sphere_rho", s.sphere_rho},
                     {"E_star", s.E_star},
                     {"sigma_y", s.sigma_y},
                     {"v_y", s.v_y}});
    }
    out["yield_velocity"]["samples"] = pts;
  }
  return out;
}

}  // namespace corlab::study
