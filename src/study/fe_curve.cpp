// FE e(v) of a pair on demand (fe_curve.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/study/fe_curve.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <numeric>
#include <optional>

#include "corlab/core/error.hpp"
#include "corlab/core/text.hpp"
#include "corlab/core/thread_pool.hpp"
#include "corlab/fem/mesh/contact_estimate.hpp"
#include "corlab/fem/output/impact_output.hpp"
#include "corlab/fem/solver/discretisation_error.hpp"
#include "corlab/fem/solver/run_cost.hpp"
#include "corlab/fem/solver/run_status.hpp"
#include "corlab/fem/solver/simd_level.hpp"
#include "corlab/fem/solver/simulate.hpp"
#include "corlab/study/fe_interpolation.hpp"
#include "corlab/study/progress.hpp"

namespace corlab::study {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// The status of a speed the solver refuses, and of one not run because of a cancel.
constexpr std::string_view kInvalid = "invalid";
constexpr std::string_view kCancelled = "cancelled";

double number_or_nan(const nlohmann::json& value, const char* name) {
  const auto it = value.find(name);
  return it != value.end() && it->is_number() ? it->get<double>() : kNaN;
}

std::string text_or_empty(const nlohmann::json& value, const char* name) {
  const auto it = value.find(name);
  return it != value.end() && it->is_string() ? it->get<std::string>() : std::string();
}

// A point from a run's summary (summary_to_json, without its config: that is the key).
FePoint point_from_summary(double velocity, const nlohmann::json& summary) {
  FePoint p;
  p.velocity = velocity;
  p.status = text_or_empty(summary, "status");
  p.e = p.status == fem::to_string(fem::RunStatus::kSeparated) ? number_or_nan(summary, "e") : kNaN;
  p.e_error = number_or_nan(summary, "e_error");
  p.wall_s = number_or_nan(summary, "wall_s");
  for (const char* why : {"status_detail", "e_error_reason", "suspect"}) {
    const std::string text = text_or_empty(summary, why);
    if (text.empty()) continue;
    p.detail += (p.detail.empty() ? "" : "; ") + text;
  }
  return p;
}

// An elastic substrate as a half-space: the elastic-wave loss is the e of such a flat (all of it
// for an elastic pair), and the default 70 mm block (2 R) reflects its waves back into the
// contact (alumina on glass at 1 m/s: e 0.99994 there, 0.99449 on a 0.7 m block, the same on
// 1.4 m). The block grows to kHalfSpaceMargin times the distance a dilatational wave travels
// out in half the Hertz contact time, so that none returns before the bodies part, and its far
// elements to 1/35 of it (0.7 m with 20 mm elements: 0.99446, 5,831 elements; with 5 mm:
// 26,483). At most the substrate keys' 10 m.
void as_half_space(fem::ImpactConfig& c) {
  constexpr double kHalfSpaceMargin = 1.5;
  constexpr double kElementsAcross = 35.0;
  constexpr double kMaxSize = 10.0;  // substrate.radius and .depth's upper limit [m]
  const double travel =
      c.substrate.material.dilatational_wave_speed() * fem::hertz_reference(c).contact_time / 2.0;
  const double size = std::min(kMaxSize, kHalfSpaceMargin * travel);
  if (!(size > c.substrate.radius)) return;  // also NaN for a pair validate() will refuse
  c.substrate.radius = c.substrate.depth = size;
  c.mesh.h_max = std::max(c.mesh.h_max, size / kElementsAcross);
}

bool is_material_field(const std::string& field) {
  return field.starts_with("sphere.") || field.starts_with("substrate.");
}

}  // namespace

fem::SubstrateShape resolve_fe_shape(std::string_view shape,
                                     double radius_ratio,
                                     std::string_view shape_field,
                                     std::string_view ratio_field) {
  if (shape.empty()) {
    return radius_ratio > 0.0 ? fem::SubstrateShape::kSphere : fem::SubstrateShape::kFlat;
  }
  if (shape == "sphere") {
    if (!(radius_ratio > 0.0)) {
      throw_invalid(ratio_field, radius_ratio, "> 0 for a second sphere (R1/R2) [-]");
    }
    return fem::SubstrateShape::kSphere;
  }
  if (shape != "flat" && shape != "rigid")
    throw_invalid(shape_field, shape, "flat, sphere or rigid");
  if (radius_ratio != 0.0) {
    throw_invalid(ratio_field, radius_ratio, fmt::format("0 for a {} target [-]", shape));
  }
  return shape == "rigid" ? fem::SubstrateShape::kRigid : fem::SubstrateShape::kFlat;
}

fem::ImpactConfig fe_curve_config(const FePair& pair, double velocity) {
  fem::ImpactConfig c;
  c.sphere.material = pair.sphere;
  c.substrate.material = pair.substrate;
  c.substrate.shape = pair.shape;
  c.impact.velocity = velocity;
  if (pair.shape == fem::SubstrateShape::kSphere) {
    if (!(pair.radius_ratio > 0.0 && pair.radius_ratio <= 1e3)) {
      throw_invalid("radius_ratio", pair.radius_ratio, "in (0, 1000] for a second sphere [-]");
    }
    c.substrate.radius = c.sphere.radius / pair.radius_ratio;
  } else if (pair.radius_ratio != 0.0) {
    throw_invalid("radius_ratio", pair.radius_ratio,
                  fmt::format("0 for a {} target [-]", fem::to_string(pair.shape)));
  }
  if (pair.shape == fem::SubstrateShape::kFlat && !pair.substrate.yield_stress) as_half_space(c);
  return c;
}

