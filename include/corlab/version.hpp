#pragma once
/// @file version.hpp
#include <string_view>

namespace corlab {
inline constexpr std::string_view kVersion = "0.1.0";
}  // namespace corlab
