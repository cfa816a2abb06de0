// The hot loops' instruction-set level (simd_level.hpp): names, the supported list, selection.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/simd_level.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

#include "corlab/core/error.hpp"

namespace corlab::fem {
namespace {

TEST(SimdLevel, NamesRoundTripAndAnUnknownNameIsAnInputError) {
  for (const SimdLevel l : {SimdLevel::kBaseline, SimdLevel::kX86_64_V3, SimdLevel::kX86_64_V4}) {
    EXPECT_EQ(parse_simd_level(to_string(l)), l);
  }
  EXPECT_EQ(to_string(SimdLevel::kX86_64_V3), "x86-64-v3");
  try {
    parse_simd_level("avx512", "CORLAB_SIMD");
    FAIL() << "accepted avx512";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "CORLAB_SIMD");
    EXPECT_EQ(e.value(), "avx512");
  }
}

TEST(SimdLevel, TheBaselineIsAlwaysSupportedAndEachSupportedLevelCanBeSet) {
  const std::vector<SimdLevel> levels = supported_simd_levels();
  ASSERT_FALSE(levels.empty());
  EXPECT_EQ(levels.front(), SimdLevel::kBaseline);
  const SimdLevel before = simd_level();
  const char* env = std::getenv("CORLAB_SIMD");
  EXPECT_EQ(before, env != nullptr && *env != '\0' ? parse_simd_level(env) : levels.back())
      << "the default: $CORLAB_SIMD, else the highest level";
  for (const SimdLevel l : levels) {
    set_simd_level(l);
    EXPECT_EQ(simd_level(), l);
  }
  // A level the CPU lacks is refused (only testable on a CPU that lacks one).
  if (levels.back() != SimdLevel::kX86_64_V4) {
    EXPECT_THROW(set_simd_level(SimdLevel::kX86_64_V4), InputError);
  }
  set_simd_level(before);
}

}  // namespace
}  // namespace corlab::fem
