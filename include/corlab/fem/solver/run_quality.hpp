// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file run_quality.hpp
/// Quality guards on a finished run: a run whose numerical side effects exceed these limits is
/// `suspect` (the reason is reported, fits exclude it by default). The limits sit 5-20x above
/// what the verification cases show (paper case at 5 m/s: energy balance 4.6e-7, hourglass
/// energy 0.049 % of the initial energy, penetration 0.35 % of the indentation; 0.1 m/s: 1.9 %;
/// 70 m/s: hourglass 0.066 %), so a converged run never trips them.

#include <string>

#include "corlab/fem/solver/impact_result.hpp"

namespace corlab::fem {

struct QualityLimits {
  double energy_balance = 1e-2;    ///< max |energy balance error| / initial energy [-]
  double hourglass_energy = 5e-3;  ///< max hourglass energy / initial energy [-]
  double penetration = 0.1;        ///< max contact penetration / max indentation [-]
  /// A separated run's e (and every e of impact.repeats) may exceed 1 by this much before it is
  /// suspect: round-off, where it has no error bar; its e_error where it has one [-]. The
  /// rebound then took more energy than the impact brought (energy stored by earlier impacts'
  /// vibrations, or a numerical gain): 26 of 100 repeated impacts reached 1.0028.
  double restitution_excess = 1e-6;
};

/// Empty when the run is within `limits`; otherwise the first violated guard, one line, e.g.
/// "hourglass energy 6.3 % of the initial energy (limit 0.5 %)", or
/// "e_impacts[3] = 1.0028 above 1 by more than round-off (1e-06)". The same guards for every
/// geometry and model; the solver calls it when a run ends, again once e_impacts and e_error are
/// known.
std::string suspect_reason(const ImpactResult& result, const QualityLimits& limits = {});

}  // namespace corlab::fem
