// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dem/hysteresis_chi.hpp"

#include <gsl/gsl_sf_lambert.h>

#include <cmath>

#include "corlab/core/error.hpp"
#include "corlab/dem/contact_laws.hpp"
#include "dem/detail/gsl_solvers.hpp"

namespace corlab::dem {

namespace {

// [chi (1 + e) - ln((1 + chi)/(1 - e chi))] / chi^2 = sum_{k>=2} ((-1)^k - e^k) chi^(k-2) / k,
// free of cancellation; used for chi < 0.06 (40 terms: remainder < 0.06^38).
double scaled_relation(double chi, double e) {
  double sum = 0.0;
  double chi_power = 1.0;
  double e_power = e * e;
  for (int k = 2; k < 40; ++k) {
    sum += ((k % 2 == 0 ? 1.0 : -1.0) - e_power) * chi_power / k;
    chi_power *= chi;
    e_power *= e;
  }
  return sum;
}

}  // namespace

std::string_view to_string(ChiFormula formula) {
  switch (formula) {
    case ChiFormula::kHuntCrossley:
      return "hunt_crossley";
    case ChiFormula::kLankaraniNikravesh:
      return "lankarani_nikravesh";
    case ChiFormula::kFlores:
      return "flores";
    case ChiFormula::kGonthier:
      return "gonthier";
    case ChiFormula::kHuGuo:
      return "hu_guo";
    case ChiFormula::kCarvalhoMartins:
      return "carvalho_martins";
  }
  return "unknown";
}

double published_chi(ChiFormula formula, double e) {
  require_closed_range("restitution", e, kMinRestitution, 1.0);
  switch (formula) {
    case ChiFormula::kHuntCrossley:
      return 1.5 * (1.0 - e);
    case ChiFormula::kLankaraniNikravesh:
      return 0.75 * (1.0 - e * e);
    case ChiFormula::kFlores:
      return 8.0 * (1.0 - e) / (5.0 * e);
    case ChiFormula::kGonthier:
      return (1.0 - e * e) / e;
    case ChiFormula::kHuGuo:
      return 1.5 * (1.0 - e) / e;
    case ChiFormula::kCarvalhoMartins:
      return 1.5 * (1.0 - e) * (11.0 - e) / (1.0 + 9.0 * e);
  }
  return 0.0;
}

double exact_restitution(double chi) {
  require_non_negative("chi", chi);
  if (chi == 0.0) return 1.0;
  if (chi < 0.05) {
    // Near the Lambert-W branch point W0 loses digits: solve the series form for e.
    return detail::brent_root([chi](double e) { return scaled_relation(chi, e); }, 0.0, 1.0, 2e-16,
                              0.0);
  }
  const double a = 1.0 + chi;
  return (1.0 + gsl_sf_lambert_W0(-a * std::exp(-a))) / chi;
}

double exact_chi(double e) {
  require_closed_range("restitution", e, kMinRestitution, 1.0);
  if (e == 1.0) return 0.0;
  if (e > 0.97) {
    // chi* < 0.06 there.
    const auto scaled = [e](double chi) { return scaled_relation(chi, e); };
    return detail::brent_root(scaled, 0.0, 0.06, 0.0, 1e-14);
  }
  if (e < 0.1) {
    // chi* is within 1e-3 relative of the pole 1/e (1 - e chi ~ (1 + 1/e) exp(-(1 + e)/e)):
    // iterate y = 1 - e chi = (1 + chi) exp(-chi (1 + e)), contraction ~ y (1 + e)/e < 3e-3.
    double chi = 1.0 / e;
    for (int iter = 0; iter < 100; ++iter) {
      const double next = (1.0 - (1.0 + chi) * std::exp(-chi * (1.0 + e))) / e;
      if (std::abs(next - chi) <= 1e-16 * chi) return next;
      chi = next;
    }
    return chi;
  }
  // g(chi) > 0 on (0, chi*), < 0 on (chi*, 1/e); log1p keeps the O(chi^2) difference accurate.
  const auto g = [e](double chi) {
    return chi * (1.0 + e) - std::log1p(chi) + std::log1p(-e * chi);
  };
  return detail::brent_root(g, 0.1 * (1.0 - e), (1.0 - 1e-15) / e, 0.0, 1e-14);
}

}  // namespace corlab::dem
