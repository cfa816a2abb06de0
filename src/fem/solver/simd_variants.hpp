// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file simd_variants.hpp
/// One hot loop compiled for each SimdLevel (simd_level.hpp), chosen per call. Private to the
/// solver. CORLAB_SIMD_VARIANTS(ret, name, params, names, body) defines
///   ret name(SimdLevel level, <params>)
/// which evaluates `body` (a call of an always-inline function, in terms of the parameters, whose
/// parenthesised names are `names`) compiled for `level`: the body is inlined into one function
/// per instruction set. That is what GCC's target_clones does, but with the level chosen by the
/// caller instead of by the loader, so that every level can be run, compared and pinned on one
/// machine. `body` may name the variant's level as the constant kSimdLevel (to choose code that
/// only one level runs well).

#include "corlab/fem/solver/simd_level.hpp"

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && __GNUC__ >= 12
#define CORLAB_SIMD_VARIANTS_X86 1
#else
#define CORLAB_SIMD_VARIANTS_X86 0
#endif

// CORLAB_SIMD_UNPAREN (a, b) -> a, b: a parenthesised parameter list without its parentheses.
#define CORLAB_SIMD_UNPAREN(...) __VA_ARGS__

#if CORLAB_SIMD_VARIANTS_X86
#define CORLAB_SIMD_VARIANTS(ret, name, params, names, body)                 \
  [[gnu::target("arch=x86-64-v4")]] static ret name##_x86_64_v4 params {     \
    [[maybe_unused]] constexpr SimdLevel kSimdLevel = SimdLevel::kX86_64_V4; \
    return body;                                                             \
  }                                                                          \
  [[gnu::target("arch=x86-64-v3")]] static ret name##_x86_64_v3 params {     \
    [[maybe_unused]] constexpr SimdLevel kSimdLevel = SimdLevel::kX86_64_V3; \
    return body;                                                             \
  }                                                                          \
  static ret name##_baseline params {                                        \
    [[maybe_unused]] constexpr SimdLevel kSimdLevel = SimdLevel::kBaseline;  \
    return body;                                                             \
  }                                                                          \
  ret name(SimdLevel level, CORLAB_SIMD_UNPAREN params) {                    \
    switch (level) {                                                         \
      case SimdLevel::kX86_64_V4:                                            \
        return name##_x86_64_v4 names;                                       \
      case SimdLevel::kX86_64_V3:                                            \
        return name##_x86_64_v3 names;                                       \
      case SimdLevel::kBaseline:                                             \
        break;                                                               \
    }                                                                        \
    return name##_baseline names;                                            \
  }
#else
#define CORLAB_SIMD_VARIANTS(ret, name, params, names, body)                \
  ret name(SimdLevel, CORLAB_SIMD_UNPAREN params) {                         \
    [[maybe_unused]] constexpr SimdLevel kSimdLevel = SimdLevel::kBaseline; \
    return body;                                                            \
  }
#endif
