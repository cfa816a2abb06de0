// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dem/uniform_table.hpp"

#include <cmath>
#include <stdexcept>

#include "corlab/core/error.hpp"

namespace corlab::dem {

UniformTable::UniformTable(double x_min, double x_max, std::vector<double> values)
    : x_min_(x_min), x_max_(x_max), values_(std::move(values)) {
  if (values_.size() < 2) throw_invalid("table size", static_cast<double>(values_.size()), ">= 2");
  if (!(x_max > x_min)) throw_invalid("table x_max", x_max, "> x_min");
  last_ = static_cast<double>(values_.size() - 1);
  inverse_step_ = last_ / (x_max - x_min);
}

UniformTable tabulate(const std::function<double(double)>& f, double x_min, double x_max, int n) {
  if (n < 2) throw_invalid("table points", n, ">= 2");
  std::vector<double> values(static_cast<std::size_t>(n));
  const double step = (x_max - x_min) / (n - 1);
  for (int i = 0; i < n; ++i) values[static_cast<std::size_t>(i)] = f(x_min + i * step);
  return {x_min, x_max, std::move(values)};
}

double max_interpolation_error(const UniformTable& table, const std::function<double(double)>& f) {
  const std::size_t n = table.values().size();
  const double step = (table.x_max() - table.x_min()) / static_cast<double>(n - 1);
  double worst = 0.0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    for (const double frac : {0.25, 0.5, 0.75}) {
      const double x = table.x_min() + (static_cast<double>(i) + frac) * step;
      worst = std::max(worst, std::abs(table(x) - f(x)));
    }
  }
  return worst;
}

}  // namespace corlab::dem
