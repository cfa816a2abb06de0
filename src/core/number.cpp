// The one strict number parser (number.hpp).
#include "corlab/core/number.hpp"

#include <charconv>
#include <cmath>
#include <system_error>

#include "corlab/core/error.hpp"
#include "corlab/core/text.hpp"

namespace corlab {
namespace {

/// std::from_chars over the whole text, after an optional '+' (from_chars itself refuses it).
template <typename T>
std::optional<T> parse_whole(std::string_view text) {
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (!text.empty() && text.front() == '-') return std::nullopt;  // "+-5"
  }
  if (text.empty()) return std::nullopt;
  T value{};
  const char* last = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), last, value);
  if (ec != std::errc() || ptr != last) return std::nullopt;
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
