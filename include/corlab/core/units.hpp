// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file units.hpp
/// corlab works in SI units everywhere: m, kg, s, N, Pa, J. Every physical field documents its
/// unit in its doc comment (`double yield_stress; ///< [Pa]`). The only conversions happen where
/// text is read or written, with these named factors.

namespace corlab::units {

inline constexpr double kMilli = 1e-3;  ///< mm -> m, ms -> s
inline constexpr double kMicro = 1e-6;  ///< um -> m, us -> s
inline constexpr double kMega = 1e6;    ///< MPa -> Pa
inline constexpr double kGiga = 1e9;    ///< GPa -> Pa
inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDegree = kPi / 180.0;  ///< deg -> rad (an angle in degrees x kDegree)

}  // namespace corlab::units
