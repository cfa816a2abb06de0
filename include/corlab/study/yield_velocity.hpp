#pragma once
/// @file yield_velocity.hpp
/// Yield velocity straight from the impact solver: the lowest impact velocity whose run leaves
/// plastic strain (plastic_strain_max > threshold), by bisection on ln v. This is the physical
/// onset of yield, which Hertz theory puts at p0 = 1.6 sigma_y (nu ~ 0.3), i.e.
/// v_Y = sqrt(25.5 sigma_y^5 / (rho E*^4)) (Johnson 1985, ch. 11; Thornton 1997 with
/// p_y = 1.6 sigma_y). It is NOT the v_y of Ma et al. (2023), which is the e = 1 crossing of
/// their log law (a fit extrapolation, 2.6-2.8x larger; docs/reference models.md section 9).

#include <functional>
#include <optional>
#include <vector>

#include "corlab/fem/impact_config.hpp"
#include "corlab/fem/impact_result.hpp"

namespace corlab::study {

/// Options of find_yield_onset().
struct OnsetOptions {
  double v_low = 0.01;      ///< lower end of the initial bracket [m/s] (expected elastic)
  double v_high = 3.0;      ///< upper end of the initial bracket [m/s] (expected plastic)
  int iterations = 7;       ///< bisection steps on ln v (bracket ratio shrinks as 2^-k in ln)
  double threshold = 1e-6;  ///< plastic_strain_max above this counts as plastic [-]
};

/// One solver run of the bisection.
struct OnsetProbe {
  double velocity = 0.0;            ///< [m/s]
  double plastic_strain_max = 0.0;  ///< [-]
  double e = 0.0;                   ///< CoR of the run [-]
  bool plastic = false;             ///< plastic_strain_max > threshold
};

/// Result of find_yield_onset().
struct OnsetResult {
  double v_elastic = 0.0;          ///< highest velocity seen elastic [m/s]
  double v_plastic = 0.0;          ///< lowest velocity seen plastic [m/s]
  double v_onset = 0.0;            ///< geometric mean of the two [m/s]; NaN if not bracketed
  bool bracketed = false;          ///< v_low elastic and v_high plastic
  std::vector<OnsetProbe> probes;  ///< every run, in order
};

/// Runs one impact at the given config (default: fem::simulate).
using ImpactRunner = std::function<fem::ImpactResult(const fem::ImpactConfig&)>;
/// Returns a probe already computed at this velocity (resume), or nothing.
using ProbeCache = std::function<std::optional<OnsetProbe>(double velocity)>;

/// Bisection on ln v between options.v_low and options.v_high for the config `base` (its
/// impact.velocity is replaced). `on_probe` is called after every new run (for logging and
/// resuming). Throws InputError for bad options (0 < v_low < v_high, iterations >= 0,
/// threshold >= 0).
OnsetResult find_yield_onset(const fem::ImpactConfig& base,
                             const OnsetOptions& options,
                             const ImpactRunner& run = {},
                             const ProbeCache& cached = {},
                             const std::function<void(const OnsetProbe&)>& on_probe = {});

/// Hertz yield-onset velocity for p0 = 1.6 sigma_y: sqrt(25.5 sigma_y^5 / (rho E*^4)) [m/s]
/// (Johnson 1985 ch. 11; equals Thornton 1997 v_y with p_y = 1.6 sigma_y up to 0.4 %).
double hertz_yield_onset_velocity(double sphere_rho, double E_star, double sigma_y);

}  // namespace corlab::study
