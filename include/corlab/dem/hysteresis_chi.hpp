// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file hysteresis_chi.hpp
/// The damping factor chi of F = K delta^n (1 + chi delta_dot / v_in) for a target restitution e:
/// the published approximations and the exact relation
///     chi (1 + e) = ln[(1 + chi) / (1 - e chi)],
/// which follows from integrating m v dv = -K x^n (1 + chi v/v_in) dx over approach and rebound
/// and holds for every n, K, m* and v_in (force never negative: 1 - e chi > 0).

#include <array>
#include <string_view>

namespace corlab::dem {

/// Published chi(e) formulas (docs/theory/dem_contact_laws.md).
enum class ChiFormula {
  kHuntCrossley,        ///< chi = 3(1 - e)/2 (Hunt & Crossley 1975)
  kLankaraniNikravesh,  ///< chi = 3(1 - e^2)/4 (Lankarani & Nikravesh 1990)
  kFlores,              ///< chi = 8(1 - e)/(5 e) (Flores et al. 2011)
  kGonthier,            ///< chi = (1 - e^2)/e (Gonthier et al. 2004)
  kHuGuo,               ///< chi = 3(1 - e)/(2 e) (Hu & Guo 2015)
  kCarvalhoMartins,     ///< chi = 3(1 - e)(11 - e)/(2(1 + 9 e)) (Carvalho & Martins 2019)
};

/// All formulas in a fixed order.
inline constexpr std::array<ChiFormula, 6> kChiFormulas = {
    ChiFormula::kHuntCrossley, ChiFormula::kLankaraniNikravesh,
    ChiFormula::kFlores,       ChiFormula::kGonthier,
    ChiFormula::kHuGuo,        ChiFormula::kCarvalhoMartins};

/// Registry key of a formula ("hunt_crossley", ...), as in law_catalog().
std::string_view to_string(ChiFormula formula);

/// The published chi for restitution e in (0, 1].
double published_chi(ChiFormula formula, double restitution);

/// Exact restitution delivered by chi >= 0: e = (1 + W0(-(1 + chi) exp(-(1 + chi)))) / chi
/// (Lambert W, principal branch); e(0) = 1.
double exact_restitution(double chi);

/// Exact chi for e in (0, 1): the non-zero root of chi (1 + e) - ln[(1 + chi)/(1 - e chi)] in
/// (0, 1/e) (Brent, |chi error| < 1e-13 chi); 0 for e = 1.
double exact_chi(double restitution);

}  // namespace corlab::dem
