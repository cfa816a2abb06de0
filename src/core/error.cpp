// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/core/error.hpp"

#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "corlab/core/escaped_text.hpp"
#include "corlab/core/text_file.hpp"

namespace corlab {

namespace {
/// Longest user value shown in a message [bytes]; a longer one is cut with its length said.
constexpr std::size_t kMaxShownValueBytes = 160;

// User text in a message is shown with its control characters and any byte that is not UTF-8
// escaped, so the message stays one line of valid text whatever the input holds (found by fuzzing
// the inline material parser; a non-UTF-8 byte broke `corlab fit --json`).
std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x80) {
      // a whole valid UTF-8 character is kept, a stray byte escaped
      const std::size_t len = u >= 0xF0 ? 4 : u >= 0xE0 ? 3 : 2;
      const std::string_view ch = text.substr(i, len);
      if (ch.size() == len && invalid_utf8_offset(ch) == std::string_view::npos) {
        out += ch;
        i += len;
        continue;
      }
      out += fmt::format("\\x{:02x}", u);
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (u < 0x20 || u == 0x7f) {
      out += fmt::format("\\x{:02x}", u);
    } else {
      out += c;
    }
    ++i;
  }
  return out;
}

// A value as shown: printable, and a long one (a 1 MB material name) cut to its first bytes.
std::string shown_value(std::string_view value) {
  if (value.size() <= kMaxShownValueBytes) return printable(value);
  std::size_t cut = kMaxShownValueBytes;
  while (cut > 0 && (static_cast<unsigned char>(value[cut]) & 0xC0) == 0x80) --cut;  // whole chars
  return fmt::format("{}... ({} bytes)", printable(value.substr(0, cut)), value.size());
}
}  // namespace

std::string message_text(std::string_view value) { return shown_value(value); }

std::string escaped_text(std::string_view value) { return printable(value); }

InputError::InputError(std::string field, std::string value, std::string constraint, bool quoted)
    : std::invalid_argument(quoted ? fmt::format("invalid {} = '{}': must be {}",
                                                 printable(field),
                                                 shown_value(value),
                                                 printable(constraint))
                                   : fmt::format("invalid {} = {}: must be {}",
                                                 printable(field),
                                                 shown_value(value),
                                                 printable(constraint))),
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
