// 1D node distributions: one- and two-sided grading, fractions, fitting and splitting.
// SPDX-License-Identifier: BSD-3-Clause
#include "fem/mesh/graded_distribution.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "corlab/fem/mesh/mesh_generator.hpp"

namespace corlab::fem::meshing {
namespace {

/// Rescales the sizes flagged `graded` so that the total is `length`; when none is graded, all.
void fit_length(std::vector<double>& sizes, const std::vector<bool>& graded, double length) {
  double fixed = 0.0;
  double free = 0.0;
  for (std::size_t i = 0; i < sizes.size(); ++i) (graded[i] ? free : fixed) += sizes[i];
  if (free <= 0.0 || fixed >= length) {
    const double f = length / (fixed + free);
    for (double& s : sizes) s *= f;
    return;
  }
  const double f = (length - fixed) / free;
  for (std::size_t i = 0; i < sizes.size(); ++i)
    if (graded[i]) sizes[i] *= f;
}

/// Grows sizes from `start` (uniform for `uniform_length`) by `growth` up to `cap`; appends to
/// `sizes` until their sum reaches `target`.
void grow_sizes(double start,
                double uniform_length,
                double growth,
                double cap,
                double target,
                std::vector<double>& sizes,
                std::vector<bool>& graded) {
  double x = 0.0;
  double s = start;
  while (x < target * (1.0 - 1e-12)) {
    const bool uniform = x + 0.5 * start < uniform_length;
    if (!uniform) s = std::max(start, std::min(s * growth, cap));
    sizes.push_back(uniform ? start : s);
    graded.push_back(!uniform);
    x += sizes.back();
  }
}

/// Picks between keeping the last (overshooting) size and dropping it, so that the rescaling of
/// the graded part is closest to 1, then rescales.
std::vector<double> close_distribution(std::vector<double> sizes,
                                       std::vector<bool> graded,
                                       double length) {
  auto factor = [&](std::size_t n) {
    double fixed = 0.0;
    double free = 0.0;
    for (std::size_t i = 0; i < n; ++i) (graded[i] ? free : fixed) += sizes[i];
    if (free <= 0.0 || fixed >= length) return length / (fixed + free);
    return (length - fixed) / free;
  };
  if (sizes.size() > 1) {
    const double keep = factor(sizes.size());
    const double drop = factor(sizes.size() - 1);
    if (std::abs(std::log(drop)) < std::abs(std::log(keep))) {
      sizes.pop_back();
      graded.pop_back();
    }
  }
  fit_length(sizes, graded, length);
  return sizes;
}

}  // namespace

std::vector<double> spacings(const std::vector<double>& x) {
  std::vector<double> s(x.size() - 1);
  for (std::size_t i = 0; i + 1 < x.size(); ++i) s[i] = x[i + 1] - x[i];
  return s;
}

std::vector<double> positions_from_sizes(const std::vector<double>& sizes) {
  std::vector<double> x(sizes.size() + 1, 0.0);
  for (std::size_t i = 0; i < sizes.size(); ++i) x[i + 1] = x[i] + sizes[i];
  return x;
}

std::vector<double> two_sided_sizes(
    double length, double s0, double uniform_length, double s1, double growth, double cap) {
  std::vector<double> left;
  std::vector<double> right;
  std::vector<bool> left_graded;
  double x = 0.0;
  double a = s0;
  double b = s1;
  bool first_right = true;
  while (x < length * (1.0 - 1e-12)) {
    const bool uniform = x + 0.5 * s0 < uniform_length;
    if (uniform) {
      left.push_back(s0);
      left_graded.push_back(false);
      x += s0;
      continue;
    }
    // next candidates
    const double next_a = std::max(s0, std::min(a * growth, cap));
    const double next_b = first_right ? s1 : std::min(b * growth, cap);
    if (next_b <= next_a) {
      right.push_back(next_b);
      b = next_b;
      first_right = false;
      x += next_b;
    } else {
      left.push_back(next_a);
      left_graded.push_back(true);
      a = next_a;
      x += next_a;
    }
  }
  std::vector<double> sizes = left;
  std::vector<bool> graded = left_graded;
  sizes.insert(sizes.end(), right.rbegin(), right.rend());
  graded.insert(graded.end(), right.size(), true);
  // rescale the graded part (dropping one interval if that is closer)
  if (sizes.size() > 2) {
    double fixed = 0.0;
    double free = 0.0;
    for (std::size_t i = 0; i < sizes.size(); ++i) (graded[i] ? free : fixed) += sizes[i];
    // drop the largest graded interval when that makes the factor closer to one
    auto largest = std::max_element(sizes.begin(), sizes.end());
    const std::size_t k = static_cast<std::size_t>(largest - sizes.begin());
    if (graded[k] && free - sizes[k] > 0.0 && fixed < length) {
      const double keep = (length - fixed) / free;
      const double drop = (length - fixed) / (free - sizes[k]);
      if (std::abs(std::log(drop)) < std::abs(std::log(keep))) {
        sizes.erase(sizes.begin() + static_cast<std::ptrdiff_t>(k));
        graded.erase(graded.begin() + static_cast<std::ptrdiff_t>(k));
      }
    }
  }
  fit_length(sizes, graded, length);
  return sizes;
}

std::vector<double> fractions(const std::vector<double>& x) {
  std::vector<double> f(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) f[i] = x[i] / x.back();
  f.back() = 1.0;
  return f;
}

std::vector<double> uniform_fractions(std::size_t n) {
  std::vector<double> f(n + 1);
  for (std::size_t k = 0; k <= n; ++k) f[k] = static_cast<double>(k) / static_cast<double>(n);
  f.back() = 1.0;
  return f;
}

std::vector<double> fit_fractions(const std::vector<double>& f, double length, double min_size) {
  const std::size_t n = f.size() - 1;
  auto blend = [&](double w) {
    std::vector<double> x(f.size());
    for (std::size_t i = 0; i <= n; ++i)
      x[i] = length * ((1.0 - w) * f[i] + w * static_cast<double>(i) / static_cast<double>(n));
    x.back() = length;
    return x;
  };
  auto smallest = [](const std::vector<double>& x) {
    double m = x[1] - x[0];
    for (std::size_t i = 1; i + 1 < x.size(); ++i) m = std::min(m, x[i + 1] - x[i]);
    return m;
  };
  std::vector<double> x = blend(0.0);
  if (smallest(x) >= min_size) return x;
  if (smallest(blend(1.0)) < min_size) return blend(1.0);
  double lo = 0.0;
  double hi = 1.0;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (smallest(blend(mid)) >= min_size ? hi : lo) = mid;
  }
  return blend(hi);
}

std::vector<double> split_to_count(const std::vector<double>& x, std::size_t n) {
  std::vector<double> sizes = spacings(x);
  while (sizes.size() < n) {
    const auto it = std::max_element(sizes.begin(), sizes.end());
    const double half = 0.5 * *it;
    *it = half;
    sizes.insert(it, half);
  }
  return positions_from_sizes(sizes);
}

std::size_t uniform_count(const std::vector<double>& x, double h) {
  std::size_t n = 0;
  while (n + 1 < x.size() && std::abs((x[n + 1] - x[n]) - h) <= 1e-9 * h) ++n;
  return n;
}

}  // namespace corlab::fem::meshing

namespace corlab::fem {

std::vector<double> graded_positions(
    double length, double h, double uniform_length, double growth, double h_max) {
  std::vector<double> sizes;
  std::vector<bool> graded;
  meshing::grow_sizes(h, uniform_length, growth, std::max(h, h_max), length, sizes, graded);
  auto x = meshing::positions_from_sizes(
      meshing::close_distribution(std::move(sizes), std::move(graded), length));
  x.back() = length;  // exact end (the sum of the sizes may differ in the last bit)
  return x;
}

}  // namespace corlab::fem
