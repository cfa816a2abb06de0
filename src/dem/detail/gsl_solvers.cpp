// SPDX-License-Identifier: BSD-3-Clause
#include "dem/detail/gsl_solvers.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <cmath>
#include <memory>
#include <stdexcept>

namespace corlab::dem::detail {
namespace {

double call(double x, void* params) {
  return (*static_cast<const std::function<double(double)>*>(params))(x);
}

}  // namespace

double brent_root(
    const std::function<double(double)>& f, double lo, double hi, double abs_tol, double rel_tol) {
  const double flo = f(lo);
  const double fhi = f(hi);
  if (flo == 0.0) return lo;
  if (fhi == 0.0) return hi;
  if ((flo > 0.0) == (fhi > 0.0) || !std::isfinite(flo) || !std::isfinite(fhi)) {
    throw std::runtime_error("brent_root: the interval does not bracket a root");
  }
  gsl_set_error_handler_off();
  gsl_function fn{&call, const_cast<std::function<double(double)>*>(&f)};
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  gsl_root_fsolver_set(solver.get(), &fn, lo, hi);
  for (int iter = 0; iter < 200; ++iter) {
    gsl_root_fsolver_iterate(solver.get());
    const double a = gsl_root_fsolver_x_lower(solver.get());
    const double b = gsl_root_fsolver_x_upper(solver.get());
    if (gsl_root_test_interval(a, b, abs_tol, rel_tol) == GSL_SUCCESS || a == b) {
      return gsl_root_fsolver_root(solver.get());
    }
  }
  throw std::runtime_error("brent_root: no convergence in 200 iterations");
}

}  // namespace corlab::dem::detail
