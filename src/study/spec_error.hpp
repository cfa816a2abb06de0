// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file spec_error.hpp
/// The errors of a sweep spec, located: "invalid spec <origin> <where>: <what>" as one-line
/// InputErrors. Private to src/study (sweep_spec.cpp).

#include <fmt/format.h>

#include <string>
#include <string_view>

#include "corlab/core/error.hpp"
#include "corlab/core/number.hpp"
#include "corlab/core/text.hpp"

namespace corlab::study {

/// How a value appears in messages: numbers as they are, strings in quotes.
inline std::string shown(std::string_view value) {
  return parse_double(value) ? std::string(value) : fmt::format("'{}'", message_text(value));
}

class SpecError {
 public:
  explicit SpecError(std::string origin) : origin_(std::move(origin)) {}

  /// "invalid spec <origin> <where>: <what>"
  [[noreturn]] void fail(std::string_view where, std::string_view what) const {
    if (where.empty())
      throw InputError(one_line(fmt::format("invalid spec {}: {}", origin_, what)));
    throw InputError(one_line(fmt::format("invalid spec {} {}: {}", origin_, where, what)));
  }
  /// "invalid spec <origin> <where> = <value>: <constraint>"
  [[noreturn]] void fail_value(std::string_view where,
                               std::string_view value,
                               std::string_view constraint) const {
    throw InputError(one_line(
        fmt::format("invalid spec {} {} = {}: {}", origin_, where, shown(value), constraint)));
  }
  /// Re-throws an error of fem::apply_setting / fem::validate at a location of the spec. When the
  /// error is about `key` itself (or, for "<body>.material", about the material of <body>), only
  /// its constraint is kept.
  [[noreturn]] void rethrow_at(std::string_view where,
                               std::string_view key,
                               std::string_view value,
                               const InputError& err) const {
    const std::string& field = err.field();
    if (!field.empty() && (field == key || std::string(key) == field + ".material")) {
      fail_value(where, value, "must be " + err.constraint());
    }
    fail_value(where, value, err.what());
  }

 private:
  std::string origin_;
};

}  // namespace corlab::study
