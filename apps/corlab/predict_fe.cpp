// `corlab predict --model fe|auto` (predict_fe.hpp): FE-backed e(v) with error bars.
// SPDX-License-Identifier: BSD-3-Clause
#include "predict_fe.hpp"

#include <fmt/core.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>

#include "corlab/core/error.hpp"
#include "corlab/core/interrupt.hpp"
#include "corlab/dataset/auto_restitution.hpp"
#include "corlab/dataset/impact_box.hpp"
#include "corlab/study/fe_curve.hpp"
#include "corlab/study/result_cache.hpp"
#include "corlab/study/results_table.hpp"
#include "corlab/study/sweep.hpp"

namespace corlab::cli {
namespace {

fem::SubstrateShape resolve_shape(const FeOptions& o, double radius_ratio) {
  return study::resolve_fe_shape(o.shape, radius_ratio, "--shape", "--radius-ratio");
}

// A number's cell: shortest round-trip text, empty where there is none (NaN).
std::string cell(double value) {
  return std::isfinite(value) ? study::format_number(value) : std::string();
}

nlohmann::json json_number(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

}  // namespace

bool is_fe_model(const std::string& model) { return model == "fe" || model == "auto"; }

void add_fe_options(CLI::App& sub, FeOptions& options) {
  sub.add_option("--shape", options.shape,
                 "fe|auto: what the sphere hits: flat (fixed, elastic-plastic), sphere (a free "
                 "second sphere, R1/R2 = --radius-ratio) or rigid (a rigid flat); default: "
                 "sphere for --radius-ratio > 0, else flat")
      ->check(CLI::IsMember({"flat", "sphere", "rigid"}));
  sub.add_option("--jobs", options.jobs, "fe|auto: speeds run at once (0: one per core)")
      ->check(CLI::Range(0, 4096));
  sub.add_flag("--no-cache", options.no_cache,
               "fe|auto: compute every speed and store nothing (cache: `corlab cache`)");
  sub.add_flag("--quiet", options.quiet, "fe|auto: no progress line on stderr");
  sub.add_option("--tolerance", options.tolerance,
                 "fe: run the FE at fewer speeds, refined until the interpolation between them "
                 "is within this error of e, and interpolate the others [-]");
}

void require_no_fe_options(const FeOptions& options, double radius_ratio) {
  if (!options.shape.empty() &&
      resolve_shape(options, radius_ratio) != resolve_shape({}, radius_ratio)) {
    throw_invalid("--shape", options.shape,
                  "flat or sphere as --radius-ratio says (other "
                  "shapes: --model fe or auto)");
  }
}

int run_predict_fe(const FePredictRequest& r) {
  // Every rank would run every speed and print the table: the speeds run on threads (--jobs).
  if (const int ranks = study::launched_world_size(); ranks > 1) {
    throw_invalid("mpirun ranks", ranks,
                  "1 for predict --model fe|auto (its speeds run on threads, --jobs; a "
                  "distributed study: corlab sweep)");
  }
  study::FePair pair{.sphere = r.sphere,
                     .substrate = r.substrate,
                     .shape = resolve_shape(r.options, r.radius_ratio),
                     .radius_ratio = r.radius_ratio};
  std::optional<study::ResultCache> cache;
  if (!r.options.no_cache) {
    cache.emplace(study::default_cache_directory(), study::cache_build_id(),
                  [](const std::string& warning) {
                    std::fprintf(stderr, "corlab: warning: %s\n", warning.c_str());
                  });
  }
  const InterruptScope interrupt;
  study::FeCurveOptions options{.jobs = r.options.jobs,
                                .cache = cache ? &*cache : nullptr,
                                .progress = r.options.quiet ? nullptr : stderr,
                                .cancel = interrupt.flag()};
  if (r.options.tolerance != 0.0 && r.model != "fe") {
    throw_invalid("--tolerance", r.options.tolerance, "0 (unset) with --model auto");
  }
  const std::vector<study::FePoint> points =
      r.model == "auto" ? dataset::auto_curve(pair, r.velocities, options)
      : r.options.tolerance != 0.0
          ? study::fe_curve_refined(pair, r.velocities, r.options.tolerance, options)
          : study::fe_curve(pair, r.velocities, options);
  if (interrupt.requested()) {
    fmt::print(stderr, "corlab predict: interrupted ({}); finished speeds are cached\n",
               interrupt.signal_name());
    return interrupt.exit_code();
  }
  bool complete = true;
  nlohmann::json columns;
  const char* const header[] = {"model",  "velocity", "e",  "e_error", "answered_by",
                                "status", "cached",   "k1", "k2",      "detail"};
  if (r.format == "csv") {
    fmt::print("{}\n", study::csv_line({std::begin(header), std::end(header)}));
  }
  for (const study::FePoint& p : points) {
    complete = complete && std::isfinite(p.e);
    const dataset::DimensionlessInputs in =
        dataset::dimensionless_inputs(study::fe_curve_config(pair, p.velocity));
    const double k2 = pair.shape == fem::SubstrateShape::kRigid
                          ? std::numeric_limits<double>::quiet_NaN()
                          : in.k2;
    const bool ran = p.answered_by == "fe" && p.status != "invalid";
    if (r.format == "csv") {
      fmt::print("{}\n", study::csv_line({r.model, study::format_number(p.velocity), cell(p.e),
                                          cell(p.e_error), p.answered_by, p.status,
                                          ran ? (p.cached ? "true" : "false") : "", cell(in.k1),
                                          cell(k2), p.detail}));
      continue;
    }
    columns["velocity"].push_back(p.velocity);
    columns["e"].push_back(json_number(p.e));
    columns["e_error"].push_back(json_number(p.e_error));
    columns["answered_by"].push_back(p.answered_by);
    columns["status"].push_back(p.status);
    columns["cached"].push_back(ran ? nlohmann::json(p.cached) : nlohmann::json(nullptr));
    columns["k1"].push_back(json_number(in.k1));
    columns["k2"].push_back(json_number(k2));
    columns["detail"].push_back(p.detail);
  }
  if (r.format == "json") {
    columns["model"] = r.model;
    columns["sphere"] = r.sphere_spec;
    columns["substrate"] = r.substrate_spec;
    columns["shape"] = fem::to_string(pair.shape);
    columns["radius_ratio"] = r.radius_ratio;
    columns["corlab_build"] = study::cache_build_id();
    fmt::print("{}\n", columns.dump(2));
  }
  return complete ? 0 : 4;
}

}  // namespace corlab::cli
