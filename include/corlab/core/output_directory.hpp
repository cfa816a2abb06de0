// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file output_directory.hpp
/// A command's output directory, made or refused in one line.

#include <filesystem>
#include <string_view>

namespace corlab {

/// Creates `dir` and its parents if missing. Throws InputError naming `field` (e.g. "--out") when
/// it cannot be made or is not a directory (an existing file, /dev/null, a path under /proc).
void ensure_output_directory(const std::filesystem::path& dir, std::string_view field);

}  // namespace corlab
