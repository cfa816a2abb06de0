// `corlab reproduce`, running the studies: history studies (time histories, field snapshots),
// sweeps (with their error-bar companions) and the yield-onset search. Each keeps what is done on
// disk, so a rerun continues where it stopped.
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <map>
#include <mutex>
#include <optional>
#include <tuple>

#include "corlab/core/atomic_file.hpp"
#include "corlab/core/thread_pool.hpp"
#include "corlab/fem/output/impact_output.hpp"
#include "corlab/fem/output/vtu_writer.hpp"
#include "corlab/fem/solver/discretisation_error.hpp"
#include "corlab/fem/solver/run_cost.hpp"
#include "corlab/fem/solver/simulate.hpp"
#include "corlab/materials/material.hpp"
#include "corlab/study/results_table.hpp"
#include "corlab/study/sweep.hpp"
#include "reproduce_internal.hpp"

namespace corlab::study::reproduce_detail {

namespace fs = std::filesystem;
using json = nlohmann::json;

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// The scaled onset search (find_yield_onset_scaled) with its default options: a 2 % confirming
/// bracket, as narrow as the 8-step bisection it replaced ([0.01, 3] m/s: 2.2 %).
ScaledOnsetOptions onset_options(const std::string& /*preset*/) { return {}; }

json onset_options_json(const ScaledOnsetOptions& o) {
  return {{"method", "elastic scaling (v^(2/5)) + confirming bracket"},
          {"bracket", o.bracket},
          {"max_widen", o.max_widen},
          {"reference_tolerance", o.reference_tolerance},
          {"threshold", o.threshold}};
}

/// (case id, probe) of every row of a probes.csv (empty when the file does not exist).
std::vector<std::pair<std::string, OnsetProbe>> read_onset_probes(const fs::path& file) {
  std::vector<std::pair<std::string, OnsetProbe>> out;
  if (!fs::exists(file)) return out;
  const ResultsTable t = read_results(file);
  if (t.size() == 0) return out;
  const auto& ids = t.text("onset_case");
  const auto& kinds = t.text("kind");
  const auto vs = t.numbers("velocity");
  const auto ps = t.numbers("plastic_strain_max");
  const auto vm = t.numbers("von_mises_max");
  const auto es = t.numbers("e");
  for (std::size_t i = 0; i < t.size(); ++i) {
    OnsetProbe p;
    p.velocity = vs[i];
    p.plastic_strain_max = ps[i];
    p.von_mises_max = vm[i];
    p.e = es[i];
    p.elastic_reference = kinds[i] == kElasticKind;
    out.emplace_back(ids[i], p);
  }
  return out;
}

namespace {

std::string setting_value(const Settings& settings, const std::string& key) {
  std::string value;
  for (const auto& [k, v] : settings) {
    if (k == key) value = v;
  }
  return value;
}

/// The onset cases, most expensive first: each costs about three loading-half runs near its
/// Hertz onset velocity, and a low yield stress (a tiny, finely meshed, slow contact) costs up to
/// ten times more than a high one; started last on two workers, it would run alone at the end.
std::vector<std::size_t> onset_cases_longest_first(const std::vector<SweepCase>& cases) {
  std::vector<double> cost(cases.size(), 0.0);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    try {
      fem::ImpactConfig probe = cases[i].config;
      const auto& substrate = probe.substrate.material;
      if (substrate.yield_stress) {
        probe.impact.velocity = hertz_yield_onset_velocity(
            probe.sphere.material.density, effective_modulus(probe.sphere.material, substrate),
            *substrate.yield_stress);
      }
      cost[i] = fem::estimate_run_cost(probe).element_steps();
    } catch (const std::exception&) {
      cost[i] = 0.0;  // an invalid case fails at once when it runs: last
    }
  }
  std::vector<std::size_t> order(cases.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&cost](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
  return order;
}

}  // namespace

/// A study whose runs keep their time histories (Figs. 2, 3, 5): runs/<case>/{history.csv,
/// summary.json}, plus fields_<t>.vtu at each `output.times` (Fig. 4; only when it is set); a run
/// with summary.json is done.
json run_history_study(const SweepSpec& spec, const fs::path& dir, const ReproduceOptions& opt) {
  const double t0 = now_s();
  fs::create_directories(dir / "runs");
  write_file_atomically(dir / "spec.toml", spec.to_toml());
  const auto cases = spec.expand();
  const auto keys = spec.swept_keys();
  {
    std::vector<std::string> header{"case_id"};
    header.insert(header.end(), keys.begin(), keys.end());
    std::string text = csv_line(header) + "\n";
    for (const auto& c : cases) {
      std::vector<std::string> row{c.id};
      for (const auto& k : keys) row.push_back(setting_value(c.settings, k));
      text += csv_line(row) + "\n";
    }
    write_file_atomically(dir / "cases.csv", text);
  }
  std::vector<int> todo;
  for (int i = 0; i < static_cast<int>(cases.size()); ++i) {
    if (!fs::exists(dir / "runs" / cases[static_cast<std::size_t>(i)].id / "summary.json")) {
      todo.push_back(i);
    }
  }
  std::atomic<int> failed{0};
  std::atomic<int> ran{0};
  std::mutex log;
  parallel_for(todo.size(), worker_count(opt.jobs), [&](std::size_t k) {
    const auto& c = cases[static_cast<std::size_t>(todo[k])];
    if (opt.cancel && opt.cancel->load()) return;
    const fs::path run_dir = dir / "runs" / c.id;
    try {
      fem::SimulationControl control;
      control.cancel = opt.cancel;
      control.config_validated = true;  // spec.expand() validated it
      fs::create_directories(run_dir);
      if (!c.config.output.field_times.empty()) {
        // Field snapshots (Fig. 4) next to the history: runs/<case>/fields_<t>.vtu.
        control.on_fields = [&run_dir](double time, const fem::FieldSnapshot& snapshot) {
          fem::write_vtu(run_dir / fmt::format("fields_{:.6e}.vtu", time), snapshot);
        };
      }
      const fem::ImpactResult r = fem::simulate(c.config, control);
      fem::write_history_csv(r.history, run_dir / "history.csv");
      fem::write_summary_json(r, c.config, run_dir / "summary.json");  // atomic: see its doc
      ++ran;
      if (opt.progress) {
        std::lock_guard lock(log);
        std::fprintf(stderr, "corlab: %s %s: e = %.4f (%.1f s)\n", spec.name.c_str(), c.id.c_str(),
                     r.e, r.wall_s);
      }
    } catch (const std::exception& err) {
      ++failed;
      std::lock_guard lock(log);
      std::fprintf(stderr, "corlab: %s %s failed: %s\n", spec.name.c_str(), c.id.c_str(),
                   err.what());
    }
  });
  return {
      {"kind", "history"}, {"total", cases.size()},   {"already_done", cases.size() - todo.size()},
      {"ran", ran.load()}, {"failed", failed.load()}, {"wall_s", now_s() - t0}};
}

json run_sweep_study(const SweepSpec& spec, const fs::path& dir, const ReproduceOptions& opt) {
  SweepOptions so;
  so.jobs = opt.jobs;
  so.progress = opt.progress;
  so.cancel = opt.cancel;
  if (opt.error_estimate) {
    so.runner = [](const fem::ImpactConfig& config, const fem::SimulationControl& control) {
      return fem::simulate_with_error_estimate(config, control);
    };
  }
  const SweepSummary s = run_sweep(spec, dir, so);
  return {{"kind", "sweep"},    {"total", s.total},     {"already_done", s.already_done},
          {"ran", s.ran},       {"failed", s.failed},   {"not_separated", s.not_separated},
          {"wall_s", s.wall_s}, {"workers", s.workers}, {"interrupted", s.interrupted}};
}

/// Yield onset per case by elastic scaling + a confirming bracket (find_yield_onset_scaled);
/// every probe goes to probes.csv (resume).
json run_onset_study(const SweepSpec& spec, const fs::path& dir, const ReproduceOptions& opt) {
  const double t0 = now_s();
  fs::create_directories(dir);
  write_file_atomically(dir / "spec.toml", spec.to_toml());
  const auto cases = spec.expand();
  const ScaledOnsetOptions options = onset_options(opt.preset);
  const fs::path probes_file = dir / "probes.csv";
  // "onset_case", not "case_id": a case has several probe rows (read_results keeps a case_id once).
  const std::vector<std::string> header{"onset_case",    "kind", "velocity", "plastic_strain_max",
                                        "von_mises_max", "e",    "wall_s"};
  std::map<std::tuple<std::string, std::string, std::string>, OnsetProbe> cache;
  for (const auto& p : read_onset_probes(probes_file)) {
    cache[{p.first, p.second.elastic_reference ? kElasticKind : kPlasticKind,
           format_number(p.second.velocity)}] = p.second;
  }
  CsvAppender appender(probes_file, header);
  std::mutex mutex;
  std::atomic<int> ran{0};
  std::atomic<int> failed{0};
  const std::vector<std::size_t> order = onset_cases_longest_first(cases);
  parallel_for(cases.size(), worker_count(opt.jobs), [&](std::size_t i) {
    const auto& c = cases[order[i]];
    if (opt.cancel && opt.cancel->load()) return;
    try {
      KindProbeCache lookup = [&](bool elastic, double v) -> std::optional<OnsetProbe> {
        std::lock_guard lock(mutex);
        auto it = cache.find({c.id, elastic ? kElasticKind : kPlasticKind, format_number(v)});
        if (it == cache.end()) return std::nullopt;
        return it->second;
      };
      ControlledRunner runner = [&](const fem::ImpactConfig& config,
                                    fem::SimulationControl control) {
        control.cancel = opt.cancel;
        fem::ImpactResult r = fem::simulate(config, control);
        if (r.status == fem::RunStatus::kCancelled) throw std::runtime_error("interrupted");
        ++ran;
        const bool elastic = !config.substrate.material.yield_stress.has_value();
        std::lock_guard lock(mutex);
        appender.append({c.id, elastic ? kElasticKind : kPlasticKind,
                         format_number(config.impact.velocity), format_number(r.plastic_strain_max),
                         format_number(r.substrate_von_mises_max), format_number(r.e),
                         format_number(r.wall_s)});
        if (opt.progress) {
          std::fprintf(stderr,
                       "corlab: yield_onset %s %s v = %.4g m/s: eps_p,max = %.3g, "
                       "von Mises max = %.4g Pa (%.1f s)\n",
                       c.id.c_str(), elastic ? "elastic reference" : "probe",
                       config.impact.velocity, r.plastic_strain_max, r.substrate_von_mises_max,
                       r.wall_s);
        }
        return r;
      };
      find_yield_onset_scaled(c.config, options, runner, lookup);
    } catch (const std::exception& err) {
      ++failed;
      std::lock_guard lock(mutex);
      std::fprintf(stderr, "corlab: yield_onset %s failed: %s\n", c.id.c_str(), err.what());
    }
  });
  return {{"kind", "onset"},        {"total", cases.size()},
          {"ran", ran.load()},      {"failed", failed.load()},
          {"wall_s", now_s() - t0}, {"options", onset_options_json(options)}};
}

}  // namespace corlab::study::reproduce_detail
