// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file yield_velocity.hpp
/// Yield velocity straight from the impact solver: the lowest impact velocity whose run leaves
/// plastic strain (plastic_strain_max > threshold), by bisection on ln v. This is the physical
/// onset of yield, which Hertz theory puts at p0 = 1.6 sigma_y (nu ~ 0.3), i.e.
/// v_Y = sqrt(25.5 sigma_y^5 / (rho E*^4)) (Johnson 1985, ch. 11; Thornton 1997 with
/// p_y = 1.6 sigma_y). It is NOT the v_y of Ma et al. (2023), which is the e = 1 crossing of
/// their log law (a fit extrapolation, 2.6-2.8x larger; docs/reference models.md section 9).

#include <functional>
#include <limits>
#include <optional>
#include <vector>

#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/solver/impact_result.hpp"
#include "corlab/fem/solver/simulate.hpp"

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
  bool elastic_reference = false;   ///< a run with the substrate made elastic (scaled method)
  double von_mises_max = 0.0;       ///< substrate von Mises stress at max compression [Pa]
};

/// Result of find_yield_onset().
struct OnsetResult {
  double v_elastic = 0.0;          ///< highest velocity seen elastic [m/s]
  double v_plastic = 0.0;          ///< lowest velocity seen plastic [m/s]
  double v_onset = 0.0;            ///< geometric mean of the two [m/s]; NaN if not bracketed
  bool bracketed = false;          ///< v_low elastic and v_high plastic
  std::vector<OnsetProbe> probes;  ///< every run, in order
  double v_scaled = std::numeric_limits<double>::quiet_NaN();  ///< elastic-scaling estimate [m/s]
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

/// Options of find_yield_onset_scaled().
struct ScaledOnsetOptions {
  double bracket = 0.02;  ///< confirming runs at v_scaled / (1 + b) and v_scaled (1 + b) [-]
  int max_widen = 6;      ///< bracket moves allowed when the estimate is not bracketed
  double reference_tolerance = 0.1;  ///< re-run the elastic reference at the estimate if the
                                     ///< two differ by more than this (relative) [-]
  double threshold = 1e-6;           ///< plastic_strain_max above this counts as plastic [-]
};

/// Runs one impact with a control (the search sets stop_at_max_compression; the caller adds
/// cancel etc.). Default: fem::simulate.
using ControlledRunner =
    std::function<fem::ImpactResult(const fem::ImpactConfig&, fem::SimulationControl)>;
/// A probe already computed (resume): elastic reference or plastic probe at this velocity.
using KindProbeCache =
    std::function<std::optional<OnsetProbe>(bool elastic_reference, double velocity)>;

/// Yield onset without bisection. In the elastic regime the quasi-static stress field of a
/// Hertz contact scales with p0 ~ v^(2/5) (Johnson 1985, eq. 11.24), so one run with the
/// substrate made elastic, stopped at maximum compression, gives the peak von Mises stress
/// s_ref at v_ref and the onset estimate v_scaled = v_ref (sigma_y / s_ref)^(5/2). Two runs of
/// the real (plastic) substrate at v_scaled / (1 + b) and v_scaled (1 + b), also stopped at
/// maximum compression (yield starts on loading), confirm it; when they do not bracket the
/// onset the bracket moves by (1 + b)^2 at a time. v_ref starts at the Hertz estimate
/// (hertz_yield_onset_velocity) and is moved to v_scaled once when they differ by more than
/// reference_tolerance (the built-in mesh scales with the contact radius). The result's
/// v_elastic / v_plastic / v_onset are those of the final bracket. Throws InputError when the
/// substrate has no yield stress or the options are invalid.
OnsetResult find_yield_onset_scaled(const fem::ImpactConfig& base,
                                    const ScaledOnsetOptions& options,
                                    const ControlledRunner& run = {},
                                    const KindProbeCache& cached = {},
                                    const std::function<void(const OnsetProbe&)>& on_probe = {});

/// Hertz yield-onset velocity for p0 = 1.6 sigma_y: sqrt(25.5 sigma_y^5 / (rho E*^4)) [m/s]
/// (Johnson 1985 ch. 11; equals Thornton 1997 v_y with p_y = 1.6 sigma_y up to 0.4 %).
double hertz_yield_onset_velocity(double sphere_rho, double E_star, double sigma_y);

}  // namespace corlab::study
