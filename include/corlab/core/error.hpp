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
class InputError : public std::invalid_argument {
 public:
  explicit InputError(const std::string& message) : std::invalid_argument(message) {}
};

/// Throws InputError("invalid <field> = <value>: must be <constraint>").
[[noreturn]] void throw_invalid(std::string_view field, double value, std::string_view constraint);
/// Same, for a textual value (model name, file, malformed token).
[[noreturn]] void throw_invalid(std::string_view field,
                                std::string_view value,
                                std::string_view constraint);

/// Requires a finite value > 0.
void require_positive(std::string_view field, double value, std::string_view unit = "");
/// Requires a finite value >= 0.
void require_non_negative(std::string_view field, double value, std::string_view unit = "");
/// Requires a finite value in the open interval (lo, hi).
void require_open_range(std::string_view field, double value, double lo, double hi);
/// Requires a finite value in the closed interval [lo, hi].
void require_closed_range(std::string_view field, double value, double lo, double hi);

}  // namespace corlab
