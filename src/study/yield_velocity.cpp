// Yield-onset velocity by bisection on ln v with the impact solver.
#include "corlab/study/yield_velocity.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "corlab/core/error.hpp"
#include "corlab/fem/simulate.hpp"

namespace corlab::study {

double hertz_yield_onset_velocity(double sphere_rho, double E_star, double sigma_y) {
  // rho V^2 / Y = (4/5) pi^4 (0.8)^5 (Y/E*)^4 with p0 = 1.6 Y  (models.md section 5.1)
  const double k = 0.8 * std::pow(std::numbers::pi, 4) * std::pow(0.8, 5);
  return std::sqrt(k * std::pow(sigma_y, 5) / (sphere_rho * std::pow(E_star, 4)));
}

OnsetResult find_yield_onset(const fem::ImpactConfig& base,
                             const OnsetOptions& options,
                             const ImpactRunner& run,
                             const ProbeCache& cached,
                             const std::function<void(const OnsetProbe&)>& on_probe) {
  require_positive("onset.v_low", options.v_low, "[m/s]");
  require_positive("onset.v_high", options.v_high, "[m/s]");
  if (!(options.v_high > options.v_low)) {
    throw_invalid("onset.v_high", options.v_high, "> onset.v_low");
  }
  if (options.iterations < 0) {
    throw_invalid("onset.iterations", static_cast<double>(options.iterations), ">= 0");
  }
  require_non_negative("onset.threshold", options.threshold);

  OnsetResult out;
  auto probe = [&](double v) {
    if (cached) {
      if (auto hit = cached(v)) {
        hit->plastic = hit->plastic_strain_max > options.threshold;
        out.probes.push_back(*hit);
        return *hit;
      }
    }
    fem::ImpactConfig config = base;
    config.impact.velocity = v;
    const fem::ImpactResult r = run ? run(config) : fem::simulate(config);
    OnsetProbe p{v, r.plastic_strain_max, r.e, r.plastic_strain_max > options.threshold};
    out.probes.push_back(p);
    if (on_probe) on_probe(p);
    return p;
  };

  const OnsetProbe lo = probe(options.v_low);
  const OnsetProbe hi = probe(options.v_high);
  out.bracketed = !lo.plastic && hi.plastic;
  if (!out.bracketed) {
    out.v_elastic = lo.plastic ? std::numeric_limits<double>::quiet_NaN() : options.v_low;
    out.v_plastic = hi.plastic ? options.v_high : std::numeric_limits<double>::quiet_NaN();
    out.v_onset = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  double a = options.v_low;
  double b = options.v_high;
  for (int k = 0; k < options.iterations; ++k) {
    const double mid = std::sqrt(a * b);
    if (probe(mid).plastic) {
      b = mid;
    } else {
      a = mid;
    }
  }
  out.v_elastic = a;
  out.v_plastic = b;
  out.v_onset = std::sqrt(a * b);
  return out;
}

}  // namespace corlab::study
