// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dem/lammps_mapping.hpp"

#include <stdexcept>

#include "corlab/core/error.hpp"
#include "corlab/dem/calibration.hpp"
#include "dem/detail/gsl_solvers.hpp"

namespace corlab::dem {

double lammps_tsuji_alpha(double e) {
  // Horner form of LAMMPS's polynomial (pair_granular.cpp, PairGranular::coeff).
  return 1.2728 +
         e * (-4.2783 + e * (11.087 + e * (-22.348 + e * (27.467 + e * (-18.022 + e * 4.8218)))));
}

double lammps_tsuji_input(double target) {
  require_open_range("restitution", target, 0.0, 1.0);
  const double alpha = calibrate_tsuji_alpha(target);
  // poly decreases monotonically on [-1, 1]; find poly(e_in) = alpha.
  const auto f = [alpha](double e_in) { return lammps_tsuji_alpha(e_in) - alpha; };
  if (f(-1.0) < 0.0 || f(1.0) > 0.0) {
    throw_invalid("restitution", target, "reachable by LAMMPS damping tsuji (input in [-1, 1])");
  }
  return detail::brent_root(f, -1.0, 1.0, 1e-14, 0.0);
}

}  // namespace corlab::dem
