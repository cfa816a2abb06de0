// Relative errors and their statistics, summed in numpy's pairwise order.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fit/relative_error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "corlab/core/error.hpp"

namespace corlab::study {
namespace {

// numpy's add.reduce over contiguous doubles (numpy.sum, numpy.mean): blocks of 8192 values
// added in turn, each summed pairwise (halves cut at multiples of 8, down to 128 values that are
// summed in 8 lanes). Its rounding error grows like log n, not n; and the same order keeps the
// dataset's published scores, which numpy computed, the same to the last bit.
constexpr std::size_t kBufferSize = 8192;
constexpr std::size_t kPairwiseBlock = 128;
constexpr std::size_t kLanes = 8;

double pairwise_sum(const double* x, std::size_t n) {
  if (n < kLanes) {
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) sum += x[i];
    return sum;
  }
  if (n <= kPairwiseBlock) {
    std::array<double, kLanes> lane{};
    std::copy_n(x, kLanes, lane.begin());
    std::size_t i = kLanes;
    for (; i < n - n % kLanes; i += kLanes) {
      for (std::size_t j = 0; j < kLanes; ++j) lane[j] += x[i + j];
    }
    double sum =
        ((lane[0] + lane[1]) + (lane[2] + lane[3])) + ((lane[4] + lane[5]) + (lane[6] + lane[7]));
    for (; i < n; ++i) sum += x[i];
    return sum;
  }
  std::size_t half = n / 2;
  half -= half % kLanes;
  return pairwise_sum(x, half) + pairwise_sum(x + half, n - half);
}

double mean(const std::vector<double>& x) {
  double sum = 0.0;
  for (std::size_t i = 0; i < x.size(); i += kBufferSize) {
    sum += pairwise_sum(x.data() + i, std::min(kBufferSize, x.size() - i));
  }
  return sum / static_cast<double>(x.size());
}

void require_same_size(std::span<const double> model, std::span<const double> reference) {
  if (model.size() != reference.size()) {
    throw_invalid("model values", static_cast<double>(model.size()),
                  "as many as the reference values (" + std::to_string(reference.size()) + ")");
  }
}

}  // namespace

std::vector<double> relative_errors(std::span<const double> model,
                                    std::span<const double> reference) {
  require_same_size(model, reference);
  std::vector<double> r(model.size());
  for (std::size_t i = 0; i < r.size(); ++i) r[i] = (model[i] - reference[i]) / reference[i];
  return r;
}

RelativeErrorStats relative_error_stats(std::span<const double> relative_errors) {
  RelativeErrorStats s;
  std::vector<double> kept;
  std::vector<double> squares;
  kept.reserve(relative_errors.size());
  squares.reserve(relative_errors.size());
  for (std::size_t i = 0; i < relative_errors.size(); ++i) {
    const double r = relative_errors[i];
    if (!std::isfinite(r)) continue;
    if (kept.empty() || std::abs(r) > std::abs(relative_errors[s.worst_index])) s.worst_index = i;
    kept.push_back(r);
    squares.push_back(r * r);
  }
  s.n = kept.size();
  if (s.n == 0) return s;
  s.worst = relative_errors[s.worst_index];
  s.rms = std::sqrt(mean(squares));
  s.bias = mean(kept);
  return s;
}

RelativeErrorStats relative_error_stats(std::span<const double> model,
                                        std::span<const double> reference) {
  return relative_error_stats(relative_errors(model, reference));
}

}  // namespace corlab::study
