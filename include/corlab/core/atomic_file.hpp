// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file atomic_file.hpp
/// Crash-safe file replacement: the file holds either its old or its new content, never a part.

#include <filesystem>
#include <string_view>

namespace corlab {

/// Replaces `file` by `text`: writes `<file>.tmp`, syncs it to disk (fsync), renames it over
/// `file`. A kill at any point leaves the old file (or none) or the new one. Throws
/// std::runtime_error naming the file if it cannot be written.
void write_file_atomically(const std::filesystem::path& file, std::string_view text);

/// The same for a file that other processes may replace at the same time (a result cache
/// entry): the temporary is unique (`<file>.tmp.XXXXXX`), so concurrent writers never share one;
/// the last rename wins and every reader sees one writer's whole file. A failed write removes
/// its temporary.
void write_file_atomically_shared(const std::filesystem::path& file, std::string_view text);

/// Writes all of `data` to the open descriptor `fd` (retries short writes and EINTR). Throws
/// std::runtime_error naming `file` on failure.
void write_all(int fd, std::string_view data, const std::filesystem::path& file);

}  // namespace corlab
