// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file results_table.hpp
/// results.csv of a sweep: the column layout, one-row formatting, a crash-safe appender and a
/// reader with access by column name (used by the fitter and Python).
///
/// Layout: case_id, status (ok | failed | not_separated), the swept keys as given in the spec,
/// then the result columns (result_columns()), then `error` (the one-line message of a failed
/// case). RFC 4180 quoting; one physical line per row; numbers written in the shortest text that
/// reads back to the same double, so a table re-read is bitwise identical.

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/solver/impact_result.hpp"

namespace corlab::study {

/// Result columns, in order: the fields of fem::result_fields() written to the CSV (names, units
/// and descriptions are in that table, src/fem/solver/result_fields.cpp).
const std::vector<std::string>& result_columns();

/// Columns whose values depend on the machine (timings, `machine_dependent` in the table);
/// excluded when comparing two runs.
const std::vector<std::string>& timing_columns();

/// The full header for the given swept keys.
std::vector<std::string> results_header(const std::vector<std::string>& swept_keys);

/// Status of a finished case as written in the `status` column.
inline constexpr std::string_view kStatusOk = "ok";
inline constexpr std::string_view kStatusFailed = "failed";
inline constexpr std::string_view kStatusNotSeparated = "not_separated";

/// The `status` column of a row: failed (no result: the run threw), ok (a clean rebound) or the
/// run status (fem::to_string(RunStatus), e.g. not_separated, element_inverted). This is
/// the one place a run's outcome becomes the CSV status (the result fields table holds the rest).
std::string_view row_status(const fem::ImpactResult* result);

/// The fields of one row (same order as results_header()). `result` is null for a failed case,
/// whose `error` holds the message; `wall_s` is used when the result carries no timing.
std::vector<std::string> result_row(std::string_view case_id,
                                    const std::vector<std::string>& swept_values,
                                    const fem::ImpactConfig& config,
                                    const fem::ImpactResult* result,
                                    std::string_view error,
                                    double wall_s);

/// Shortest text that reads back to the same double; "" for NaN (no value: fem::field_text).
std::string format_number(double value);

/// One CSV line (no line break) with RFC 4180 quoting; line breaks inside fields become spaces.
std::string csv_line(const std::vector<std::string>& fields);
/// Splits one CSV line; throws InputError on an unterminated quote.
std::vector<std::string> split_csv_line(std::string_view line);

/// Appends rows to a CSV file: each row is one write() of the whole line followed by fsync, so a
/// kill leaves at most one partial last line. Not thread-safe: use from one writer thread.
class CsvAppender {
 public:
  /// Opens (creating if needed) for appending. If the file is empty, writes `header` first.
  CsvAppender(const std::filesystem::path& file, const std::vector<std::string>& header);
  ~CsvAppender();
  CsvAppender(const CsvAppender&) = delete;
  CsvAppender& operator=(const CsvAppender&) = delete;
  /// Writes one row (fields) and syncs it to disk.
  void append(const std::vector<std::string>& fields);
  /// Writes one already formatted line (without line break) and syncs it to disk.
  void append_line(std::string_view line);

 private:
  int fd_ = -1;
  std::filesystem::path file_;
};

/// What an existing results.csv holds, for resuming.
struct ExistingResults {
  std::vector<std::string> header;            ///< empty if the file does not exist or is empty
  std::map<std::string, std::string> status;  ///< case_id -> status of its first complete row
  bool dropped_partial_line = false;          ///< a cut last line (kill during a write)
  std::size_t rows = 0;                       ///< complete rows kept
  std::size_t duplicates_dropped = 0;         ///< kept rows of a case that was already kept
};

/// Prepares `file` for resuming: drops a cut last line (a last line that has every field but no
/// line break is kept), the rows whose status is not in `keep_status` and repeated rows of a case
/// (rewritten atomically: temp file + rename), and returns what is left. Throws
/// InputError if the file's header differs from `expected_header` (written for another spec).
ExistingResults prepare_resume(const std::filesystem::path& file,
                               const std::vector<std::string>& expected_header,
                               const std::vector<std::string>& keep_status);

/// A CSV table read into memory, with column access by name.
class ResultsTable {
 public:
  ResultsTable() = default;
  ResultsTable(std::vector<std::string> columns, std::vector<std::vector<std::string>> rows);

  const std::vector<std::string>& columns() const { return columns_; }
  std::size_t size() const { return rows_; }
  bool has_column(std::string_view name) const;
  /// True if every non-empty cell of the column is a number and at least one cell is not empty
  /// (case_id, status and error are always text).
  bool is_numeric(std::string_view name) const;
  /// The column as numbers (empty cells -> nan); throws InputError if missing or not numeric.
  std::vector<double> numbers(std::string_view name) const;
  /// The column's cells as written; throws InputError if missing.
  const std::vector<std::string>& text(std::string_view name) const;
  /// One cell; throws InputError if the column is missing.
  const std::string& cell(std::size_t row, std::string_view name) const;
  /// The rows whose `column` equals `value` (e.g. status == "ok").
  ResultsTable where(std::string_view column, std::string_view value) const;
  /// Rows sorted by a text column (e.g. case_id), stable.
  ResultsTable sorted_by(std::string_view column) const;
  /// What read_results() repaired, one line each (a dropped partial line, a repeated row): to
  /// show the user as warnings.
  const std::vector<std::string>& notes() const { return notes_; }

 private:
  friend ResultsTable read_results(const std::filesystem::path& csv);
  std::size_t index_of(std::string_view name) const;
  std::vector<std::string> columns_;
  std::vector<std::vector<std::string>> cells_;  ///< column-major
  std::size_t rows_ = 0;
  std::vector<std::string> notes_;
};

/// Reads a results.csv (any CSV with a header). Nothing is dropped or doubled silently:
/// - a last line without a line break is a row like any other when it has every field;
/// - a cut last line is dropped with a note in a sweep's own results.csv (header case_id, status,
///   ..., error: append-only, so the cut is a kill during a write) and is an error elsewhere;
/// - a case_id repeated with the same values (timings aside) is kept once, with a note; with
///   other values it is an error;
/// - a column named twice in the header, or a row with the wrong number of fields, is an error.
/// Errors are InputError naming the file and line; notes are in ResultsTable::notes().
ResultsTable read_results(const std::filesystem::path& csv);

}  // namespace corlab::study
