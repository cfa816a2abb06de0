// The golden-section minimiser (golden_section.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/core/golden_section.hpp"

#include <cmath>

namespace corlab {

double golden_section_minimum(const std::function<double(double)>& f,
                              double lo,
                              double hi,
                              double rel_tol) {
  constexpr double kInvPhi = 0.6180339887498949;  // (sqrt 5 - 1)/2
  double a = lo;
  double b = hi;
  double c = b - kInvPhi * (b - a);
  double d = a + kInvPhi * (b - a);
  double fc = f(c);
  double fd = f(d);
  const double abs_tol = 1e-12 * std::abs(hi - lo);
  for (int iter = 0;
       iter < 500 && std::abs(b - a) > rel_tol * (std::abs(c) + std::abs(d)) + abs_tol; ++iter) {
    if (fc < fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - kInvPhi * (b - a);
      fc = f(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + kInvPhi * (b - a);
      fd = f(d);
    }
  }
  return 0.5 * (a + b);
}

}  // namespace corlab
