// The model forms of Ma et al. (2023), eqs. 9, 11, 15, 17, 18, fitted with inference.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/paper/fit_paper.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "corlab/core/error.hpp"

namespace corlab::study {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Coefficient coefficient(
    const LinearFit& fit, Eigen::Index j, std::string name, double paper, std::string unit) {
  Coefficient c;
  c.name = std::move(name);
  c.value = fit.coefficients[j];
  c.standard_error = fit.standard_errors[j];
  c.ci_lower = fit.ci_lower[j];
  c.ci_upper = fit.ci_upper[j];
  c.paper = paper;
  c.unit = std::move(unit);
  return c;
}

/// exp of a log-space coefficient: value exp(x), interval exp(x -+ t se), se by the delta method.
Coefficient exp_coefficient(
    const LinearFit& fit, Eigen::Index j, std::string name, double paper, std::string unit) {
  Coefficient c = coefficient(fit, j, std::move(name), paper, std::move(unit));
  c.value = std::exp(fit.coefficients[j]);
  c.standard_error = c.value * fit.standard_errors[j];
  c.ci_lower = std::exp(fit.ci_lower[j]);
  c.ci_upper = std::exp(fit.ci_upper[j]);
  return c;
}

Coefficient nan_coefficient(std::string name, double paper, std::string unit) {
  return Coefficient{std::move(name), kNaN, kNaN, kNaN, kNaN, paper, std::move(unit)};
}

Eigen::VectorXd to_vector(const std::vector<double>& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

}  // namespace

double crossing_yield_velocity(
    double alpha, double beta, double slope, double sphere_rho, double E_star, double sigma_y) {
  const double ln_k1 = (1.0 - alpha - beta * std::log(sigma_y / E_star)) / slope;
  return std::sqrt(E_star / (sphere_rho * std::exp(ln_k1)));
}

double log_law_restitution(double alpha,
                           double beta,
                           double slope,
                           double sphere_rho,
                           double E_star,
                           double sigma_y,
                           double velocity) {
  const double v_y = crossing_yield_velocity(alpha, beta, slope, sphere_rho, E_star, sigma_y);
  if (velocity < v_y) return 1.0;
  const double e = alpha + beta * std::log(sigma_y / E_star) +
                   slope * std::log(E_star / (sphere_rho * velocity * velocity));
  return std::clamp(e, 0.0, 1.0);
}

double power_law_yield_velocity(
    double K, double n, double m, double sphere_rho, double E_star, double sigma_y) {
  return std::sqrt(K * std::pow(sigma_y, n) * std::pow(E_star, m) / sphere_rho);
}

namespace {

/// Why a sample cannot be a point of form (i), or "" if it can.
std::string exclusion_reason(const RestitutionSample& s, double plastic_tolerance) {
  if (!std::isfinite(s.e)) return fmt::format("e = {}", s.e);
  if (s.e <= 0.0) return fmt::format("e = {:g}: not > 0", s.e);
  if (s.e >= 1.0 - plastic_tolerance) {
    return fmt::format("e = {:g}: elastic (>= 1 - {:g})", s.e, plastic_tolerance);
  }
  for (const auto& [name, value] :
       {std::pair{"velocity", s.velocity}, std::pair{"sphere_rho", s.sphere_rho},
        std::pair{"E_star", s.E_star}, std::pair{"sigma_y", s.sigma_y}}) {
    if (!(std::isfinite(value) && value > 0.0)) return fmt::format("{} = {}: not > 0", name, value);
  }
  return {};
}

/// Plastic points grouped by case (map: sorted by case id).
using CasePoints = std::map<std::string, std::vector<const RestitutionSample*>>;

/// The points form (i) can use, by case; the others are counted and listed in `out`.
CasePoints plastic_points_by_case(const std::vector<RestitutionSample>& samples,
                                  const PaperFitOptions& options,
                                  RestitutionLawFit& out) {
  CasePoints by_case;
  for (const auto& s : samples) {
    std::string reason = exclusion_reason(s, options.plastic_tolerance);
    if (!reason.empty()) {
      ++out.points_excluded;
      out.excluded.push_back({s.row_id.empty() ? s.case_id : s.row_id, std::move(reason)});
      continue;
    }
    by_case[s.case_id].push_back(&s);
  }
  for (auto it = by_case.begin(); it != by_case.end();) {
    if (static_cast<int>(it->second.size()) >= options.min_points_per_case) {
      ++it;
      continue;
    }
    out.points_excluded += static_cast<int>(it->second.size());
    out.cases_excluded.push_back(it->first);
    for (const auto* s : it->second) {
      out.excluded.push_back(
          {s->row_id.empty() ? s->case_id : s->row_id,
           fmt::format("its case {} has {} plastic point(s), fewer than {}", it->first,
                       it->second.size(), options.min_points_per_case)});
    }
    it = by_case.erase(it);
  }
  if (by_case.empty()) {
    throw_invalid("cases with plastic points", 0.0,
                  ">= 1 (each with >= " + std::to_string(options.min_points_per_case) + " points)");
  }
  return by_case;
}

/// Form (i): e = a_i + s ln k1 with one intercept per case; fills slope, form_i, cases.
void fit_form_i(const CasePoints& by_case, const PaperFitOptions& options, RestitutionLawFit& out) {
  const auto cases = static_cast<Eigen::Index>(by_case.size());
  Eigen::Index rows = 0;
  for (const auto& [id, pts] : by_case) rows += static_cast<Eigen::Index>(pts.size());
  out.points_used = static_cast<int>(rows);
  // design [dummies | ln k1]
  Eigen::MatrixXd X = Eigen::MatrixXd::Zero(rows, cases + 1);
  Eigen::VectorXd y(rows);
  LinearFitOptions lin;
  lin.confidence = options.confidence;
  Eigen::Index r = 0;
  Eigen::Index c = 0;
  for (const auto& [id, pts] : by_case) {
    lin.names.push_back("a[" + id + "]");
    for (const auto* s : pts) {
      X(r, c) = 1.0;
      X(r, cases) = std::log(s->k1());
      y[r] = s->e;
      ++r;
    }
    ++c;
  }
  lin.names.emplace_back("s");
  const LinearFit fit_i = fit_linear(X, y, lin);
  out.slope = coefficient(fit_i, cases, "s", PaperConstants::kSlope, "-");
  out.form_i = fit_i.goodness;
  c = 0;
  for (const auto& [id, pts] : by_case) {
    CaseIntercept ci;
    ci.case_id = id;
    ci.sphere_rho = pts.front()->sphere_rho;
    ci.E_star = pts.front()->E_star;
    ci.sigma_y = pts.front()->sigma_y;
    ci.k2 = pts.front()->k2();
    ci.a = coefficient(fit_i, c, "a[" + id + "]", kNaN, "-");
    ci.points = static_cast<int>(pts.size());
    ci.v_cross =
        std::sqrt(ci.E_star / (ci.sphere_rho * std::exp((1.0 - ci.a.value) / out.slope.value)));
    out.cases.push_back(ci);
    ++c;
  }
}

/// Form (ii): a_i = alpha + beta ln k2 over the cases (needs >= 3 cases with >= 2 distinct k2;
/// NaN otherwise), and the combined eq. 12 over the plastic points.
void fit_form_ii(const CasePoints& by_case,
                 const PaperFitOptions& options,
                 RestitutionLawFit& out) {
  std::set<double> distinct_k2;
  for (const auto& ci : out.cases) distinct_k2.insert(ci.k2);
  if (out.cases.size() < 3 || distinct_k2.size() < 2) {
    out.alpha = nan_coefficient("alpha", PaperConstants::kAlpha, "-");
    out.beta = nan_coefficient("beta", PaperConstants::kBeta, "-");
    return;
  }
  const auto cases = static_cast<Eigen::Index>(out.cases.size());
  Eigen::MatrixXd X2(cases, 2);
  Eigen::VectorXd y2(cases);
  for (Eigen::Index i = 0; i < cases; ++i) {
    X2(i, 0) = 1.0;
    X2(i, 1) = std::log(out.cases[static_cast<std::size_t>(i)].k2);
    y2[i] = out.cases[static_cast<std::size_t>(i)].a.value;
  }
  LinearFitOptions lin2;
  lin2.confidence = options.confidence;
  lin2.names = {"alpha", "beta"};
  const LinearFit fit_ii = fit_linear(X2, y2, lin2);
  out.alpha = coefficient(fit_ii, 0, "alpha", PaperConstants::kAlpha, "-");
  out.beta = coefficient(fit_ii, 1, "beta", PaperConstants::kBeta, "-");
  out.form_ii = fit_ii.goodness;
  std::vector<double> obs;
  std::vector<double> pred;
  for (const auto& [id, pts] : by_case) {
    for (const auto* s : pts) {
      obs.push_back(s->e);
      pred.push_back(out.alpha.value + out.beta.value * std::log(s->k2()) +
                     out.slope.value * std::log(s->k1()));
    }
  }
  out.combined = goodness_of_fit(to_vector(obs), to_vector(pred), 3);
}

void require_yield_samples(const std::vector<YieldVelocitySample>& samples,
                           const PaperFitOptions& options) {
  require_open_range("confidence", options.confidence, 0.0, 1.0);
  require_positive("sigma0", options.sigma0, "[Pa]");
  require_positive("E0", options.E0, "[Pa]");
  for (const auto& s : samples) {
    require_positive("v_y[" + s.case_id + "]", s.v_y, "[m/s]");
    require_positive("sphere_rho[" + s.case_id + "]", s.sphere_rho, "[kg/m^3]");
    require_positive("E_star[" + s.case_id + "]", s.E_star, "[Pa]");
    require_positive("sigma_y[" + s.case_id + "]", s.sigma_y, "[Pa]");
  }
  std::set<double> distinct_sigma;
  for (const auto& s : samples) distinct_sigma.insert(s.sigma_y);
  if (distinct_sigma.size() < 2) {
    throw_invalid("distinct sigma_y values", static_cast<double>(distinct_sigma.size()), ">= 2");
  }
}

/// The distinct E* values (relative tolerance 1e-9), sorted.
std::vector<double> e_star_groups(const std::vector<YieldVelocitySample>& samples) {
  std::vector<double> groups;
  for (const auto& s : samples) {
    const bool known = std::any_of(groups.begin(), groups.end(),
                                   [&](double g) { return std::abs(g - s.E_star) <= 1e-9 * g; });
    if (!known) groups.push_back(s.E_star);
  }
  std::sort(groups.begin(), groups.end());
  return groups;
}

Eigen::Index group_of(const std::vector<double>& groups, double E_star) {
  for (std::size_t g = 0; g < groups.size(); ++g) {
    if (std::abs(groups[g] - E_star) <= 1e-9 * groups[g]) return static_cast<Eigen::Index>(g);
  }
  return Eigen::Index{-1};
}

/// Form (iii): ln(rho v_y^2) = ln b_g + n ln sigma_bar, one b per E* group; fills n, form_iii,
/// groups and returns the fit (its first G coefficients are ln b_g).
LinearFit fit_form_iii(const std::vector<YieldVelocitySample>& samples,
                       const std::vector<double>& groups,
                       const Eigen::VectorXd& y,
                       const PaperFitOptions& options,
                       YieldVelocityFit& out) {
  const auto n = static_cast<Eigen::Index>(samples.size());
  const auto G = static_cast<Eigen::Index>(groups.size());
  Eigen::MatrixXd X = Eigen::MatrixXd::Zero(n, G + 1);
  LinearFitOptions lin;
  lin.confidence = options.confidence;
  for (Eigen::Index g = 0; g < G; ++g) lin.names.push_back("ln b[" + std::to_string(g) + "]");
  lin.names.emplace_back("n");
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto& s = samples[static_cast<std::size_t>(i)];
    X(i, group_of(groups, s.E_star)) = 1.0;
    X(i, G) = std::log(s.sigma_y / options.sigma0);
  }
  LinearFit fit_iii = fit_linear(X, y, lin);
  out.n = coefficient(fit_iii, G, "n", PaperConstants::kExponentN, "-");
  const Eigen::VectorXd obs = y.array().exp();
  const Eigen::VectorXd pred = fit_iii.fitted.array().exp();
  out.form_iii = goodness_of_fit(obs, pred, static_cast<int>(G + 1));
  for (Eigen::Index g = 0; g < G; ++g) {
    YieldGroup yg;
    yg.E_star = groups[static_cast<std::size_t>(g)];
    yg.b = exp_coefficient(fit_iii, g, "b", kNaN, "Pa");
    yg.points = static_cast<int>((X.col(g).array() > 0.5).count());
    out.groups.push_back(yg);
  }
  return fit_iii;
}

/// Form (iv): ln b_g = ln c + m ln E_bar (needs >= 3 E* groups; NaN otherwise).
void fit_form_iv(const std::vector<double>& groups,
                 const LinearFit& fit_iii,
                 const PaperFitOptions& options,
                 YieldVelocityFit& out) {
  const auto G = static_cast<Eigen::Index>(groups.size());
  if (G < 3) {
    out.c = nan_coefficient("c", PaperConstants::kC, "Pa");
    out.m = nan_coefficient("m", PaperConstants::kExponentM, "-");
    out.combined_two_step = kNaN;
    return;
  }
  Eigen::MatrixXd X4(G, 2);
  Eigen::VectorXd y4(G);
  for (Eigen::Index g = 0; g < G; ++g) {
    X4(g, 0) = 1.0;
    X4(g, 1) = std::log(groups[static_cast<std::size_t>(g)] / options.E0);
    y4[g] = fit_iii.coefficients[g];
  }
  LinearFitOptions lin4;
  lin4.confidence = options.confidence;
  lin4.names = {"ln c", "m"};
  const LinearFit fit_iv = fit_linear(X4, y4, lin4);
  out.c = exp_coefficient(fit_iv, 0, "c", PaperConstants::kC, "Pa");
  out.m = coefficient(fit_iv, 1, "m", PaperConstants::kExponentM, "-");
  out.form_iv = goodness_of_fit(y4.array().exp().matrix(), fit_iv.fitted.array().exp().matrix(), 2);
  out.combined_two_step =
      out.c.value * std::pow(options.sigma0, -out.n.value) * std::pow(options.E0, -out.m.value);
}

/// K with the paper's exponents: ln(rho v_y^2) - 4.5 ln sigma_y + 3.5 ln E* = ln K.
Coefficient fit_fixed_exponents(const std::vector<YieldVelocitySample>& samples,
                                const Eigen::VectorXd& y,
                                const PaperFitOptions& options) {
  const auto n = static_cast<Eigen::Index>(samples.size());
  const Eigen::MatrixXd ones = Eigen::MatrixXd::Ones(n, 1);
  Eigen::VectorXd y6(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto& s = samples[static_cast<std::size_t>(i)];
    y6[i] = y[i] - PaperConstants::kExponentN * std::log(s.sigma_y) -
            PaperConstants::kExponentM * std::log(s.E_star);
  }
  LinearFitOptions lin6;
  lin6.confidence = options.confidence;
  lin6.names = {"ln K"};
  return exp_coefficient(fit_linear(ones, y6, lin6), 0, "K (n = 4.5, m = -3.5 fixed)",
                         PaperConstants::kCombined, "-");
}

/// One step: ln(rho v_y^2) = ln K + n ln sigma_y + m ln E* (needs >= 2 E* groups and > 3
/// points; NaN otherwise).
void fit_one_step(const std::vector<YieldVelocitySample>& samples,
                  const Eigen::VectorXd& y,
                  std::size_t group_count,
                  const PaperFitOptions& options,
                  YieldVelocityFit& out) {
  const auto n = static_cast<Eigen::Index>(samples.size());
  if (group_count < 2 || n <= 3) {
    out.combined = nan_coefficient("K", PaperConstants::kCombined, "Pa^(1-n-m)");
    out.n_joint = nan_coefficient("n (one step)", PaperConstants::kExponentN, "-");
    out.m_joint = nan_coefficient("m (one step)", PaperConstants::kExponentM, "-");
    return;
  }
  Eigen::MatrixXd X5(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto& s = samples[static_cast<std::size_t>(i)];
    X5(i, 0) = 1.0;
    X5(i, 1) = std::log(s.sigma_y);
    X5(i, 2) = std::log(s.E_star);
  }
  LinearFitOptions lin5;
  lin5.confidence = options.confidence;
  lin5.names = {"ln K", "n", "m"};
  const LinearFit fit5 = fit_linear(X5, y, lin5);
  out.combined = exp_coefficient(fit5, 0, "K", PaperConstants::kCombined, "Pa^(1-n-m)");
  out.n_joint = coefficient(fit5, 1, "n (one step)", PaperConstants::kExponentN, "-");
  out.m_joint = coefficient(fit5, 2, "m (one step)", PaperConstants::kExponentM, "-");
  std::vector<double> obs;
  std::vector<double> pred;
  for (const auto& s : samples) {
    obs.push_back(s.v_y);
    pred.push_back(power_law_yield_velocity(out.combined.value, out.n_joint.value,
                                            out.m_joint.value, s.sphere_rho, s.E_star, s.sigma_y));
  }
  out.combined_v = goodness_of_fit(to_vector(obs), to_vector(pred), 3);
}

}  // namespace

