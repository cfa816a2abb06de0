// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file history_columns.hpp
/// The one table of the time histories' columns (impact_result.hpp HistoryColumns): name, SI
/// unit, description and CSV precision. The solver's rows, history.csv (impact_output.cpp), the
/// Python `corlab.simulate()["history"]` arrays and `corlab.history_columns()` derive from it.
///
/// Adding a column: a member of HistoryColumns, one entry in history_columns.cpp, and the value
/// where the solver fills its HistoryRow.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "corlab/fem/solver/impact_result.hpp"

namespace corlab::fem {

struct HistoryColumn {
  std::string_view name;                       ///< the Python key; with the unit, the CSV column
  std::string_view unit;                       ///< SI unit; "-" for dimensionless
  std::string_view description;                ///< one line, for docs
  double HistoryRow::*value;                   ///< the row's member
  std::vector<double> ImpactHistory::*series;  ///< the histories' member
  int digits;                                  ///< significant digits in history.csv
};

/// Every column, in history.csv's order.
std::span<const HistoryColumn> history_columns();

/// The column's history.csv header: the name and its unit, "/" spelled "_per_" ("time_s",
/// "sphere_velocity_m_per_s"); the name alone for a dimensionless column.
std::string history_csv_header(const HistoryColumn& column);

/// Appends one row to the histories.
void append_row(ImpactHistory& history, const HistoryRow& row);

}  // namespace corlab::fem
