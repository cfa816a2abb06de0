#pragma once
/// @file simd_variants.hpp
/// One hot loop compiled for each SimdLevel (simd_level.hpp), chosen per call. Private to the
/// solver. CORLAB_SIMD_VARIANTS(ret, name, params, args) defines `ret name(SimdLevel level,
/// <params>)`, which runs `name_body args` compiled for `level`: the body, an always-inline
/// function, is inlined into one function per instruction set (what GCC's target_clones does, but
/// with the level chosen by the caller instead of by the loader, so that every level can be run,
/// compared and pinned on one machine).

#include "corlab/fem/solver/simd_level.hpp"

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && __GNUC__ >= 12
#define CORLAB_SIMD_VARIANTS_X86 1
#else
#define CORLAB_SIMD_VARIANTS_X86 0
#endif

#if CORLAB_SIMD_VARIANTS_X86
#define CORLAB_SIMD_VARIANTS(ret, name, params, args)                    \
  [[gnu::target("arch=x86-64-v4")]] static ret name##_x86_64_v4 params { \
    return name##_body args;                                             \
  }                                                                      \
  [[gnu::target("arch=x86-64-v3")]] static ret name##_x86_64_v3 params { \
    return name##_body args;                                             \
  }                                                                      \
  static ret name##_baseline params { return name##_body args; }         \
  ret name(SimdLevel level, CORLAB_SIMD_UNPAREN params) {                \
    switch (level) {                                                     \
      case SimdLevel::kX86_64_V4:                                        \
        return name##_x86_64_v4 args;                                    \
      case SimdLevel::kX86_64_V3:                                        \
        return name##_x86_64_v3 args;                                    \
      case SimdLevel::kBaseline:                                         \
        break;                                                           \
    }                                                                    \
    return name##_baseline args;                                         \
  }
#else
#define CORLAB_SIMD_VARIANTS(ret, name, params, args) \
  ret name(SimdLevel, CORLAB_SIMD_UNPAREN params) { return name##_body args; }
#endif
// CORLAB_SIMD_UNPAREN (a, b) -> a, b: a parenthesised parameter list without its parentheses.
#define CORLAB_SIMD_UNPAREN(...) __VA_ARGS__
