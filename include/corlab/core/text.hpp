#pragma once
/// @file text.hpp
/// Small text helpers shared by the parsers (config keys, material specs, fit forms, CSV).

#include <string_view>

namespace corlab {

/// `text` without leading and trailing blanks (space, tab, CR, LF, FF, VT).
constexpr std::string_view trim(std::string_view text) {
  constexpr std::string_view kBlank = " \t\r\n\f\v";
  const auto first = text.find_first_not_of(kBlank);
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(kBlank) - first + 1);
}

}  // namespace corlab
