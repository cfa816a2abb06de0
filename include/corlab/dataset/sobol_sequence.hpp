// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file sobol_sequence.hpp
/// Space-filling design: the Sobol low-discrepancy sequence (GSL gsl_qrng_sobol, Bratley & Fox
/// 1988 direction numbers) with its first point, the origin, which GSL leaves out. With the
/// origin the first 2^m points of every coordinate hold exactly one point in each of the 2^m
/// intervals [k 2^-m, (k + 1) 2^-m) (a (t, m, s)-net's one-dimensional projections), so a design
/// of 2^m points is stratified in each input and any prefix of 2^j points is as well.

#include <cstddef>
#include <vector>

namespace corlab::dataset {

/// Largest dimension of the sequence (GSL's limit).
inline constexpr int kSobolMaxDimension = 40;

/// Points index 0 .. count-1 of the Sobol sequence in [0, 1)^dimension, point 0 the origin.
/// Throws InputError for dimension outside [1, kSobolMaxDimension].
std::vector<std::vector<double>> sobol_points(int dimension, std::size_t count);

}  // namespace corlab::dataset
