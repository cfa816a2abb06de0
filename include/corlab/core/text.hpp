// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file text.hpp
/// Small text helpers shared by the parsers (config keys, material specs, fit forms, CSV) and their
/// error messages.

#include <algorithm>
#include <string>
#include <string_view>

namespace corlab {

/// `text` without leading and trailing blanks (space, tab, CR, LF, FF, VT).
constexpr std::string_view trim(std::string_view text) {
  constexpr std::string_view kBlank = " \t\r\n\f\v";
  const auto first = text.find_first_not_of(kBlank);
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(kBlank) - first + 1);
}

/// `text` with each line break (CR, LF) replaced by a blank: error messages are one line, also when
/// they quote a parser's multi-line message.
inline std::string one_line(std::string text) {
  std::replace_if(
      text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  return text;
}

}  // namespace corlab
