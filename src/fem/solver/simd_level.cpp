// The hot loops' instruction-set level (simd_level.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/simd_level.hpp"

#include <fmt/format.h>

#include <array>
#include <atomic>
#include <cstdlib>
#include <string>
#include <utility>

#include "corlab/core/error.hpp"
#include "fem/solver/simd_variants.hpp"

namespace corlab::fem {
namespace {

constexpr std::array<std::pair<SimdLevel, std::string_view>, 3> kNames{{
    {SimdLevel::kBaseline, "baseline"},
    {SimdLevel::kX86_64_V3, "x86-64-v3"},
    {SimdLevel::kX86_64_V4, "x86-64-v4"},
}};

/// Whether this CPU has what GCC's -march=<level> assumes (the same tests as GCC's own
/// target_clones resolver).
bool cpu_has(SimdLevel level) {
#if CORLAB_SIMD_VARIANTS_X86
  switch (level) {
    case SimdLevel::kBaseline:
      return true;
    case SimdLevel::kX86_64_V3:
      return __builtin_cpu_supports("x86-64-v3");
    case SimdLevel::kX86_64_V4:
      return __builtin_cpu_supports("x86-64-v4");
  }
  return false;
#else
  return level == SimdLevel::kBaseline;
#endif
}

std::string supported_names() {
  std::string out;
  for (SimdLevel l : supported_simd_levels()) {
    if (!out.empty()) out += ", ";
    out += to_string(l);
  }
  return out;
}

/// The chosen level, -1 until the first simd_level() or set_simd_level().
std::atomic<int> g_level{-1};

SimdLevel initial_level() {
  if (const char* env = std::getenv("CORLAB_SIMD"); env != nullptr && *env != '\0') {
    const SimdLevel level = parse_simd_level(env);
    if (!cpu_has(level)) {
      throw_invalid("CORLAB_SIMD", env, fmt::format("one this CPU runs: {}", supported_names()));
    }
    return level;
  }
  return supported_simd_levels().back();
}

}  // namespace

std::string_view to_string(SimdLevel level) {
  for (const auto& [l, name] : kNames) {
    if (l == level) return name;
  }
  return "baseline";
}

SimdLevel parse_simd_level(std::string_view text, std::string_view field) {
  for (const auto& [l, name] : kNames) {
    if (name == text) return l;
  }
  throw_invalid(field, text, "one of baseline, x86-64-v3, x86-64-v4");
}

std::vector<SimdLevel> supported_simd_levels() {
  std::vector<SimdLevel> out;
  for (const auto& [l, name] : kNames) {
    if (cpu_has(l)) out.push_back(l);
  }
  return out;
}

SimdLevel simd_level() {
  int level = g_level.load(std::memory_order_relaxed);
  if (level < 0) {
    level = static_cast<int>(initial_level());
    g_level.store(level, std::memory_order_relaxed);
  }
  return static_cast<SimdLevel>(level);
}

void set_simd_level(SimdLevel level) {
  if (!cpu_has(level)) {
    throw_invalid("simd level", to_string(level),
                  fmt::format("one this CPU runs: {}", supported_names()));
  }
  g_level.store(static_cast<int>(level), std::memory_order_relaxed);
}

}  // namespace corlab::fem
