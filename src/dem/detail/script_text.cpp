// SPDX-License-Identifier: BSD-3-Clause
#include "dem/detail/script_text.hpp"

#include <fmt/format.h>

namespace corlab::dem::detail {

std::string script_text(std::string_view text) {
  constexpr std::string_view kEscaped = "\"'\\$&#";
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u > 0x7e || kEscaped.find(c) != std::string_view::npos) {
      out += fmt::format("\\x{:02x}", u);
    } else {
      out += c;
    }
  }
  return out;
}

std::string python_string(std::string_view text) { return fmt::format("'{}'", script_text(text)); }

}  // namespace corlab::dem::detail
