#include "corlab/core/error.hpp"

#include <fmt/format.h>

#include <cmath>
#include <utility>

namespace corlab {

namespace {
// User text in a message is shown with its control characters escaped, so the message stays one
// line whatever the input holds (found by fuzzing the inline material parser).
std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (u < 0x20 || u == 0x7f) {
      out += fmt::format("\\x{:02x}", u);
    } else {
      out += c;
    }
  }
  return out;
}
}  // namespace

InputError::InputError(std::string field, std::string value, std::string constraint, bool quoted)
    : std::invalid_argument(
          quoted ? fmt::format("invalid {} = '{}': must be {}", printable(field), printable(value),
                               printable(constraint))
                 : fmt::format("invalid {} = {}: must be {}", printable(field), printable(value),
                               printable(constraint))),
      field_(std::move(field)),
      value_(std::move(value)),
      constraint_(std::move(constraint)) {}

void throw_invalid(std::string_view field, double value, std::string_view constraint) {
  throw InputError(std::string(field), fmt::format("{}", value), std::string(constraint), false);
}

void throw_invalid(std::string_view field, std::string_view value, std::string_view constraint) {
  throw InputError(std::string(field), std::string(value), std::string(constraint), true);
}

void require_positive(std::string_view field, double value, std::string_view unit) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw_invalid(field, value, unit.empty() ? std::string("> 0") : fmt::format("> 0 {}", unit));
  }
}

void require_non_negative(std::string_view field, double value, std::string_view unit) {
  if (!(std::isfinite(value) && value >= 0.0)) {
    throw_invalid(field, value, unit.empty() ? std::string(">= 0") : fmt::format(">= 0 {}", unit));
  }
}

void require_open_range(std::string_view field, double value, double lo, double hi) {
  if (!(std::isfinite(value) && value > lo && value < hi)) {
    throw_invalid(field, value, fmt::format("in ({}, {})", lo, hi));
  }
}

void require_closed_range(std::string_view field, double value, double lo, double hi) {
  if (!(std::isfinite(value) && value >= lo && value <= hi)) {
    throw_invalid(field, value, fmt::format("in [{}, {}]", lo, hi));
  }
}

}  // namespace corlab
