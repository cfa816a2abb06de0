// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file escaped_text.hpp
/// User text echoed into a generated file (a comment of a spec): one line of valid UTF-8.

#include <string>
#include <string_view>

namespace corlab {

/// `value` as one line of valid UTF-8 text, whole: message_text's escapes (error.hpp) without its
/// cut, i.e. control characters and bytes that are not UTF-8 written \n, \r, \x1b, \xff.
std::string escaped_text(std::string_view value);

}  // namespace corlab
