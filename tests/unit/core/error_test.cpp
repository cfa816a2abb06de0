// InputError messages: one line naming field, value and constraint.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/core/error.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "support/input_errors.hpp"

namespace corlab {
namespace {

using test::input_error_message;

TEST(InputError, NamesFieldValueAndConstraint) {
  const std::string msg = input_error_message([] { require_positive("sphere.E", -2e11, "[Pa]"); });
  EXPECT_EQ(msg, "invalid sphere.E = -200000000000: must be > 0 [Pa]");
  EXPECT_EQ(msg.find('\n'), std::string::npos);
}

TEST(InputError, RejectsNonFiniteValues) {
  EXPECT_THROW(require_positive("v", std::numeric_limits<double>::quiet_NaN()), InputError);
  EXPECT_THROW(require_positive("v", std::numeric_limits<double>::infinity()), InputError);
  EXPECT_THROW(require_non_negative("h", -1e-300), InputError);
  EXPECT_NO_THROW(require_non_negative("h", 0.0));
}

TEST(InputError, RangesAreOpenOrClosedAsNamed) {
  EXPECT_THROW(require_open_range("nu", 0.5, -1.0, 0.5), InputError);
  EXPECT_NO_THROW(require_closed_range("x", 0.5, -1.0, 0.5));
  EXPECT_EQ(input_error_message([] { require_open_range("substrate.nu", 0.7, -1.0, 0.5); }),
            "invalid substrate.nu = 0.7: must be in (-1, 0.5)");
}

TEST(InputError, ALongValueIsCutAndABadByteEscaped) {
  // issue 31 item 11: an unknown 1 MB material name was echoed whole.
  const std::string huge(1'000'000, 'x');
  const std::string msg =
      input_error_message([&] { throw_invalid("sphere.material", huge, "known"); });
  EXPECT_EQ(msg, "invalid sphere.material = '" + std::string(160, 'x') +
                     "... (1000000 bytes)': must be known");
  // a non-UTF-8 byte is escaped (it broke `fit --json`), a whole UTF-8 character kept
  EXPECT_EQ(input_error_message([] { throw_invalid("status", "fa\xFFil \xC3\xA9", "ok"); }),
            "invalid status = 'fa\\xffil \xC3\xA9': must be ok");
  EXPECT_EQ(message_text(std::string(158, 'a') + "\xC3\xA9\xC3\xA9"),
            std::string(158, 'a') + "\xC3\xA9... (162 bytes)");  // cut between characters
}

TEST(InputError, TextValuesAreQuoted) {
  EXPECT_EQ(input_error_message([] { throw_invalid("model", "foo", "one of [a, b]"); }),
            "invalid model = 'foo': must be one of [a, b]");
}

TEST(InputError, CarriesFieldValueAndConstraintAsData) {
  try {
    require_positive("impact.velocity", -1.5, "[m/s]");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "impact.velocity");
    EXPECT_EQ(e.value(), "-1.5");
    EXPECT_EQ(e.constraint(), "> 0 [m/s]");
    EXPECT_STREQ(e.what(), "invalid impact.velocity = -1.5: must be > 0 [m/s]");
  }
  try {
    throw_invalid("model", "Nope", "one of A, B");
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "model");
    EXPECT_EQ(e.value(), "Nope");  // without the quotes of the message
    EXPECT_STREQ(e.what(), "invalid model = 'Nope': must be one of A, B");
  }
  const InputError free_form("gmsh support not built");
  EXPECT_TRUE(free_form.field().empty() && free_form.value().empty());
  EXPECT_TRUE(free_form.constraint().empty());
}

}  // namespace
}  // namespace corlab
