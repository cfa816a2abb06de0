// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dataset/sobol_sequence.hpp"

#include <gsl/gsl_qrng.h>

#include <memory>

#include "corlab/core/error.hpp"

namespace corlab::dataset {

std::vector<std::vector<double>> sobol_points(int dimension, std::size_t count) {
  if (dimension < 1 || dimension > kSobolMaxDimension) {
    throw_invalid("sobol dimension", dimension, "in [1, 40] (GSL's Sobol generator)");
  }
  const std::unique_ptr<gsl_qrng, decltype(&gsl_qrng_free)> rng(
      gsl_qrng_alloc(gsl_qrng_sobol, static_cast<unsigned>(dimension)), &gsl_qrng_free);
  std::vector<std::vector<double>> points;
  points.reserve(count);
  if (count > 0) points.emplace_back(static_cast<std::size_t>(dimension), 0.0);
  while (points.size() < count) {
    std::vector<double> x(static_cast<std::size_t>(dimension));
    gsl_qrng_get(rng.get(), x.data());
    points.push_back(std::move(x));
  }
  return points;
}

}  // namespace corlab::dataset
