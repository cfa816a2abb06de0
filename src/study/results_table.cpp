// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/study/results_table.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <numeric>
#include <optional>

#include "corlab/core/atomic_file.hpp"
#include "corlab/core/error.hpp"
#include "corlab/core/number.hpp"
#include "corlab/core/text_file.hpp"
#include "corlab/fem/solver/result_fields.hpp"
#include "corlab/materials/material.hpp"

namespace corlab::study {
namespace {

/// A results table, bounded and checked (text_file.hpp). `utf8` off for a sweep's own results.csv
/// on resume: a kill may have cut its last line inside a character.
std::string read_file(const std::filesystem::path& file, bool utf8 = true) {
  return read_text_file(file, "results file", {.max_bytes = kMaxTableFileBytes, .utf8 = utf8});
}

/// Complete lines of a file (the part after the last '\n' is returned in `partial`).
std::vector<std::string_view> complete_lines(std::string_view text, std::string_view& partial) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (true) {
    const auto end = text.find('\n', start);
    if (end == std::string_view::npos) break;
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
    start = end + 1;
  }
  partial = text.substr(start);
  return lines;
}

bool always_text(std::string_view column) {
  if (column == "case_id" || column == "status" || column == "error") return true;
  const fem::ResultField* field = fem::find_result_field(column);
  return field != nullptr && field->kind == fem::FieldKind::text;
}

/// A data row with its line number in the file (1 = header).
struct NumberedRow {
  std::size_t line = 0;
  std::vector<std::string> fields;
};

[[noreturn]] void throw_wrong_field_count(const std::string& file,
                                          std::size_t line,
                                          const std::vector<std::string>& header,
                                          const std::vector<std::string>& fields) {
  throw InputError(fmt::format("invalid {} line {}: must have {} fields, has {}", file, line,
                               header.size(), fields.size()));
}

void require_unique_columns(const std::vector<std::string>& header, const std::string& file) {
  for (std::size_t c = 0; c < header.size(); ++c) {
    const auto first = std::find(header.begin(), header.end(), header[c]);
    if (first != header.begin() + static_cast<std::ptrdiff_t>(c)) {
      throw InputError(
          fmt::format("invalid {} column '{}': must appear once in the header (columns {} and {})",
                      file, header[c], first - header.begin() + 1, c + 1));
    }
  }
}

/// The fields of a last line that has no line break, if it is a complete row.
std::optional<std::vector<std::string>> last_line_fields(std::string_view line, std::size_t count) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  try {
    auto fields = split_csv_line(line);
    if (fields.size() == count) return fields;
  } catch (const InputError&) {  // cut inside a quoted field
  }
  return std::nullopt;
}

/// A sweep's own results.csv (results_header()): append-only, so a cut last line is a kill.
bool is_sweep_output(const std::vector<std::string>& header) {
  return header.size() >= 3 && header[0] == "case_id" && header[1] == "status" &&
         header.back() == "error";
}

/// True if two rows hold the same values, timings (machine dependent) aside.
bool same_results(const std::vector<std::string>& header,
                  const std::vector<std::string>& a,
                  const std::vector<std::string>& b) {
  const auto& timing = timing_columns();
  for (std::size_t c = 0; c < header.size(); ++c) {
    if (std::find(timing.begin(), timing.end(), header[c]) != timing.end()) continue;
    if (a[c] != b[c]) return false;
  }
  return true;
}