RestitutionLawFit fit_restitution_law(const std::vector<RestitutionSample>& samples,
                                      const PaperFitOptions& options) {
  require_open_range("confidence", options.confidence, 0.0, 1.0);
  require_non_negative("plastic_tolerance", options.plastic_tolerance);
  RestitutionLawFit out;
  const CasePoints by_case = plastic_points_by_case(samples, options, out);
  fit_form_i(by_case, options, out);
  fit_form_ii(by_case, options, out);
  return out;
}

YieldVelocityFit fit_yield_velocity(const std::vector<YieldVelocitySample>& samples,
                                    const PaperFitOptions& options) {
  require_yield_samples(samples, options);
  YieldVelocityFit out;
  out.points = static_cast<int>(samples.size());
  const std::vector<double> groups = e_star_groups(samples);
  Eigen::VectorXd y(static_cast<Eigen::Index>(samples.size()));  // ln(rho v_y^2)
  for (Eigen::Index i = 0; i < y.size(); ++i) {
    const auto& s = samples[static_cast<std::size_t>(i)];
    y[i] = std::log(s.sphere_rho * s.v_y * s.v_y);
  }
  const LinearFit fit_iii = fit_form_iii(samples, groups, y, options, out);
  fit_form_iv(groups, fit_iii, options, out);
  out.combined_fixed = fit_fixed_exponents(samples, y, options);
  fit_one_step(samples, y, groups.size(), options, out);
  return out;
}

}  // namespace corlab::study
