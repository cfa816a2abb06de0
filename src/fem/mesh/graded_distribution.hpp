// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file graded_distribution.hpp
/// 1D node distributions of the generated mesh (docs/theory/mesh.md, "1D graded distribution"):
/// positions <-> sizes, two-sided grading, fractions and their fit to another edge, splitting to a
/// count. The one-sided graded_positions is public (corlab/fem/mesh/mesh_generator.hpp). Private to
/// the mesh generator (src/fem/mesh).

#include <cstddef>
#include <vector>

namespace corlab::fem::meshing {

/// Sizes of a distribution from positions.
std::vector<double> spacings(const std::vector<double>& x);

/// Positions 0, s_0, s_0 + s_1, ... of a distribution from its sizes.
std::vector<double> positions_from_sizes(const std::vector<double>& sizes);

/// Two-sided graded sizes over `length`: starts at s0 (uniform over `uniform_length`), ends at
/// s1, grows by `growth` from both ends up to `cap`.
std::vector<double> two_sided_sizes(
    double length, double s0, double uniform_length, double s1, double growth, double cap);

/// Normalised positions (0..1) of a distribution.
std::vector<double> fractions(const std::vector<double>& x);

/// Normalised positions k / n, k = 0..n, of n uniform intervals (the last exactly 1).
std::vector<double> uniform_fractions(std::size_t n);

/// Positions on an edge of `length` with the same count as `f` (fractions): f scaled, blended
/// towards uniform just enough that no interval is below `min_size` (when possible).
std::vector<double> fit_fractions(const std::vector<double>& f, double length, double min_size);

/// Splits the largest intervals in half until the distribution has `n` intervals.
std::vector<double> split_to_count(const std::vector<double>& x, std::size_t n);

/// Number of leading intervals of size h (the uniform part of a graded distribution).
std::size_t uniform_count(const std::vector<double>& x, double h);

}  // namespace corlab::fem::meshing
