#include "corlab/core/error.hpp"

#include <fmt/format.h>

#include <cmath>
#include <utility>

namespace corlab {

InputError::InputError(std::string field, std::string value, std::string constraint, bool quoted)
    : std::invalid_argument(
          quoted ? fmt::format("invalid {} = '{}': must be {}", field, value, constraint)
                 : fmt::format("invalid {} = {}: must be {}", field, value, constraint)),
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
