// Bounded, checked reading of input files (text_file.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/core/text_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "corlab/core/error.hpp"

namespace corlab {
namespace {

constexpr std::string_view kBom = "\xEF\xBB\xBF";

/// "a directory", "a character device" ...: what a non-regular file is, for the message.
const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

/// Closes the descriptor on every path out.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

[[noreturn]] void refuse(const std::filesystem::path& file,
                         std::string_view what,
                         std::string_view constraint) {
  throw_invalid(what, file.string(), constraint);
}

/// A path with a NUL byte names another file (the system reads it up to the NUL: "/tmp\0x" was
/// read as the directory /tmp); refused as such.
void require_no_nul(const std::filesystem::path& file, std::string_view what) {
  if (const auto nul = file.native().find('\0'); nul != std::string::npos) {
    refuse(file, what, fmt::format("a path without a NUL byte (byte {} is NUL)", nul));
  }
}

/// The 1-based line of byte `offset` of `text`.
std::size_t line_of(std::string_view text, std::size_t offset) {
  return 1 + static_cast<std::size_t>(std::count(
                 text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

std::string too_long(std::size_t max_bytes) {
  return fmt::format("at most {} long (the cap of this input)", byte_size_text(max_bytes));
}

}  // namespace

std::string byte_size_text(std::size_t bytes) {
  constexpr std::size_t kMiB = std::size_t{1} << 20;
  if (bytes >= kMiB && bytes % kMiB == 0) return fmt::format("{} MiB", bytes / kMiB);
  return fmt::format("{} bytes", bytes);
}

std::size_t invalid_utf8_offset(std::string_view text) {
  const auto* s = reinterpret_cast<const unsigned char*>(text.data());
  const std::size_t n = text.size();
  std::size_t i = 0;
  while (i < n) {
    const unsigned c = s[i];
    if (c < 0x80) {
      ++i;
      continue;
    }
    std::size_t len = 0;
    unsigned lo = 0x80;  // the allowed range of the second byte (no overlong form, no surrogate)
    unsigned hi = 0xBF;
    if (c >= 0xC2 && c <= 0xDF) {
      len = 2;
    } else if (c >= 0xE0 && c <= 0xEF) {
      len = 3;
      if (c == 0xE0) lo = 0xA0;
      if (c == 0xED) hi = 0x9F;
    } else if (c >= 0xF0 && c <= 0xF4) {
      len = 4;
      if (c == 0xF0) lo = 0x90;
      if (c == 0xF4) hi = 0x8F;
    } else {
      return i;
    }
    if (i + len > n || s[i + 1] < lo || s[i + 1] > hi) return i;
    for (std::size_t k = 2; k < len; ++k) {
      if (s[i + k] < 0x80 || s[i + k] > 0xBF) return i;
    }
    i += len;
  }
  return std::string_view::npos;
}

std::string read_text_file(const std::filesystem::path& file,
                           std::string_view what,
                           const TextFileRules& rules) {
  require_no_nul(file, what);
  // O_NONBLOCK: opening a FIFO without a writer must not wait for one (it reads as empty).
  const Fd in{::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK)};
  if (in.fd < 0) {
    refuse(file, what, fmt::format("a readable file ({})", std::strerror(errno)));
  }
  struct stat st {};
  if (::fstat(in.fd, &st) != 0) {
    refuse(file, what, fmt::format("a readable file ({})", std::strerror(errno)));
  }
  const bool regular = S_ISREG(st.st_mode);
  if (!regular && !S_ISFIFO(st.st_mode)) {
    refuse(file, what, fmt::format("a regular file or a pipe (it is {})", kind_of(st.st_mode)));
  }
  if (regular && static_cast<std::uintmax_t>(st.st_size) > rules.max_bytes) {
    refuse(file, what, too_long(rules.max_bytes));
  }
  ::fcntl(in.fd, F_SETFL, ::fcntl(in.fd, F_GETFL) & ~O_NONBLOCK);
  std::string text;
  text.reserve(regular ? static_cast<std::size_t>(st.st_size) : std::size_t{1} << 16);
  char buffer[1 << 16];
  while (true) {
    const ssize_t got = ::read(in.fd, buffer, sizeof buffer);
    if (got < 0) {
      if (errno == EINTR) continue;
      refuse(file, what, fmt::format("a readable file ({})", std::strerror(errno)));
    }
    if (got == 0) break;
    // A file that grows while it is read (or a pipe) is held to the cap as it is read.
    if (text.size() + static_cast<std::size_t>(got) > rules.max_bytes) {
      refuse(file, what, too_long(rules.max_bytes));
    }
    text.append(buffer, static_cast<std::size_t>(got));
  }
  if (text.starts_with(kBom)) text.erase(0, kBom.size());
  if (rules.utf8) {
    if (const auto nul = text.find('\0'); nul != std::string::npos) {
      refuse(file, what, fmt::format("a text file (line {} holds a NUL byte)", line_of(text, nul)));
    }
    if (const auto bad = invalid_utf8_offset(text); bad != std::string_view::npos) {
      refuse(file, what,
             fmt::format("UTF-8 text (line {}: byte 0x{:02x} is not valid UTF-8)",
                         line_of(text, bad), static_cast<unsigned char>(text[bad])));
    }
  }
  return text;
}

void require_regular_file(const std::filesystem::path& file,
                          std::string_view what,
                          std::size_t max_bytes) {
  require_no_nul(file, what);
  struct stat st {};
  if (::stat(file.c_str(), &st) != 0) {
    refuse(file, what, fmt::format("a readable file ({})", std::strerror(errno)));
  }
  if (!S_ISREG(st.st_mode)) {
    refuse(file, what,
           fmt::format("a regular file (it is {})",
                       S_ISFIFO(st.st_mode) ? "a pipe" : kind_of(st.st_mode)));
  }
  if (static_cast<std::uintmax_t>(st.st_size) > max_bytes) refuse(file, what, too_long(max_bytes));
}

}  // namespace corlab
