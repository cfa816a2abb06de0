// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file error.hpp
/// Errors for bad user input. Every invalid value is reported on one line that names the field,
/// the value and the violated constraint, e.g.
///   invalid sphere.E = -200000000000: must be > 0 [Pa]
/// The CLI turns an InputError into that line on stderr and exit code 2; Python sees ValueError.

#include <stdexcept>
#include <string>
#include <string_view>

namespace corlab {

/// Bad user input (configuration, material, model name, velocity ...). Thrown only at the edges
/// (parsers, validators); physics kernels never throw.
///
/// An error about one field carries the field, the value and the constraint as data, so callers
/// that re-word it (a sweep spec naming the line of the value) read them instead of parsing
/// what(). what() is the one-line message.
class InputError : public std::invalid_argument {
 public:
  /// An error that is not about one field's value (field(), value(), constraint() are empty).
  explicit InputError(const std::string& message) : std::invalid_argument(message) {}
  /// "invalid <field> = <value>: must be <constraint>", value quoted when `quoted`.
  InputError(std::string field, std::string value, std::string constraint, bool quoted);

  /// The field, e.g. "impact.velocity"; empty if the error is not about one field.
  const std::string& field() const noexcept { return field_; }
  /// The value as written in the message (text, or the number's shortest form), without quotes.
  const std::string& value() const noexcept { return value_; }
  /// What the value must be, e.g. "> 0 [m/s]" (the text after "must be ").
  const std::string& constraint() const noexcept { return constraint_; }

 private:
  std::string field_;
  std::string value_;
  std::string constraint_;
};

/// Throws InputError("invalid <field> = <value>: must be <constraint>").
[[noreturn]] void throw_invalid(std::string_view field, double value, std::string_view constraint);
/// Same, for a textual value (model name, file, malformed token).
[[noreturn]] void throw_invalid(std::string_view field,
                                std::string_view value,
                                std::string_view constraint);

/// A user's value as messages show it: control characters and bytes that are not UTF-8 escaped
/// (\n, \x1b, \xff), and a value longer than 160 bytes cut to its first 160 with its length said,
/// so a message is one short line of valid text whatever the input (the InputError constructor
/// shows every value this way).
std::string message_text(std::string_view value);

/// Requires a finite value > 0.
void require_positive(std::string_view field, double value, std::string_view unit = "");
/// Requires a finite value >= 0.
void require_non_negative(std::string_view field, double value, std::string_view unit = "");
/// Requires a finite value in the open interval (lo, hi).
void require_open_range(std::string_view field, double value, double lo, double hi);
/// Requires a finite value in the closed interval [lo, hi].
void require_closed_range(std::string_view field, double value, double lo, double hi);

}  // namespace corlab
