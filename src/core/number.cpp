// The one strict number parser (number.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/core/number.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>
#include <system_error>
#include <version>

#include "corlab/core/error.hpp"
#include "corlab/core/text.hpp"

namespace corlab {
namespace {

/// std::from_chars of the whole text into `value`; false if the text is not one number.
template <typename T>
bool read_whole(std::string_view text, T& value) {
  const char* last = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), last, value);
  return ec == std::errc() && ptr == last;
}

#if !defined(__cpp_lib_to_chars)
// libc++ before 17 (emscripten's: the explorer's WebAssembly build, explorer/CMakeLists.txt) has
// no floating-point from_chars: strtod under from_chars's rules (no blanks, no hex, out of range
// is no number).
template <>
bool read_whole<double>(std::string_view text, double& value) {
  if (text.find_first_of(" \t\n\v\f\rxXpP") != std::string_view::npos) return false;
  const std::string copy(text);
  char* end = nullptr;
  errno = 0;
  value = std::strtod(copy.c_str(), &end);
  return errno != ERANGE && end == copy.c_str() + copy.size();
}
#endif

/// std::from_chars over the whole text, after an optional '+' (from_chars itself refuses it).
template <typename T>
std::optional<T> parse_whole(std::string_view text) {
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (!text.empty() && text.front() == '-') return std::nullopt;  // "+-5"
  }
  if (text.empty()) return std::nullopt;
  T value{};
  if (!read_whole(text, value)) return std::nullopt;
  return value;
}

}  // namespace

std::optional<double> parse_double(std::string_view text) { return parse_whole<double>(text); }

std::optional<long long> parse_integer(std::string_view text) {
  return parse_whole<long long>(text);
}

double parse_finite(std::string_view field, std::string_view text) {
  text = trim(text);
  const std::optional<double> value = parse_double(text);
  if (!value || !std::isfinite(*value)) throw_invalid(field, text, "a finite number");
  return *value;
}

}  // namespace corlab