/// Rows with a case_id seen before: the same values again are dropped with a note; different
/// values for one case are an error (two studies mixed into one file).
std::vector<std::vector<std::string>> without_duplicate_cases(
    const std::vector<std::string>& header,
    std::vector<NumberedRow> rows,
    const std::string& file,
    std::vector<std::string>& notes) {
  std::vector<std::vector<std::string>> kept;
  const auto id_col = std::find(header.begin(), header.end(), "case_id");
  if (id_col == header.end()) {
    for (auto& row : rows) kept.push_back(std::move(row.fields));
    return kept;
  }
  const auto id = static_cast<std::size_t>(id_col - header.begin());
  std::map<std::string, const NumberedRow*> first;
  for (const NumberedRow& row : rows) {
    const auto [it, inserted] = first.emplace(row.fields[id], &row);
    if (inserted) continue;
    if (!same_results(header, it->second->fields, row.fields)) {
      throw InputError(fmt::format(
          "invalid {} line {}: case_id '{}' must appear once (line {} holds other values for it: "
          "two studies in one file?)",
          file, row.line, row.fields[id], it->second->line));
    }
    notes.push_back(
        fmt::format("{} line {}: case_id '{}' repeats line {} (same values): counted "
                    "once",
                    file, row.line, row.fields[id], it->second->line));
  }
  for (auto& row : rows) {
    if (first.at(row.fields[id]) == &row) kept.push_back(std::move(row.fields));
  }
  return kept;
}

/// The header and the rows of `lines` to keep on resume (status in `keep_status`, first row of a
/// case), as text; fills existing.status, .rows and .duplicates_dropped.
std::string kept_rows(const std::filesystem::path& file,
                      const std::vector<std::string_view>& lines,
                      const std::vector<std::string>& keep_status,
                      ExistingResults& existing) {
  const auto& header = existing.header;
  const auto status_col =
      static_cast<std::size_t>(std::find(header.begin(), header.end(), "status") - header.begin());
  std::string kept(lines.front());
  kept += '\n';
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto fields = split_csv_line(lines[i]);
    if (fields.size() != header.size())
      throw_wrong_field_count(file.string(), i + 1, header, fields);
    const std::string& status = fields[status_col];
    if (std::find(keep_status.begin(), keep_status.end(), status) == keep_status.end()) continue;
    if (!existing.status.emplace(fields[0], status).second) {
      ++existing.duplicates_dropped;
      continue;
    }
    ++existing.rows;
    kept += lines[i];
    kept += '\n';
  }
  return kept;
}

}  // namespace

const std::vector<std::string>& result_columns() {
  static const std::vector<std::string> columns = [] {
    std::vector<std::string> names;
    for (const auto& f : fem::result_fields()) {
      if ((f.outputs & fem::kCsv) != 0) names.emplace_back(f.name);
    }
    return names;
  }();
  return columns;
}

const std::vector<std::string>& timing_columns() {
  static const std::vector<std::string> columns = [] {
    std::vector<std::string> names;
    for (const auto& f : fem::result_fields()) {
      if ((f.outputs & fem::kCsv) != 0 && f.machine_dependent) names.emplace_back(f.name);
    }
    return names;
  }();
  return columns;
}

std::vector<std::string> results_header(const std::vector<std::string>& swept_keys) {
  std::vector<std::string> header{"case_id", "status"};
  header.insert(header.end(), swept_keys.begin(), swept_keys.end());
  header.insert(header.end(), result_columns().begin(), result_columns().end());
  header.emplace_back("error");
  return header;
}

std::string format_number(double value) { return fem::field_text(value); }

std::string_view row_status(const fem::ImpactResult* result) {
  if (result == nullptr) return kStatusFailed;
  return result->status == fem::RunStatus::kSeparated ? kStatusOk : fem::to_string(result->status);
}

std::vector<std::string> result_row(std::string_view case_id,
                                    const std::vector<std::string>& swept_values,
                                    const fem::ImpactConfig& config,
                                    const fem::ImpactResult* result,
                                    std::string_view error,
                                    double wall_s) {
  std::vector<std::string> row{std::string(case_id), std::string(row_status(result))};
  row.insert(row.end(), swept_values.begin(), swept_values.end());
  const fem::FieldInput in{result, &config, wall_s};
  for (const auto& f : fem::result_fields()) {
    if ((f.outputs & fem::kCsv) != 0) row.push_back(fem::field_text(f.value(in)));
  }
  row.emplace_back(result != nullptr && error.empty() ? result->status_detail : std::string(error));
  return row;
}

