// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file fitted_coefficients.hpp
/// A model's fitted coefficients {name, value} as configure generates them from its
/// model_fit.json (cmake/Corlab2026Coefficients.cmake), and the Corlab2026Coefficients they set:
/// shared by corlab2026 and corlab2026p. Private to src/restitution.

#include <string_view>

#include "corlab/restitution/corlab2026.hpp"

namespace corlab::restitution::detail {

/// One generated entry: a coefficient's name (kCorlab2026Coefficients) and value [-].
struct FittedValue {
  std::string_view name;
  double value;
};

/// The coefficients named in `fitted` (a range of FittedValue); the others keep their defaults.
template <class Fitted>
constexpr Corlab2026Coefficients coefficients_from(const Fitted& fitted) {
  Corlab2026Coefficients k;
  for (const auto& [name, member] : kCorlab2026Coefficients) {
    for (const auto& f : fitted) {
      if (f.name == name) k.*member = f.value;
    }
  }
  return k;
}

}  // namespace corlab::restitution::detail
