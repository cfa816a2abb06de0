// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file version.hpp
#include <string_view>

namespace corlab {
inline constexpr std::string_view kVersion = "0.11.0";
/// The build: kVersion + "+git." + `git describe --always --dirty` of the source tree at build
/// time ("unknown" outside a git checkout), e.g. "0.2.0+git.b5fe1b3a1c2d-dirty". Provenance of
/// every result row (result field `corlab_build`).
std::string_view build_id();
}  // namespace corlab