std::string csv_line(const std::vector<std::string>& fields) {
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i > 0) line += ',';
    std::string field = fields[i];
    std::replace(field.begin(), field.end(), '\n', ' ');
    std::replace(field.begin(), field.end(), '\r', ' ');
    if (field.find_first_of(",\"") != std::string::npos ||
        (!field.empty() && (field.front() == ' ' || field.back() == ' '))) {
      line += '"';
      for (const char c : field) {
        if (c == '"') line += '"';
        line += c;
      }
      line += '"';
    } else {
      line += field;
    }
  }
  return line;
}

std::vector<std::string> split_csv_line(std::string_view line) {
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false;
  bool in_quotes = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (in_quotes) {
      if (c == '"') {
        if (i + 1 < line.size() && line[i + 1] == '"') {
          field += '"';
          ++i;
        } else {
          in_quotes = false;
        }
      } else {
        field += c;
      }
    } else if (c == '"' && field.empty() && !quoted) {
      in_quotes = quoted = true;
    } else if (c == ',') {
      fields.push_back(std::move(field));
      field.clear();
      quoted = false;
    } else {
      field += c;
    }
  }
  if (in_quotes) throw_invalid("CSV line", line, "terminated quotes");
  fields.push_back(std::move(field));
  return fields;
}

CsvAppender::CsvAppender(const std::filesystem::path& file, const std::vector<std::string>& header)
    : file_(file) {
  fd_ = ::open(file.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    throw InputError(fmt::format("invalid output file = '{}': must be writable ({})", file.string(),
                                 std::strerror(errno)));
  }
  if (::lseek(fd_, 0, SEEK_END) == 0) append(header);
}

CsvAppender::~CsvAppender() {
  if (fd_ >= 0) ::close(fd_);
}

void CsvAppender::append(const std::vector<std::string>& fields) { append_line(csv_line(fields)); }

void CsvAppender::append_line(std::string_view line) {
  std::string data(line);
  data += '\n';
  write_all(fd_, data, file_);
  ::fsync(fd_);
}

ExistingResults prepare_resume(const std::filesystem::path& file,
                               const std::vector<std::string>& expected_header,
                               const std::vector<std::string>& keep_status) {
  ExistingResults existing;
  if (!std::filesystem::exists(file)) return existing;
  const std::string text = read_file(file, false);
  std::string_view partial;
  auto lines = complete_lines(text, partial);
  bool changed = false;
  if (!partial.empty()) {
    // A row whose write stopped just before its line break is complete: keep it (the rewrite
    // below adds the break, so the next append starts a new line). A cut row is dropped.
    changed = true;
    if (!lines.empty() && last_line_fields(partial, expected_header.size())) {
      lines.push_back(partial);
    } else {
      existing.dropped_partial_line = true;
    }
  }
  if (lines.empty()) {
    if (existing.dropped_partial_line) std::filesystem::remove(file);  // killed writing the header
    return existing;
  }
  existing.header = split_csv_line(lines.front());
  if (existing.header != expected_header) {
    throw InputError(fmt::format(
        "invalid output = '{}': must be a results.csv of this spec (its columns differ; use "
        "another --out directory)",
        file.string()));
  }
  const std::string kept = kept_rows(file, lines, keep_status, existing);
  if (changed || existing.rows + 1 != lines.size()) write_file_atomically(file, kept);
  return existing;
}

ResultsTable::ResultsTable(std::vector<std::string> columns,
                           std::vector<std::vector<std::string>> rows)
    : columns_(std::move(columns)), cells_(columns_.size()), rows_(rows.size()) {
  for (auto& column : cells_) column.reserve(rows_);
  for (auto& row : rows) {
    if (row.size() != columns_.size()) {
      throw_invalid("results row", static_cast<double>(row.size()),
                    fmt::format("{} fields (one per column)", columns_.size()));
    }
    for (std::size_t c = 0; c < columns_.size(); ++c) cells_[c].push_back(std::move(row[c]));
  }
}

