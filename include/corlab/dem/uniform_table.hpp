// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file uniform_table.hpp
/// Piecewise-linear table on a uniform grid, for nanosecond evaluation of chi(e) or e(v) inside a
/// DEM loop. Outside [x_min, x_max] the end values are returned (documented clamp).
/// Interpolation error of a C2 function: <= h^2/8 max|f''| (measured: max_interpolation_error).

#include <algorithm>
#include <functional>
#include <vector>

namespace corlab::dem {

class UniformTable {
 public:
  UniformTable() = default;
  /// values[i] = f(x_min + i h), h = (x_max - x_min)/(n - 1), n >= 2.
  UniformTable(double x_min, double x_max, std::vector<double> values);

  /// Linear interpolation; clamps x to [x_min, x_max]. No allocation, no branch on NaN-free input.
  double operator()(double x) const noexcept {
    const double s = std::clamp((x - x_min_) * inverse_step_, 0.0, last_);
    const auto i = static_cast<std::size_t>(s);
    const std::size_t j = std::min(i, values_.size() - 2);
    const double w = s - static_cast<double>(j);
    return values_[j] + w * (values_[j + 1] - values_[j]);
  }

  double x_min() const { return x_min_; }
  double x_max() const { return x_max_; }
  const std::vector<double>& values() const { return values_; }

 private:
  double x_min_ = 0.0;
  double x_max_ = 1.0;
  double inverse_step_ = 1.0;
  double last_ = 1.0;
  std::vector<double> values_{0.0, 0.0};
};

/// Samples f at n >= 2 uniform points of [x_min, x_max].
UniformTable tabulate(const std::function<double(double)>& f, double x_min, double x_max, int n);

/// Largest |table(x) - f(x)| over the midpoints of every interval and 3 interior points each.
double max_interpolation_error(const UniformTable& table, const std::function<double(double)>& f);

}  // namespace corlab::dem
