#include "corlab/core/error.hpp"

#include <fmt/format.h>

#include <cmath>

namespace corlab {

void throw_invalid(std::string_view field, double value, std::string_view constraint) {
  throw InputError(fmt::format("invalid {} = {}: must be {}", field, value, constraint));
}

void throw_invalid(std::string_view field, std::string_view value, std::string_view constraint) {
  throw InputError(fmt::format("invalid {} = '{}': must be {}", field, value, constraint));
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
