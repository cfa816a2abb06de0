// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file dem_fe_targets.hpp
/// `corlab dem --model fe|auto` (and `corlab.dem.export(model="fe")`): each pair's e(v) from
/// corlab's FE solver (study/fe_curve.hpp), or corlab2026p where it is accurate and the FE
/// elsewhere (auto_restitution.hpp), at the export's fit speeds, each run from the result
/// cache when it was computed before. The pair is taken as `corlab predict` takes it: the
/// particle is the sphere, on the wall (a flat; an elastic wall a half-space, whose e is the
/// elastic-wave loss) or on the other particle (a free sphere, R1/R2 = r_i/r_j). Between the
/// speeds the target is the monotone cubic through them in ln v (fe_interpolation.hpp), held at
/// the end values outside. An elastic pair is answered like any other: never refused.

#include <string>

#include "corlab/dem/dem_export.hpp"
#include "corlab/study/fe_curve.hpp"

namespace corlab::dataset {

/// The source for ExportSpec::target_source: `model` "fe" or "auto" (InputError naming `model`
/// otherwise), run with `options` (its cache, jobs, progress and cancel flag outlive the
/// source). A pair whose runs give an e at fewer than two speeds is an InputError naming the
/// pair and the first run's reason; a speed without an e is left out with a warning.
dem::PairTargetSource fe_pair_targets(const std::string& model, study::FeCurveOptions options);

}  // namespace corlab::dataset
