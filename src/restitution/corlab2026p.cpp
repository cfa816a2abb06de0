// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/restitution/corlab2026p.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

#include "corlab/core/error.hpp"
#include "corlab/restitution/first_yield.hpp"
#include "restitution/fitted_coefficients.hpp"

namespace corlab::restitution {
namespace {

// The fitted coefficients {name, value}: data/fe_restitution_pairs/model_fit.json's
// "coefficients", generated at configure time (cmake/Corlab2026Coefficients.cmake).
using detail::FittedValue;
constexpr auto kFitted = std::to_array<FittedValue>({
#include "corlab2026p_fitted.inc"
});

constexpr bool each_coefficient_fitted_once() {
  if (kFitted.size() != kCorlab2026Coefficients.size()) return false;
  return std::all_of(kCorlab2026Coefficients.begin(), kCorlab2026Coefficients.end(),
                     [](const auto& c) {
                       return std::count_if(kFitted.begin(), kFitted.end(),
                                            [&](const auto& f) { return f.name == c.first; }) == 1;
                     });
}
static_assert(each_coefficient_fitted_once(),
              "data/fe_restitution_pairs/model_fit.json must hold exactly the coefficients of "
              "kCorlab2026Coefficients (corlab2026.hpp)");

}  // namespace

Corlab2026Pair corlab2026p_pair(const Material& sphere,
                                const Material& other,
                                double radius_ratio) {
  // The pair's Hertz impact is a sphere of density rho* [kg/m^3] on a flat.
  const Material effective = pair_reduced_sphere(sphere, other, radius_ratio);
  Corlab2026Pair pair = corlab2026_pair(effective, other);
  // Johnson's damage number on the density [kg/m^3] of the body that yields first (the one
  // cratered): corlab2026_pair() put rho* there.
  const double cratered = pair.inputs.other_is_sphere ? other.density : sphere.density;
  pair.inputs.damage_at_yield *= cratered / effective.density;
  pair.inputs.radius_ratio = radius_ratio;
  return pair;
}

Corlab2026Coefficients corlab2026p_fitted() {
  static constexpr Corlab2026Coefficients kCoefficients = detail::coefficients_from(kFitted);
  return kCoefficients;
}

Corlab2026 corlab2026p(const Material& sphere, const Material& other, double radius_ratio) {
  return Corlab2026{.pair = corlab2026p_pair(sphere, other, radius_ratio),
                    .coefficients = corlab2026p_fitted()};
}

}  // namespace corlab::restitution
