// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file number.hpp
/// The one strict number parser of corlab: config values, material specs, sweep specs, CSV
/// cells, CLI arguments and fit start values all read numbers through it, so "1e-3", "+5",
/// "5 " and "5abc" mean the same thing everywhere.

#include <optional>
#include <string_view>

namespace corlab {

/// The whole of `text` as a double (std::from_chars, general format, an optional leading '+'),
/// or nullopt when it is empty, not a number or followed by anything. Blanks are not skipped
/// (trim() first where they are allowed). "nan" and "inf" parse: callers that need a finite
/// value use parse_finite().
std::optional<double> parse_double(std::string_view text);

/// The whole of `text` as a decimal integer (an optional leading '+'), or nullopt.
std::optional<long long> parse_integer(std::string_view text);

/// `text` without surrounding blanks as a finite double; otherwise throws InputError
/// "invalid <field> = '<text>': must be a finite number".
double parse_finite(std::string_view field, std::string_view text);

}  // namespace corlab
