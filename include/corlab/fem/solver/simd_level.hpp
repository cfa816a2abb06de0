// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file simd_level.hpp
/// The instruction set the solver's hot loops (element loop, nodal update) run with. They are
/// compiled for the x86-64 baseline, x86-64-v3 (AVX2, FMA) and x86-64-v4 (AVX-512); a run uses the
/// highest level the CPU has unless $CORLAB_SIMD or set_simd_level() picks a lower one. The
/// levels agree to ~1e-11 relative in e (FMA contraction, vector width in the reductions) and
/// are each bit-for-bit reproducible: CORLAB_SIMD=x86-64-v3 gives the same bits on every CPU
/// that has AVX2, which is how a study spread over mixed machines stays comparable and how the
/// golden tests (tests/golden) pin every level. Other compilers and CPUs: the baseline only.

#include <cstdint>
#include <string_view>
#include <vector>

namespace corlab::fem {

enum class SimdLevel : std::uint8_t { kBaseline, kX86_64_V3, kX86_64_V4 };

/// "baseline", "x86-64-v3" or "x86-64-v4" (the names GCC's -march takes).
std::string_view to_string(SimdLevel level);

/// The level named `text` (a to_string name); InputError naming `field` otherwise.
SimdLevel parse_simd_level(std::string_view text, std::string_view field = "CORLAB_SIMD");

/// The levels this build can run on this CPU, lowest first (the baseline always).
std::vector<SimdLevel> supported_simd_levels();

/// The level runs use now: the one set_simd_level() chose, else $CORLAB_SIMD (read once; an
/// unknown or unsupported name is an InputError naming CORLAB_SIMD), else the highest supported.
SimdLevel simd_level();

/// Makes later runs use `level`; InputError if this CPU or build cannot run it. Not for use while
/// a run is in progress (a run reads the level once, when its model is built).
void set_simd_level(SimdLevel level);

}  // namespace corlab::fem