nlohmann::json fe_run_key(const fem::ImpactConfig& config) {
  return {{"config", fem::config_to_json(config)},
          {"error_estimate", fem::kDefaultErrorBar},
          {"simd", fem::to_string(fem::simd_level())}};
}

std::vector<FePoint> fe_curve(const FePair& pair,
                              const std::vector<double>& velocities,
                              const FeCurveOptions& options) {
  const std::size_t n = velocities.size();
  std::vector<FePoint> points(n);
  std::vector<fem::ImpactConfig> configs;
  configs.reserve(n);
  std::vector<double> cost(n, 0.0);
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < n; ++i) {
    configs.push_back(fe_curve_config(pair, velocities[i]));
    FePoint& p = points[i];
    p.velocity = velocities[i];
    p.e = p.e_error = kNaN;
    try {
      fem::validate(configs[i]);
    } catch (const InputError& err) {
      if (is_material_field(err.field())) throw;  // the pair itself: every speed would say it
      p.status = kInvalid;
      p.detail = err.what();
      continue;
    }
    if (options.cache != nullptr) {
      if (auto hit = options.cache->load(fe_run_key(configs[i]))) {
        p = point_from_summary(velocities[i], *hit);
        p.cached = true;
        continue;
      }
    }
    cost[i] = fem::estimate_run_cost(configs[i]).element_steps();
    pending.push_back(i);
  }
  // The costliest first, so that the curve does not end waiting for one long run.
  std::stable_sort(pending.begin(), pending.end(),
                   [&cost](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
  for (const std::size_t i : pending) points[i].status = kCancelled;

  const int workers =
      std::min(worker_count(options.jobs), std::max(1, static_cast<int>(pending.size())));
  std::optional<ProgressBar> bar;
  std::mutex progress_mutex;
  const int done = static_cast<int>(n - pending.size());
  int ran = 0;
  int failed = 0;
  double wall_sum = 0.0;
  if (options.progress != nullptr) {
    bar.emplace(options.progress, static_cast<int>(n), workers);
    bar->update(done, 0, -1.0, true);
  }
  parallel_for(
      pending.size(), workers,
      [&](std::size_t job) {
        const std::size_t i = pending[job];
        fem::SimulationControl control;
        control.cancel = options.cancel;
        control.config_validated = true;
        const auto start = std::chrono::steady_clock::now();
        try {
          const fem::ImpactResult result = fem::simulate_with_error_estimate(configs[i], control);
          if (result.status == fem::RunStatus::kCancelled) return;
          nlohmann::json summary = fem::summary_to_json(result, configs[i]);
          summary.erase("config");
          points[i] = point_from_summary(velocities[i], summary);
          if (options.cache != nullptr) options.cache->store(fe_run_key(configs[i]), summary);
        } catch (const std::exception& err) {  // a solver failure is this speed's row, not cached
          points[i].status = "failed";
          points[i].detail = one_line(err.what());
        }
        if (!bar) return;
        const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
        const std::lock_guard lock(progress_mutex);
        ++ran;
        if (points[i].status != fem::to_string(fem::RunStatus::kSeparated)) ++failed;
        wall_sum += wall.count();
        bar->update(done + ran, failed, wall_sum / ran);
      },
      options.cancel);
  if (bar) bar->finish();
  return points;
}

std::vector<FePoint> fe_curve_refined(const FePair& pair,
                                      const std::vector<double>& velocities,
                                      double tolerance,
                                      const FeCurveOptions& options) {
  if (!(std::isfinite(tolerance) && tolerance > 0.0)) {
    throw_invalid("tolerance", tolerance, "a finite number > 0 [-]");
  }
  const auto [lo, hi] = std::minmax_element(velocities.begin(), velocities.end());
  std::map<double, FePoint> computed;
  std::vector<double> next;
  for (std::size_t i = 0; i < kRefinementStart; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(kRefinementStart - 1);
    next.push_back(i + 1 == kRefinementStart ? *hi : *lo * std::pow(*hi / *lo, t));
  }
  std::sort(next.begin(), next.end());
  next.erase(std::unique(next.begin(), next.end()), next.end());
  std::vector<CurveNode> nodes;
  while (!next.empty() && !(options.cancel != nullptr && options.cancel->load())) {
    for (FePoint& p : fe_curve(pair, next, options)) computed[p.velocity] = std::move(p);
    nodes.clear();
    for (const auto& [v, p] : computed) {
      if (std::isfinite(p.e)) nodes.push_back({v, p.e, p.e_error});
    }
    next = refinement_speeds(nodes, tolerance, kRefinementMax - computed.size());
  }
  std::vector<FePoint> out;
  out.reserve(velocities.size());
  for (const double v : velocities) {
    if (const auto it = computed.find(v); it != computed.end()) {
      out.push_back(it->second);
      continue;
    }
    const Interpolated at = interpolate_curve(nodes, v);
    FePoint p;
    p.velocity = v;
    p.e = at.e;
    p.e_error = at.e_error;
    p.answered_by = "fe-interpolated";
    p.status = std::isfinite(at.e) ? "interpolated" : "not_computed";
    if (!std::isfinite(at.e)) {
      p.detail = "outside the FE speeds that rebounded";
    } else if (at.interpolation > tolerance) {
      p.detail = fmt::format("interpolation error {:.2g} above the tolerance: {} FE speeds ran",
                             at.interpolation, computed.size());
    }
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace corlab::study
