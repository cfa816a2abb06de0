// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file hash.hpp
/// A stable text hash: the same value for the same bytes on every platform, build and run
/// (std::hash promises none of that). For names derived from content (sweep case ids, result
/// cache files); not for security.

#include <cstdint>
#include <string_view>

namespace corlab {

/// FNV-1a, 64 bit, of `text`, continuing from `hash` (feed several pieces in turn).
constexpr std::uint64_t fnv1a64(std::string_view text,
                                std::uint64_t hash = 14695981039346656037ULL) {
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ULL;
  }
  return hash;
}

}  // namespace corlab
