// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/core/output_directory.hpp"

#include <fmt/format.h>

#include <system_error>

#include "corlab/core/error.hpp"

namespace corlab {

void ensure_output_directory(const std::filesystem::path& dir, std::string_view field) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  std::error_code is_dir_ec;
  if (ec || !std::filesystem::is_directory(dir, is_dir_ec)) {
    throw_invalid(field, dir.string(),
                  fmt::format("a directory that can be made ({})",
                              ec ? ec.message() : "it exists and is not a directory"));
  }
}

}  // namespace corlab
