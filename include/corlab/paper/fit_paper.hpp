// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file fit_paper.hpp
/// The model forms of Ma et al. (2023), fitted by linear least squares with inference:
///  (i)   e = a_i + s ln k1          common slope s, one intercept a_i per case (Ma eq. 9),
///                                   plastic points only (e < 1 - plastic_tolerance)
///  (ii)  a = alpha + beta ln k2     over the per-case intercepts (Ma eq. 11)
///  (iii) rho v_y^2 = b_g sigma_bar^n, sigma_bar = sigma_y / sigma0, common n, one b_g per E*
///        group; fitted in log space (Ma eq. 15)
///  (iv)  b = c E_bar^m, E_bar = E* / E0*; fitted in log space (Ma eq. 17)
/// and the combined yield-velocity constant K = c sigma0^-n E0*^-m of
/// v_y = sqrt(K sigma_y^n E*^m / rho) (Ma eq. 18: K = 15.81 with n = 4.5, m = -3.5).
/// k1 = E*/(rho v^2) (Ma eq. 5), k2 = sigma_y/E* (Ma eq. 6).

#include <string>
#include <vector>

#include "corlab/fit/linear_regression.hpp"

namespace corlab::study {

/// The paper's published values (Ma et al. 2023, eqs. 9, 11, 15, 17, 18).
struct PaperConstants {
  static constexpr double kSlope = 0.056;     ///< s, eq. 9 [-]
  static constexpr double kAlpha = 1.16;      ///< alpha, eq. 11 [-]
  static constexpr double kBeta = 0.253;      ///< beta, eq. 11 [-]
  static constexpr double kExponentN = 4.5;   ///< n, eq. 15 [-]
  static constexpr double kExponentM = -3.5;  ///< m, eq. 17 [-]
  static constexpr double kC = 0.05;          ///< c, eq. 17 [Pa]
  static constexpr double kCombined = 15.81;  ///< K, eq. 18 [Pa^(1-n-m)]
  static constexpr double kSigma0 = 100e6;    ///< sigma0, eq. 14 [Pa]
  static constexpr double kE0 = 100e9;        ///< E0*, eq. 16 [Pa]
};

/// A row left out of a fit, and why (e.g. "e = nan", "status = failed").
struct ExcludedRow {
  std::string case_id;  ///< the row's case_id (or "row N" in a table without one)
  std::string reason;
};

/// One simulated impact (a row of results.csv).
struct RestitutionSample {
  std::string case_id;      ///< the paper "case" (group of velocities) the point belongs to
  double velocity = 0.0;    ///< impact speed v [m/s]
  double e = 0.0;           ///< coefficient of restitution [-]
  double sphere_rho = 0.0;  ///< sphere density rho [kg/m^3]
  double E_star = 0.0;      ///< effective modulus E* [Pa]
  double sigma_y = 0.0;     ///< substrate yield stress [Pa]
  std::string row_id;       ///< case_id of its results.csv row (names it when it is excluded)
  double k1() const { return E_star / (sphere_rho * velocity * velocity); }  ///< [-]
  double k2() const { return sigma_y / E_star; }                             ///< [-]
};

/// A fitted coefficient with its inference, next to the paper's value.
struct Coefficient {
  std::string name;
  double value = 0.0;
  double standard_error = 0.0;
  double ci_lower = 0.0;
  double ci_upper = 0.0;
  double paper = 0.0;  ///< published value (NaN if the paper gives none)
  std::string unit;    ///< "-" or e.g. "Pa"
};

/// Options of the paper fits.
struct PaperFitOptions {
  double confidence = 0.95;                 ///< level of the confidence intervals [-]
  double plastic_tolerance = 1e-3;          ///< form (i) uses points with e < 1 - plastic_tolerance
  bool include_suspect = false;             ///< also fit runs flagged suspect (run_quality.hpp)
  int min_points_per_case = 2;              ///< a case with fewer plastic points is left out of (i)
  double sigma0 = PaperConstants::kSigma0;  ///< [Pa]
  double E0 = PaperConstants::kE0;          ///< [Pa]
};

/// One case of form (i): its intercept and the velocity where its line reaches e = 1.
struct CaseIntercept {
  std::string case_id;
  double sphere_rho = 0.0;  ///< [kg/m^3]
  double E_star = 0.0;      ///< [Pa]
  double sigma_y = 0.0;     ///< [Pa]
  double k2 = 0.0;          ///< [-]
  Coefficient a;            ///< intercept a_i [-]
  int points = 0;           ///< plastic points of the case
  double v_cross = 0.0;  ///< e = 1 crossing of a_i + s ln k1: sqrt(E*/(rho exp((1-a_i)/s))) [m/s]
};

/// Forms (i) and (ii).
struct RestitutionLawFit {
  Coefficient slope;                 ///< s
  std::vector<CaseIntercept> cases;  ///< a_i per case (sorted by case id)
  Coefficient alpha;                 ///< form (ii) intercept
  Coefficient beta;                  ///< form (ii) slope
  GoodnessOfFit form_i;              ///< e against a_i + s ln k1
  GoodnessOfFit form_ii;             ///< a_i against alpha + beta ln k2
  GoodnessOfFit combined;            ///< e against alpha + beta ln k2 + s ln k1 (Ma eq. 12)
  int points_used = 0;
  int points_excluded = 0;  ///< elastic (e >= 1 - tol), non-finite, or in too-small cases
  std::vector<std::string> cases_excluded;  ///< cases with < min_points_per_case plastic points
  std::vector<ExcludedRow> excluded;        ///< each excluded point, with the reason
};

/// Fits forms (i) and (ii). Form (ii) needs >= 3 distinct cases; with fewer, alpha/beta are NaN.
/// Throws InputError if fewer than 2 cases or too few points remain for form (i).
RestitutionLawFit fit_restitution_law(const std::vector<RestitutionSample>& samples,
                                      const PaperFitOptions& options = {});

/// One yield velocity (from a crossing or from the solver directly).
struct YieldVelocitySample {
  std::string case_id;
  double sphere_rho = 0.0;  ///< [kg/m^3]
  double E_star = 0.0;      ///< [Pa]
  double sigma_y = 0.0;     ///< [Pa]
  double v_y = 0.0;         ///< [m/s]
};

/// One E* group of form (iii).
struct YieldGroup {
  double E_star = 0.0;  ///< [Pa]
  Coefficient b;        ///< [Pa]
  int points = 0;
};

/// Forms (iii) and (iv), and the combined constant of Ma eq. 18.
struct YieldVelocityFit {
  Coefficient n;                   ///< exponent of sigma_bar
  std::vector<YieldGroup> groups;  ///< b per E* (ascending E*)
  Coefficient c;                   ///< [Pa]
  Coefficient m;                   ///< exponent of E_bar
  /// K of v_y^2 = K sigma_y^n E*^m / rho from the one-step regression
  /// ln(rho v_y^2) = ln K + n ln sigma_y + m ln E* (interval: exp of the ln K interval; K is far
  /// outside the data, at sigma_y = E* = 1 Pa, so its interval is wide). [Pa^(1-n-m)]
  Coefficient combined;
  /// K with the exponents fixed at the paper's n = 4.5, m = -3.5 (geometric mean of
  /// rho v_y^2 sigma_y^-4.5 E*^3.5; directly comparable with the published 15.81) [-]
  Coefficient combined_fixed;
  Coefficient n_joint;             ///< n of the one-step regression
  Coefficient m_joint;             ///< m of the one-step regression
  double combined_two_step = 0.0;  ///< c sigma0^-n E0^-m from forms (iii) and (iv)
  GoodnessOfFit form_iii;          ///< rho v_y^2 against b_g sigma_bar^n (original space)
  GoodnessOfFit form_iv;           ///< b_g against c E_bar^m (original space)
  GoodnessOfFit combined_v;        ///< v_y against sqrt(K sigma^n E*^m / rho)
  int points = 0;
};

/// Fits forms (iii) and (iv). Needs >= 2 sigma_y values; form (iv) needs >= 3 E* groups (else
/// c, m, K are NaN). Throws InputError for non-positive inputs or too few points.
YieldVelocityFit fit_yield_velocity(const std::vector<YieldVelocitySample>& samples,
                                    const PaperFitOptions& options = {});

/// v_y where alpha + beta ln k2 + s ln k1 = 1 (the paper's back-calculation from Ma eq. 12):
/// k1_y = exp((1 - alpha - beta ln k2)/s), v_y = sqrt(E*/(rho k1_y)) [m/s].
double crossing_yield_velocity(
    double alpha, double beta, double slope, double sphere_rho, double E_star, double sigma_y);

/// Ma eq. 12/19 with general constants: 1 below the crossing, the log law above, clamped to
/// [0, 1].
double log_law_restitution(double alpha,
                           double beta,
                           double slope,
                           double sphere_rho,
                           double E_star,
                           double sigma_y,
                           double velocity);

/// Ma eq. 18 with general constants: sqrt(K sigma_y^n E*^m / rho) [m/s].
double power_law_yield_velocity(
    double K, double n, double m, double sphere_rho, double E_star, double sigma_y);

}  // namespace corlab::study
