// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// InputError checks shared by the unit tests.
#include <gtest/gtest.h>

#include <string>

#include "corlab/core/error.hpp"

namespace corlab::test {

/// The message of the InputError that `f` throws; "" if it throws none.
template <class F>
std::string input_error_message(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// Expects `f` to throw an InputError whose message is exactly `message`.
template <class F>
void expect_input_error(F&& f, const std::string& message) {
  try {
    f();
    ADD_FAILURE() << "no InputError; expected: " << message;
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

}  // namespace corlab::test
