// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The error-bar coverage tests' count (tests/verification/error_bar_coverage*_test.cpp): how many
// finer-mesh values lie inside their bars, and the median bar against the median change.
#include <algorithm>
#include <cstdio>
#include <vector>

namespace corlab::test {

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct CoverageTally {
  int inside = 0;
  std::vector<double> bars;     ///< the error bars [the quantity's unit, or relative]
  std::vector<double> changes;  ///< |finer value - value|, in the bars' unit

  /// Counts one bar against its change; returns "inside" or "OUTSIDE" for the test's log.
  const char* add(double bar, double change) {
    bars.push_back(bar);
    changes.push_back(change);
    inside += change <= bar ? 1 : 0;
    return change <= bar ? "inside" : "OUTSIDE";
  }
  /// Prints "inside N of M; median bar B, median change C".
  void print() const {
    std::printf("inside %d of %zu; median bar %.2e, median change %.2e\n", inside, bars.size(),
                median(bars), median(changes));
  }
};

}  // namespace corlab::test
