// The FE dataset's runs nearest a material pair (nearest_runs.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "nearest_runs.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

#include "corlab/core/error.hpp"

namespace corlab::explorer {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

const nlohmann::json& column(const nlohmann::json& columns, const char* name, std::size_t rows) {
  const auto it = columns.find(name);
  if (it == columns.end() || !it->is_array() || it->size() != rows) {
    throw_invalid("dataset column", name, "an array with one cell per run");
  }
  return *it;
}

// A numeric cell; null (an infinite or empty cell of the CSV) reads as `missing`.
double number(const nlohmann::json& cell, const char* name, double missing) {
  if (cell.is_null()) return missing;
  if (!cell.is_number()) throw_invalid("dataset column", name, "numbers (null for inf or empty)");
  return cell.get<double>();
}

// The coordinates of the distance (nearest_runs.hpp); the sphere's yield ratio is handled apart.
constexpr std::size_t kCoordinates = 6;
using Point = std::array<double, kCoordinates>;

Point point_of(const DatasetRun& r) {
  return {std::log(r.k2), std::log(r.modulus_ratio), r.nu_sphere,
          r.nu_substrate, r.hardening_ratio_sphere,  r.hardening_ratio_substrate};
}

}  // namespace

std::vector<DatasetRun> runs_from_columns(const nlohmann::json& columns) {
  if (!columns.is_object()) throw_invalid("dataset", "not an object", "a JSON object of columns");
  const auto e_column = columns.find("e");
  if (e_column == columns.end() || !e_column->is_array()) {
    throw_invalid("dataset column", "e", "an array with one cell per run");
  }
  const std::size_t rows = e_column->size();
  std::vector<DatasetRun> runs;
  const auto& status = column(columns, "status", rows);
  const auto& included = column(columns, "included", rows);
  for (std::size_t i = 0; i < rows; ++i) {
    if (status[i] != "ok" || included[i] != true) continue;
    const auto num = [&](const char* name, double missing = kNaN) {
      return number(column(columns, name, rows)[i], name, missing);
    };
    DatasetRun r;
    r.design_index = static_cast<long>(num("design_index"));
    r.case_id = column(columns, "case_id", rows)[i].get<std::string>();
    r.k1 = num("k1");
    r.k2 = num("k2");
    r.modulus_ratio = num("modulus_ratio");
    r.sphere_yield_ratio = num("sphere_yield_ratio", kInf);
    r.nu_sphere = num("nu_sphere");
    r.nu_substrate = num("nu_substrate");
    r.hardening_ratio_sphere = num("hardening_ratio_sphere");
    r.hardening_ratio_substrate = num("hardening_ratio_substrate");
    r.density_ratio = num("density_ratio");
    r.velocity = num("velocity");
    r.e = num("e");
    r.e_error = num("e_error");
    runs.push_back(std::move(r));
  }
  return runs;
}

nlohmann::json nearest_runs(std::span<const DatasetRun> runs,
                            const Material& sphere,
                            const Material& substrate,
                            double v_min,
                            double v_max,
                            std::size_t count) {
  nlohmann::json out = nlohmann::json::array();
  if (runs.empty() || count == 0 || !substrate.yield_stress) return out;
  const double e_star = effective_modulus(sphere, substrate);
  const bool elastic_sphere = !sphere.yield_stress.has_value();
  DatasetRun pair;
  pair.k2 = k2(*substrate.yield_stress, e_star);
  pair.modulus_ratio = sphere.youngs_modulus / substrate.youngs_modulus;
  pair.sphere_yield_ratio = elastic_sphere ? kInf : *sphere.yield_stress / *substrate.yield_stress;
  pair.nu_sphere = sphere.poisson_ratio;
  pair.nu_substrate = substrate.poisson_ratio;
  pair.hardening_ratio_sphere =
      elastic_sphere ? 0.0 : sphere.hardening_modulus / sphere.youngs_modulus;
  pair.hardening_ratio_substrate = substrate.hardening_modulus / substrate.youngs_modulus;

  // The span of each coordinate over the dataset (a coordinate the dataset does not vary counts
  // nothing).
  Point lo;
  Point hi;
  lo.fill(kInf);
  hi.fill(-kInf);
  double yield_lo = kInf;
  double yield_hi = -kInf;
  for (const auto& r : runs) {
    const Point p = point_of(r);
    for (std::size_t j = 0; j < kCoordinates; ++j) {
      lo[j] = std::min(lo[j], p[j]);
      hi[j] = std::max(hi[j], p[j]);
    }
    if (std::isfinite(r.sphere_yield_ratio)) {
      yield_lo = std::min(yield_lo, std::log(r.sphere_yield_ratio));
      yield_hi = std::max(yield_hi, std::log(r.sphere_yield_ratio));
    }
  }
  const auto scaled = [](double a, double b, double low, double high) {
    return high > low ? (a - b) / (high - low) : 0.0;
  };
  const Point target = point_of(pair);
  struct Candidate {
    std::size_t index;
    double distance;
    double velocity;  // the pair's speed with the run's k1 [m/s]
  };
  std::vector<Candidate> candidates;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const DatasetRun& r = runs[i];
    // k1 = E*/(rho v^2) of the pair equal to the run's (materials.hpp, Ma et al. 2023 eq. 5).
    const double v = std::sqrt(e_star / (sphere.density * r.k1));
    if (!(v >= v_min && v <= v_max)) continue;
    const Point p = point_of(r);
    double d2 = 0.0;
    for (std::size_t j = 0; j < kCoordinates; ++j) {
      const double d = scaled(p[j], target[j], lo[j], hi[j]);
      d2 += d * d;
    }
    const bool run_elastic = !std::isfinite(r.sphere_yield_ratio);
    if (run_elastic != elastic_sphere) {
      d2 += 1.0;
    } else if (!run_elastic) {
      const double d = scaled(std::log(r.sphere_yield_ratio), std::log(pair.sphere_yield_ratio),
                              yield_lo, yield_hi);
      d2 += d * d;
    }
    candidates.push_back({i, std::sqrt(d2), v});
  }
  const std::size_t n = std::min(count, candidates.size());
  std::partial_sort(candidates.begin(), candidates.begin() + static_cast<std::ptrdiff_t>(n),
                    candidates.end(), [](const Candidate& a, const Candidate& b) {
                      return a.distance < b.distance ||
                             (a.distance == b.distance && a.index < b.index);
                    });
  const auto finite_or_null = [](double x) -> nlohmann::json {
    return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
  };
  for (std::size_t c = 0; c < n; ++c) {
    const DatasetRun& r = runs[candidates[c].index];
    out.push_back({{"design_index", r.design_index},
                   {"case_id", r.case_id},
                   {"distance", candidates[c].distance},
                   {"velocity_pair", candidates[c].velocity},
                   {"velocity", r.velocity},
                   {"e", r.e},
                   {"e_error", finite_or_null(r.e_error)},
                   {"k1", r.k1},
                   {"k2", r.k2},
                   {"modulus_ratio", r.modulus_ratio},
                   {"sphere_yield_ratio", finite_or_null(r.sphere_yield_ratio)},
                   {"nu_sphere", r.nu_sphere},
                   {"nu_substrate", r.nu_substrate},
                   {"hardening_ratio_sphere", r.hardening_ratio_sphere},
                   {"hardening_ratio_substrate", r.hardening_ratio_substrate},
                   {"density_ratio", r.density_ratio}});
  }
  return out;
}

}  // namespace corlab::explorer
