// Each DEM pair's e(v) from the FE solver or --model auto (dem_fe_targets.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dataset/dem_fe_targets.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "corlab/core/error.hpp"
#include "corlab/dataset/auto_restitution.hpp"
#include "corlab/study/fe_interpolation.hpp"

namespace corlab::dataset {
namespace {

dem::ExternalTarget target_of(const std::string& model,
                              const std::vector<study::FePoint>& points,
                              const dem::PairBodies& bodies) {
  dem::ExternalTarget target;
  const std::string pair = bodies.sphere_label + " on " + bodies.substrate_label;
  std::vector<study::CurveNode> nodes;
  int cached = 0;
  int by_model = 0;
  double worst_error = 0.0;
  std::string first_failure;
  for (const study::FePoint& p : points) {
    if (!std::isfinite(p.e)) {
      const std::string why = fmt::format("v = {:g} m/s: {}{}", p.velocity, p.status,
                                          p.detail.empty() ? "" : " (" + p.detail + ")");
      if (first_failure.empty()) first_failure = why;
      target.warnings.push_back(
          fmt::format("{} ({}): no e at {}; left out of the e(v)", model, pair, why));
      continue;
    }
    nodes.push_back({p.velocity, p.e, std::isfinite(p.e_error) ? p.e_error : 0.0});
    cached += p.cached ? 1 : 0;
    by_model += p.answered_by == "fe" ? 0 : 1;
    worst_error = std::max(worst_error, std::isfinite(p.e_error) ? p.e_error : 0.0);
    if (!std::isfinite(p.e_error)) {
      target.warnings.push_back(fmt::format("{} ({}): no error bar at v = {:g} m/s ({})", model,
                                            pair, p.velocity, p.detail));
    }
  }
  if (nodes.size() < 2) {
    throw_invalid(fmt::format("{} e(v) of pair {}", model, pair), first_failure,
                  "an e at two speeds or more (narrow --v-min/--v-max)");
  }
  const std::string geometry =
      bodies.radius_ratio > 0.0 ? fmt::format("a free sphere, R1/R2 = {:.6g}", bodies.radius_ratio)
                                : "a flat";
  const std::string answered =
      model == "fe" ? fmt::format("{} speeds ({} cached)", nodes.size(), cached)
                    : fmt::format("{} speeds: corlab2026p at {}, the FE at {} ({} cached)",
                                  nodes.size(), by_model, nodes.size() - by_model, cached);
  target.description = fmt::format("{} ({} on {}: {}; {}, e +- at most {:.2g})",
                                   model == "fe" ? "corlab's FE" : "auto", bodies.sphere_label,
                                   bodies.substrate_label, geometry, answered, worst_error);
  target.curve = [nodes = std::move(nodes)](double v) {
    const double at = std::clamp(v, nodes.front().velocity, nodes.back().velocity);
    return study::interpolate_curve(nodes, at).e;
  };
  return target;
}

}  // namespace

dem::PairTargetSource fe_pair_targets(const std::string& model, study::FeCurveOptions options) {
  if (!dem::is_external_model(model)) throw_invalid("model", model, "fe or auto");
  return [model, options](const dem::PairBodies& bodies, std::span<const double> speeds) {
    const study::FePair pair{.sphere = bodies.sphere,
                             .substrate = bodies.substrate,
                             .shape = bodies.radius_ratio > 0.0 ? fem::SubstrateShape::kSphere
                                                                : fem::SubstrateShape::kFlat,
                             .radius_ratio = bodies.radius_ratio};
    const std::vector<double> v(speeds.begin(), speeds.end());
    const auto points =
        model == "auto" ? auto_curve(pair, v, options) : study::fe_curve(pair, v, options);
    return target_of(model, points, bodies);
  };
}

}  // namespace corlab::dataset
