// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file result_fields.hpp
/// The one table of result fields: name, SI unit, description, accessor and where the field is
/// written. summary.json (impact_output.cpp), the results.csv header and rows
/// (study/results_table.cpp, failed-run rows included), the CSV reader's text columns and the
/// Python module (`corlab.result_fields()`) all derive from it.
///
/// Adding a field: one entry in result_fields.cpp plus the code that computes the value.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/solver/impact_result.hpp"

namespace corlab::fem {

/// A field's value: empty (no value, e.g. a failed run), a real number, an integer, a flag, text
/// or a list of reals (summary.json only).
using FieldValue =
    std::variant<std::monostate, double, long long, bool, std::string, std::vector<double>>;

/// What an accessor reads. `result` is null for a run that failed before it produced a result;
/// `wall_s` is the caller's wall-clock time of the run [s] (used where the result has none).
struct FieldInput {
  const ImpactResult* result = nullptr;
  const ImpactConfig* config = nullptr;
  double wall_s = 0.0;
};

/// Where a field is written (bit set).
enum FieldOutput : std::uint8_t {
  kSummary = 1U << 0U,  ///< summary.json and corlab.simulate()'s dict
  kCsv = 1U << 1U,      ///< results.csv of a sweep
  kBoth = kSummary | kCsv,
};

/// The type of a field's value (for readers: text columns are never parsed as numbers).
enum class FieldKind : std::uint8_t { real, integer, boolean, text, real_list };

/// "real", "integer", "boolean", "text" or "real_list".
std::string_view to_string(FieldKind kind);

struct ResultField {
  std::string_view name;         ///< JSON key and CSV column
  std::string_view unit;         ///< SI unit; "-" for dimensionless or a count
  std::string_view description;  ///< one line, for docs and --help
  FieldKind kind;
  FieldValue (*value)(const FieldInput&);  ///< the accessor
  std::uint8_t outputs;                    ///< FieldOutput bits
  bool machine_dependent = false;          ///< timings: excluded when comparing two runs
};

/// Every result field; the order is the results.csv column order.
std::span<const ResultField> result_fields();

/// The field called `name`, or null.
const ResultField* find_result_field(std::string_view name);

/// A value as CSV text: shortest round-trip text for reals, "true"/"false" for flags, and ""
/// where the run has no value: an empty field or a NaN real (not applicable to the run, e.g.
/// e_t of a normal impact or k2 of an elastic flat, or not computed, e.g. e_error without the
/// error estimate; summary.json writes null). An infinity would be written "inf" (the contract
/// tests make sure none is).
std::string field_text(const FieldValue& value);

}  // namespace corlab::fem
