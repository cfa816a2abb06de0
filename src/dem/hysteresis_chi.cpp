#include "corlab/dem/hysteresis_chi.hpp"

#include <gsl/gsl_sf_lambert.h>

#include <cmath>

#include "corlab/core/error.hpp"
#include "dem/detail/gsl_solvers.hpp"

namespace corlab::dem {

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
  require_closed_range("restitution", e, 1e-12, 1.0);
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
  if (chi < 1e-2) {
    // Near the Lambert-W branch point W0 loses digits: solve the relation for e directly.
    const auto h = [chi](double e) {
      return chi * (1.0 + e) - std::log1p(chi) + std::log1p(-e * chi);
    };
    return detail::brent_root(h, 0.0, 1.0, 0.0, 1e-15);
  }
  const double a = 1.0 + chi;
  return (1.0 + gsl_sf_lambert_W0(-a * std::exp(-a))) / chi;
}

double exact_chi(double e) {
  require_closed_range("restitution", e, 1e-12, 1.0);
  if (e == 1.0) return 0.0;
  // g(chi) > 0 on (0, chi*), < 0 on (chi*, 1/e); log1p keeps the O(chi^2) difference accurate.
  const auto g = [e](double chi) {
    return chi * (1.0 + e) - std::log1p(chi) + std::log1p(-e * chi);
  };
  const double lo = 0.1 * (1.0 - e);
  const double hi = (1.0 - 1e-15) / e;
  return detail::brent_root(g, lo, hi, 0.0, 1e-14);
}

}  // namespace corlab::dem
