// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/core/atomic_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <system_error>

namespace corlab {

void write_all(int fd, std::string_view data, const std::filesystem::path& file) {
  while (!data.empty()) {
    const ssize_t written = ::write(fd, data.data(), data.size());
    if (written < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(
          fmt::format("cannot write {}: {}", file.string(), std::strerror(errno)));
    }
    data.remove_prefix(static_cast<std::size_t>(written));
  }
}

namespace {

// Writes `text` to the open temporary `fd`, syncs and closes it, renames it over `file`; the
// temporary is removed when any of it fails.
void replace_with(int fd,
                  const std::filesystem::path& temp,
                  const std::filesystem::path& file,
                  std::string_view text) {
  std::error_code ignored;
  try {
    write_all(fd, text, temp);
  } catch (...) {
    ::close(fd);
    std::filesystem::remove(temp, ignored);
    throw;
  }
  const bool synced = ::fsync(fd) == 0;
  const int sync_errno = errno;
  const bool closed = ::close(fd) == 0;
  if (!synced || !closed) {
    std::filesystem::remove(temp, ignored);
    throw std::runtime_error(fmt::format("cannot write {}: {}", temp.string(),
                                         std::strerror(synced ? errno : sync_errno)));
  }
  std::error_code ec;
  std::filesystem::rename(temp, file, ec);
  if (ec) {
    std::filesystem::remove(temp, ignored);
    throw std::runtime_error(fmt::format("cannot write {}: {}", file.string(), ec.message()));
  }
}

}  // namespace

void write_file_atomically(const std::filesystem::path& file, std::string_view text) {
  const std::filesystem::path temp = file.string() + ".tmp";
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw std::runtime_error(
        fmt::format("cannot write {}: {}", temp.string(), std::strerror(errno)));
  }
  replace_with(fd, temp, file, text);
}

void write_file_atomically_shared(const std::filesystem::path& file, std::string_view text) {
  std::string name = file.string() + ".tmp.XXXXXX";
  const int fd = ::mkostemp(name.data(), O_CLOEXEC);
  if (fd < 0) {
    throw std::runtime_error(fmt::format("cannot write {}: {}", name, std::strerror(errno)));
  }
  ::fchmod(fd, 0644);  // mkostemp makes it 0600; the file replaced may be read by others
  replace_with(fd, name, file, text);
}

}  // namespace corlab