std::size_t ResultsTable::index_of(std::string_view name) const {
  const auto it = std::find(columns_.begin(), columns_.end(), name);
  if (it == columns_.end()) {
    std::string known;
    for (const auto& c : columns_) known += (known.empty() ? "" : ", ") + c;
    throw_invalid("results column", name, fmt::format("one of {}", known));
  }
  return static_cast<std::size_t>(it - columns_.begin());
}

bool ResultsTable::has_column(std::string_view name) const {
  return std::find(columns_.begin(), columns_.end(), name) != columns_.end();
}

bool ResultsTable::is_numeric(std::string_view name) const {
  if (always_text(name)) return false;
  const auto& cells = cells_[index_of(name)];
  bool any = false;
  for (const auto& cell : cells) {
    if (cell.empty()) continue;
    if (!parse_double(cell)) return false;
    any = true;
  }
  return any;
}

std::vector<double> ResultsTable::numbers(std::string_view name) const {
  const auto& cells = cells_[index_of(name)];
  std::vector<double> values(cells.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (cells[i].empty()) continue;
    const std::optional<double> value = parse_double(cells[i]);
    if (!value) {
      throw_invalid(fmt::format("results column {} row {}", name, i + 1), cells[i], "a number");
    }
    values[i] = *value;
  }
  return values;
}

const std::vector<std::string>& ResultsTable::text(std::string_view name) const {
  return cells_[index_of(name)];
}

const std::string& ResultsTable::cell(std::size_t row, std::string_view name) const {
  return cells_[index_of(name)].at(row);
}

ResultsTable ResultsTable::where(std::string_view column, std::string_view value) const {
  const auto& key = cells_[index_of(column)];
  std::vector<std::vector<std::string>> rows;
  for (std::size_t r = 0; r < rows_; ++r) {
    if (key[r] != value) continue;
    std::vector<std::string> row;
    for (const auto& c : cells_) row.push_back(c[r]);
    rows.push_back(std::move(row));
  }
  return {columns_, std::move(rows)};
}

ResultsTable ResultsTable::sorted_by(std::string_view column) const {
  const auto& key = cells_[index_of(column)];
  std::vector<std::size_t> order(rows_);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&key](std::size_t a, std::size_t b) { return key[a] < key[b]; });
  std::vector<std::vector<std::string>> rows;
  for (const std::size_t r : order) {
    std::vector<std::string> row;
    for (const auto& c : cells_) row.push_back(c[r]);
    rows.push_back(std::move(row));
  }
  return {columns_, std::move(rows)};
}

ResultsTable read_results(const std::filesystem::path& csv) {
  const std::string text = read_file(csv);
  std::string_view partial;
  const auto lines = complete_lines(text, partial);
  if (lines.empty() && partial.empty()) {
    throw_invalid("results file", csv.string(), "a CSV file with a header line");
  }
  const std::string name = csv.string();
  std::vector<std::string> header = split_csv_line(lines.empty() ? partial : lines.front());
  require_unique_columns(header, name);
  std::vector<std::string> notes;
  std::vector<NumberedRow> rows;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].empty()) continue;
    auto fields = split_csv_line(lines[i]);
    if (fields.size() != header.size()) throw_wrong_field_count(name, i + 1, header, fields);
    rows.push_back({i + 1, std::move(fields)});
  }
  if (!lines.empty() && !partial.empty()) {
    // No line break at the end: a complete row is data; a cut row is damage.
    auto last = last_line_fields(partial, header.size());
    if (last) {
      rows.push_back({lines.size() + 1, std::move(*last)});
    } else if (is_sweep_output(header)) {
      notes.push_back(fmt::format(
          "{} line {}: dropped a partial last line (a sweep's results.csv cut while a row was "
          "written; resuming the sweep runs that case again)",
          name, lines.size() + 1));
    } else {
      throw InputError(fmt::format(
          "invalid {} line {}: must be a complete row of {} fields (the file ends in a cut line)",
          name, lines.size() + 1, header.size()));
    }
  }
  auto kept = without_duplicate_cases(header, std::move(rows), name, notes);
  ResultsTable table(std::move(header), std::move(kept));
  table.notes_ = std::move(notes);
  return table;
}

}  // namespace corlab::study
