// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file choice_keys.hpp
/// The enums behind the config's choice keys (substrate.shape, substrate.boundary, solver.model,
/// contact.friction_enforcement):
/// their values and the parse of a key's text. Private to config_keys.cpp (src/fem/config).

#include <fmt/format.h>

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>

#include "corlab/core/error.hpp"
#include "corlab/core/text.hpp"
#include "corlab/fem/config/impact_config.hpp"

namespace corlab::fem::config_choices {

// The values of each choice key's enum (named by to_string), in order.
constexpr std::array kShapes{SubstrateShape::kFlat, SubstrateShape::kRigid,
                             SubstrateShape::kSphere};
constexpr std::array kModels{SolverModel::kAxisymmetric, SolverModel::kThreeD};
constexpr std::array kBoundaries{SubstrateBoundary::kFixed, SubstrateBoundary::kAbsorbing,
                                 SubstrateBoundary::kViscousSpring};
constexpr std::array kEnforcements{FrictionEnforcement::kKinematic, FrictionEnforcement::kPenalty};
constexpr std::span<const SubstrateShape> choices(SubstrateShape /*tag*/) { return kShapes; }
constexpr std::span<const SolverModel> choices(SolverModel /*tag*/) { return kModels; }
constexpr std::span<const SubstrateBoundary> choices(SubstrateBoundary /*tag*/) {
  return kBoundaries;
}
constexpr std::span<const FrictionEnforcement> choices(FrictionEnforcement /*tag*/) {
  return kEnforcements;
}

template <class T>
constexpr bool kIsChoice =
    std::is_same_v<T, SubstrateShape> || std::is_same_v<T, SolverModel> ||
    std::is_same_v<T, SubstrateBoundary> || std::is_same_v<T, FrictionEnforcement>;

template <class Enum>
Enum parse_choice(std::string_view key, std::string_view text) {
  text = trim(text);
  std::string names;
  for (const Enum s : choices(Enum{})) {
    if (to_string(s) == text) return s;
    names += fmt::format("{}{}", names.empty() ? "" : ", ", to_string(s));
  }
  throw_invalid(key, text, fmt::format("one of {}", names));
}

}  // namespace corlab::fem::config_choices
