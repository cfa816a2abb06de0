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
#include <memory>
#include <mutex>
#include <optional>
#include <tuple>

#include "corlab/core/atomic_file.hpp"
#include "corlab/core/thread_pool.hpp"
#include "corlab/fem/output/impact_output.hpp"
#include "corlab/fem/output/vtu_writer.hpp"
#include "corlab/fem/solver/discretisation_error.hpp"
#include "corlab/fem/solver/simulate.hpp"
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

/// Case indices by decreasing a-priori cost: the onset cases cost about three loading-half runs
/// near their Hertz onset velocity each, and a low yield stress (a tiny, finely meshed, slow
/// contact) costs up to ten times more than a high one; started last on two workers, it would run
/// alone at the end.
std::vector<std::size_t> longest_first(const std::vector<double>& cost) {
  std::vector<std::size_t> order(cost.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&cost](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
  return order;
}

/// A line on stderr, above the progress line when there is one.
void say(WorkProgress* progress, const std::string& line) {
  if (progress != nullptr) {
    progress->log(line);
  } else {
    std::fprintf(stderr, "%s\n", line.c_str());
  }
}

}  // namespace

/// A study whose runs keep their time histories (Figs. 2, 3, 5): runs/<case>/{history.csv,
/// summary.json}, plus fields_<t>.vtu at each `output.times` (Fig. 4; only when it is set); a run
/// with summary.json is done.
bool is_history_study(const std::string& name) {
  return name == "verification_mesh" || name == "verification_hertz";
}

json run_history_study(const SweepSpec& spec,
                       const fs::path& dir,
                       const ReproduceOptions& opt,
                       const StudyCost& cost,
                       WorkProgress* progress) {
  const double t0 = now_s();
  fs::create_directories(dir / "runs");
  write_file_atomically(dir / "spec.toml", spec.to_toml());
  const auto& cases = cost.cases;
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
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (!cost.done[i]) todo.push_back(i);
  }
  std::atomic<int> failed{0};
  std::atomic<int> ran{0};
  parallel_for(todo.size(), worker_count(opt.jobs), [&](std::size_t k) {
    const auto& c = cases[todo[k]];
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
      if (progress != nullptr) {
        progress->log(
            fmt::format("corlab: {} {}: e = {:.4f} ({:.1f} s)", spec.name, c.id, r.e, r.wall_s));
      }
    } catch (const std::exception& err) {
      ++failed;
      say(progress, fmt::format("corlab: {} {} failed: {}", spec.name, c.id, err.what()));
    }
    if (progress != nullptr) progress->done(cost.cost[todo[k]]);
  });
  return {
      {"kind", "history"}, {"total", cases.size()},   {"already_done", cases.size() - todo.size()},
      {"ran", ran.load()}, {"failed", failed.load()}, {"wall_s", now_s() - t0}};
}

json run_sweep_study(const SweepSpec& spec,
                     const fs::path& dir,
                     const ReproduceOptions& opt,
                     const StudyCost& cost,
                     WorkProgress* progress) {
  SweepOptions so;
  so.jobs = opt.jobs;
  so.progress = opt.progress && progress == nullptr;  // one progress line: the whole reproduction
  so.cancel = opt.cancel;
  const bool estimate = opt.error_estimate;
  // The fits read e (and its error bar) only: each run ends one short window after its last
  // contact (SimulationControl::e_only), e as the full stop rule's to round-off; e_energy and the
  // final energies in results.csv are those of the shorter run (the history studies keep the
  // full rule: their energies are the report's).
  CaseRunner run = [estimate](const fem::ImpactConfig& config,
                              const fem::SimulationControl& control) {
    fem::SimulationControl e_only = control;
    e_only.e_only = true;
    return estimate ? fem::simulate_with_error_estimate(config, e_only)
                    : fem::simulate(config, e_only);
  };
  if (progress != nullptr) {
    // run_sweep hands the runner a config only: its case's cost is found by its swept values.
    auto cost_by_key = std::make_shared<std::map<std::string, double>>();
    const std::vector<std::string> keys = spec.swept_keys();
    for (std::size_t i = 0; i < cost.cases.size(); ++i) {
      (*cost_by_key)[swept_key(cost.cases[i].config, keys)] = cost.cost[i];
    }
    run = [run, cost_by_key, keys, progress](const fem::ImpactConfig& config,
                                             const fem::SimulationControl& control) {
      const auto it = cost_by_key->find(swept_key(config, keys));
      const double c = it == cost_by_key->end() ? 0.0 : it->second;
      try {
        fem::ImpactResult r = run(config, control);
        progress->done(c);
        return r;
      } catch (...) {
        progress->done(c);
        throw;
      }
    };
  }
  so.runner = run;
  const SweepSummary s = run_sweep(spec, dir, so);
  return {{"kind", "sweep"},    {"total", s.total},     {"already_done", s.already_done},
          {"ran", s.ran},       {"failed", s.failed},   {"not_separated", s.not_separated},
          {"wall_s", s.wall_s}, {"workers", s.workers}, {"interrupted", s.interrupted}};
}

/// Yield onset per case by elastic scaling + a confirming bracket (find_yield_onset_scaled);
/// every probe goes to probes.csv (resume).
json run_onset_study(const SweepSpec& spec,
                     const fs::path& dir,
                     const ReproduceOptions& opt,
                     const StudyCost& cost,
                     WorkProgress* progress) {
  const double t0 = now_s();
  fs::create_directories(dir);
  write_file_atomically(dir / "spec.toml", spec.to_toml());
  const auto& cases = cost.cases;
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
  const std::vector<std::size_t> order = longest_first(cost.cost);
  parallel_for(cases.size(), worker_count(opt.jobs), [&](std::size_t i) {
    const auto& c = cases[order[i]];
    if (opt.cancel && opt.cancel->load()) return;
    std::atomic<int> ran_here{0};  // 0: every probe was on disk already
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
        ++ran_here;
        const bool elastic = !config.substrate.material.yield_stress.has_value();
        std::lock_guard lock(mutex);
        appender.append({c.id, elastic ? kElasticKind : kPlasticKind,
                         format_number(config.impact.velocity), format_number(r.plastic_strain_max),
                         format_number(r.substrate_von_mises_max), format_number(r.e),
                         format_number(r.wall_s)});
        if (progress != nullptr) {
          progress->log(fmt::format(
              "corlab: yield_onset {} {} v = {:.4g} m/s: eps_p,max = {:.3g}, von Mises max = "
              "{:.4g} Pa ({:.1f} s)",
              c.id, elastic ? "elastic reference" : "probe", config.impact.velocity,
              r.plastic_strain_max, r.substrate_von_mises_max, r.wall_s));
        }
        return r;
      };
      find_yield_onset_scaled(c.config, options, runner, lookup);
    } catch (const std::exception& err) {
      ++failed;
      const std::lock_guard lock(mutex);
      say(progress, fmt::format("corlab: yield_onset {} failed: {}", c.id, err.what()));
    }
    if (progress != nullptr) progress->done(cost.cost[order[i]], ran_here.load() > 0);
  });
  return {{"kind", "onset"},        {"total", cases.size()},
          {"ran", ran.load()},      {"failed", failed.load()},
          {"wall_s", now_s() - t0}, {"options", onset_options_json(options)}};
}

}  // namespace corlab::study::reproduce_detail
