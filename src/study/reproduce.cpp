// `corlab reproduce`: studies -> fits -> fit.json (the report is made by python -m corlab.report).
#include "corlab/study/reproduce.hpp"

#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <thread>

#include "corlab/core/atomic_file.hpp"
#include "corlab/core/error.hpp"
#include "corlab/core/thread_pool.hpp"
#include "corlab/fem/discretisation_error.hpp"
#include "corlab/fem/impact_output.hpp"
#include "corlab/fem/run_cost.hpp"
#include "corlab/fem/simulate.hpp"
#include "corlab/fem/vtu_writer.hpp"
#include "corlab/materials/material.hpp"
#include "corlab/restitution/registry.hpp"
#include "corlab/study/fit_io.hpp"
#include "corlab/study/fit_paper.hpp"
#include "corlab/study/results_table.hpp"
#include "corlab/study/sweep.hpp"
#include "corlab/study/sweep_spec.hpp"
#include "corlab/study/yield_velocity.hpp"
#include "corlab/version.hpp"

namespace corlab::study {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

const std::vector<std::string> kHistoryStudies = {"verification_mesh", "verification_hertz"};
const std::vector<std::string> kSweepStudies = {"table2", "yield_velocity", "alumina", "table4"};
const std::string kOnsetStudy = "yield_onset";
/// Analytic models drawn next to the FE results (Ma et al. 2023, Figs. 11-13).
const std::vector<std::string> kCurveModels = {"ma2023", "thornton1997", "wu2003", "jg1", "jg2"};

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

fs::path studies_root(const fs::path& dir) {
  return dir.empty() ? fs::path(CORLAB_STUDIES_DIR) : dir;
}

fs::path spec_file(const fs::path& studies_dir,
                   const std::string& preset,
                   const std::string& study) {
  return studies_root(studies_dir) / preset / (study + ".toml");
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

const std::string kElasticKind = "elastic_reference";
const std::string kPlasticKind = "probe";

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

std::string setting_value(const Settings& settings, const std::string& key) {
  std::string value;
  for (const auto& [k, v] : settings) {
    if (k == key) value = v;
  }
  return value;
}

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
      fs::create_directories(run_dir);
      if (!c.config.output.field_times.empty()) {
        // Field snapshots (Fig. 4) next to the history: runs/<case>/fields_<t>.vtu.
        control.on_fields = [&run_dir](double time, const fem::FieldSnapshot& snapshot) {
          fem::write_vtu(run_dir / fmt::format("fields_{:.6e}.vtu", time), snapshot);
        };
      }
      const fem::ImpactResult r = fem::simulate(c.config, control);
      fem::write_history_csv(r.history, run_dir / "history.csv");
      const fs::path tmp = run_dir / "summary.json.tmp";
      fem::write_summary_json(r, c.config, tmp);
      fs::rename(tmp, run_dir / "summary.json");
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

/// The largest and the median discretisation-error estimate (e_error) over the compared runs,
/// overall and per study, with the run of the largest.
json discretisation_error_summary(const json& comparison) {
  std::map<std::string, std::vector<std::pair<double, const json*>>> by_study;
  for (const auto& c : comparison) {
    const double err = c.value("e_error", kNaN);
    if (!std::isfinite(err)) continue;
    by_study[c["study"].get<std::string>()].emplace_back(err, &c);
    by_study["all"].emplace_back(err, &c);
  }
  json out = json::object();
  for (auto& [study, errs] : by_study) {
    std::sort(errs.begin(), errs.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    const auto& [worst, run] = errs.back();
    out[study] = {{"count", errs.size()},
                  {"median", errs[errs.size() / 2].first},
                  {"max", worst},
                  {"max_relative", worst / (*run)["e_fe"].get<double>()},
                  {"max_case", {{"study", (*run)["study"]},
                                {"case_id", (*run)["case_id"]},
                                {"group", (*run)["group"]},
                                {"velocity", (*run)["velocity"]},
                                {"e", (*run)["e_fe"]}}}};
  }
  return out;
}

/// Case id -> config of a spec.
std::map<std::string, fem::ImpactConfig> configs_by_id(const SweepSpec& spec) {
  std::map<std::string, fem::ImpactConfig> out;
  for (const auto& c : spec.expand()) out[c.id] = c.config;
  return out;
}

json restitution_fit_or_error(const std::vector<RestitutionSample>& samples,
                              RestitutionLawFit* fit) {
  try {
    *fit = fit_restitution_law(samples);
    return to_json(*fit);
  } catch (const InputError& err) {
    return {{"error", err.what()}};
  }
}

json yield_fit_or_error(const std::vector<YieldVelocitySample>& samples, YieldVelocityFit* fit) {
  try {
    *fit = fit_yield_velocity(samples);
    json j = to_json(*fit);
    json pts = json::array();
    for (const auto& s : samples) {
      pts.push_back({{"case", s.case_id},
                     {"sphere_rho", s.sphere_rho},
                     {"E_star", s.E_star},
                     {"sigma_y", s.sigma_y},
                     {"v_y", s.v_y}});
    }
    j["samples"] = pts;
    return j;
  } catch (const InputError& err) {
    return {{"error", err.what()}};
  }
}

/// Our eq. 19: the fitted log law above our fitted power-law v_y, 1 below; clamped to [0, 1].
double our_model(const RestitutionLawFit& law,
                 const YieldVelocityFit* yv,
                 double rho,
                 double E_star,
                 double sigma_y,
                 double v) {
  // the log law, 1 below its own e = 1 crossing (for a positive slope: the clamp of the line)
  const double e = log_law_restitution(law.alpha.value, law.beta.value, law.slope.value, rho,
                                       E_star, sigma_y, v);
  if (yv == nullptr || !std::isfinite(yv->combined.value)) return e;
  const double v_y = power_law_yield_velocity(yv->combined.value, yv->n_joint.value,
                                              yv->m_joint.value, rho, E_star, sigma_y);
  return v < v_y ? 1.0 : e;
}

}  // namespace

const std::vector<std::string>& reproduce_study_names() {
  static const std::vector<std::string> names = {
      "verification_mesh", "verification_hertz", "table2", "yield_velocity", "alumina", "table4",
      "yield_onset"};
  return names;
}

json fit_outputs(const fs::path& out_dir, const fs::path& studies_dir, const std::string& preset) {
  json fits = json::object();
  auto table_of = [&](const std::string& study) -> ResultsTable {
    const fs::path csv = out_dir / study / "results.csv";
    if (!fs::exists(csv)) return {};
    return read_results(csv);
  };
  auto spec_of = [&](const std::string& study) -> std::optional<SweepSpec> {
    const fs::path file = spec_file(studies_dir, preset, study);
    if (!fs::exists(file)) return std::nullopt;
    return load_sweep_spec(file);
  };

  // forms (i)-(ii) on Table 2
  RestitutionLawFit law;
  bool have_law = false;
  {
    const auto samples = restitution_samples(table_of("table2"));
    fits["restitution_law"] = restitution_fit_or_error(samples, &law);
    have_law = !fits["restitution_law"].contains("error") && std::isfinite(law.alpha.value);
  }

  // forms (iii)-(iv): v_y from each yield-velocity case's own FE line (common slope in-study)
  YieldVelocityFit yv_fe;
  bool have_yv_fe = false;
  {
    RestitutionLawFit yl;
    const auto samples = restitution_samples(table_of("yield_velocity"));
    fits["yield_velocity_cases"] = restitution_fit_or_error(samples, &yl);
    if (!fits["yield_velocity_cases"].contains("error")) {
      std::vector<YieldVelocitySample> vs;
      for (const auto& c : yl.cases) {
        vs.push_back({c.case_id, c.sphere_rho, c.E_star, c.sigma_y, c.v_cross});
      }
      fits["yield_velocity_fe"] = yield_fit_or_error(vs, &yv_fe);
      have_yv_fe = !fits["yield_velocity_fe"].contains("error");
    }
  }

  // the paper's literal back-calculation: v_y from eq. 12 (ours, and the paper's own constants)
  // over the full (rho, E*, sigma_y) grid of the yield-velocity spec
  {
    std::set<std::tuple<double, double, double>> grid;
    if (auto spec = spec_of("yield_velocity")) {
      for (const auto& c : spec->expand()) {
        grid.insert({c.config.sphere.material.density,
                     effective_modulus(c.config.sphere.material, c.config.substrate.material),
                     c.config.substrate.material.yield_stress.value_or(kNaN)});
      }
    }
    auto back_calc = [&](double alpha, double beta, double s) {
      std::vector<YieldVelocitySample> vs;
      for (const auto& [rho, es, sy] : grid) {
        if (!std::isfinite(sy)) continue;
        vs.push_back({group_label(rho, es, sy), rho, es, sy,
                      crossing_yield_velocity(alpha, beta, s, rho, es, sy)});
      }
      return vs;
    };
    YieldVelocityFit tmp;
    fits["yield_velocity_paper_eq12"] = yield_fit_or_error(
        back_calc(PaperConstants::kAlpha, PaperConstants::kBeta, PaperConstants::kSlope), &tmp);
    if (have_law) {
      fits["yield_velocity_eq12"] =
          yield_fit_or_error(back_calc(law.alpha.value, law.beta.value, law.slope.value), &tmp);
    }
  }

  // every FE run against Ma eq. 19 (paper constants, via corlab::restitution "ma2023") and ours
  json comparison = json::array();
  json curves = json::object();
  for (const std::string study : {"table2", "yield_velocity", "alumina", "table4"}) {
    const auto spec = spec_of(study);
    const ResultsTable table = table_of(study);
    if (!spec || table.size() == 0) continue;
    const auto configs = configs_by_id(*spec);
    const ResultsTable ok = table.where("status", "ok");
    if (ok.size() == 0) continue;
    const auto& ids = ok.text("case_id");
    const auto e = ok.numbers("e");
    const auto v = ok.numbers("velocity");
    const auto e_error = ok.has_column("e_error") ? ok.numbers("e_error")
                                                  : std::vector<double>(ok.size(), kNaN);
    std::map<std::string, const fem::ImpactConfig*> groups;
    for (std::size_t i = 0; i < ok.size(); ++i) {
      const auto it = configs.find(ids[i]);
      if (it == configs.end()) continue;  // a row of an older spec
      const fem::ImpactConfig& c = it->second;
      if (!c.substrate.material.yield_stress) continue;
      const double rho = c.sphere.material.density;
      const double es = effective_modulus(c.sphere.material, c.substrate.material);
      const double sy = *c.substrate.material.yield_stress;
      const std::string group = group_label(rho, es, sy);
      groups[group] = &c;
      double e_paper = kNaN;
      try {
        e_paper =
            restitution::make_model("ma2023", c.sphere.material, c.substrate.material).cor(v[i]);
      } catch (const std::exception&) {
      }
      const double e_ours =
          have_law ? our_model(law, have_yv_fe ? &yv_fe : nullptr, rho, es, sy, v[i]) : kNaN;
      comparison.push_back({{"study", study},
                            {"case_id", ids[i]},
                            {"group", group},
                            {"sphere", c.sphere.material.name},
                            {"substrate", c.substrate.material.name},
                            {"sphere_rho", rho},
                            {"E_star", es},
                            {"sigma_y", sy},
                            {"velocity", v[i]},
                            {"e_fe", e[i]},
                            {"e_error", e_error[i]},
                            {"e_paper", e_paper},
                            {"e_ours", e_ours}});
    }
    if (study == "alumina" || study == "table4") {
      json by_group = json::object();
      for (const auto& [group, c] : groups) {
        std::vector<double> vel;
        for (int k = 0; k <= 120; ++k) vel.push_back(0.02 * std::pow(10.0, k * 3.7 / 120.0));
        json models = json::object();
        for (const auto& name : kCurveModels) {
          try {
            models[name] =
                restitution::make_model(name, c->sphere.material, c->substrate.material).cor(vel);
          } catch (const std::exception& err) {
            models[name] = {{"error", err.what()}};
          }
        }
        if (have_law) {
          const double rho = c->sphere.material.density;
          const double es = effective_modulus(c->sphere.material, c->substrate.material);
          const double sy = *c->substrate.material.yield_stress;
          std::vector<double> ours;
          for (double x : vel)
            ours.push_back(our_model(law, have_yv_fe ? &yv_fe : nullptr, rho, es, sy, x));
          models["ours"] = ours;
        }
        by_group[group] = {{"sphere", c->sphere.material.name},
                           {"substrate", c->substrate.material.name},
                           {"velocity", vel},
                           {"models", models}};
      }
      curves[study] = by_group;
    }
  }
  fits["comparison"] = comparison;
  fits["curves"] = curves;
  json titles = json::object();
  for (const auto& name : kCurveModels) {
    try {
      const auto& info = restitution::model_info(name);
      titles[name] = {{"title", info.title},
                      {"citation", info.citation},
                      {"status", std::string(restitution::to_string(info.status))}};
    } catch (const std::exception&) {
    }
  }
  fits["model_info"] = titles;
  fits["discretisation_error"] = discretisation_error_summary(comparison);

  // yield onset from the solver
  {
    json onset = json::array();
    const auto spec = spec_of(kOnsetStudy);
    const fs::path probes_file = out_dir / kOnsetStudy / "probes.csv";
    if (spec && fs::exists(probes_file)) {
      const auto all_probes = read_onset_probes(probes_file);
      const ScaledOnsetOptions options = onset_options(preset);
      for (const auto& c : spec->expand()) {
        const double sy = c.config.substrate.material.yield_stress.value_or(kNaN);
        std::vector<OnsetProbe> probes;
        double v_scaled = kNaN;  // from the last elastic reference
        for (const auto& [id, p] : all_probes) {
          if (id != c.id) continue;
          probes.push_back(p);
          probes.back().plastic = !p.elastic_reference && p.plastic_strain_max > options.threshold;
          if (p.elastic_reference) v_scaled = p.velocity * std::pow(sy / p.von_mises_max, 2.5);
        }
        double v_el = 0.0;
        double v_pl = std::numeric_limits<double>::infinity();
        for (const auto& p : probes) {
          if (p.elastic_reference) continue;
          if (p.plastic)
            v_pl = std::min(v_pl, p.velocity);
          else
            v_el = std::max(v_el, p.velocity);
        }
        const bool bracketed = v_el > 0 && std::isfinite(v_pl) && v_el < v_pl;
        const double rho = c.config.sphere.material.density;
        const double es = effective_modulus(c.config.sphere.material, c.config.substrate.material);
        json probes_json = json::array();
        for (const auto& p : probes) {
          probes_json.push_back({{"kind", p.elastic_reference ? kElasticKind : kPlasticKind},
                                 {"velocity", p.velocity},
                                 {"plastic_strain_max", p.plastic_strain_max},
                                 {"von_mises_max", p.von_mises_max}});
        }
        onset.push_back(
            {{"case_id", c.id},
             {"group", group_label(rho, es, sy)},
             {"sphere_rho", rho},
             {"E_star", es},
             {"sigma_y", sy},
             {"v_elastic", v_el},
             {"v_plastic", std::isfinite(v_pl) ? v_pl : kNaN},
             {"v_onset", bracketed ? std::sqrt(v_el * v_pl) : kNaN},
             {"v_scaled", v_scaled},
             {"bracketed", bracketed},
             {"v_hertz_onset", hertz_yield_onset_velocity(rho, es, sy)},
             {"v_y_paper_eq18",
              power_law_yield_velocity(PaperConstants::kCombined, 4.5, -3.5, rho, es, sy)},
             {"v_y_ours", have_yv_fe && std::isfinite(yv_fe.combined.value)
                              ? power_law_yield_velocity(yv_fe.combined.value, yv_fe.n_joint.value,
                                                         yv_fe.m_joint.value, rho, es, sy)
                              : kNaN},
             {"probes", probes_json}});
      }
      fits["onset_options"] = onset_options_json(options);
    }
    fits["yield_onset"] = onset;
  }
  return fits;
}

json reproduce(const ReproduceOptions& opt) {
  if (opt.preset != "paper" && opt.preset != "coarse") {
    throw_invalid("--preset", opt.preset, "paper or coarse");
  }
  if (opt.out_dir.empty()) throw_invalid("--out", "", "given (the report directory)");
  const auto& names = reproduce_study_names();
  for (const auto& name : opt.only) {
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      throw_invalid("--only", name,
                    "one of the study names (" + fmt::format("{}", fmt::join(names, ", ")) + ")");
    }
  }
  auto selected = [&](const std::string& name) {
    return opt.only.empty() || std::find(opt.only.begin(), opt.only.end(), name) != opt.only.end();
  };
  // parse every spec first: a bad spec fails before anything runs
  std::map<std::string, SweepSpec> specs;
  for (const auto& name : names) {
    if (!selected(name)) continue;
    const fs::path file = spec_file(opt.studies_dir, opt.preset, name);
    if (!fs::exists(file)) throw_invalid("study spec", file.string(), "an existing file");
    specs.emplace(name, load_sweep_spec(file));
  }
  fs::create_directories(opt.out_dir);
  const double t0 = now_s();
  json studies = json::object();
  int runs_total = 0;
  for (const auto& name : names) {
    if (!selected(name)) continue;
    if (opt.cancel && opt.cancel->load()) break;
    const SweepSpec& spec = specs.at(name);
    const fs::path dir = opt.out_dir / name;
    if (opt.progress) {
      std::fprintf(stderr, "corlab: reproduce %s: study %s (%zu runs%s)\n", opt.preset.c_str(),
                   name.c_str(), spec.run_count(),
                   name == kOnsetStudy ? " x (elastic reference + 2 bracket runs)" : "");
    }
    json s;
    if (std::find(kHistoryStudies.begin(), kHistoryStudies.end(), name) != kHistoryStudies.end()) {
      s = run_history_study(spec, dir, opt);
    } else if (name == kOnsetStudy) {
      s = run_onset_study(spec, dir, opt);
    } else {
      s = run_sweep_study(spec, dir, opt);
    }
    s["spec"] = spec_file(opt.studies_dir, opt.preset, name).string();
    s["description"] = spec.description;
    runs_total += s.value("ran", 0);
    studies[name] = s;
  }
  const double run_wall = now_s() - t0;

  json out;
  out["preset"] = opt.preset;
  out["command"] = opt.command_line;
  out["corlab_version"] = std::string(kVersion);
  out["compiler"] = fmt::format("{} {}", "gcc", __VERSION__);
  out["build_type"] =
#ifdef NDEBUG
      "Release";
#else
      "Debug";
#endif
  {
    const std::time_t t = std::time(nullptr);
    char buf[64];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
    out["date_utc"] = buf;
  }
  out["hardware_threads"] = std::thread::hardware_concurrency();
  out["jobs"] = worker_count(opt.jobs);
  out["studies"] = studies;
  out["runs_this_invocation"] = runs_total;
  out["run_wall_s"] = run_wall;
  const double tf = now_s();
  out["fits"] = fit_outputs(opt.out_dir, opt.studies_dir, opt.preset);
  out["fit_wall_s"] = now_s() - tf;
  out["paper"] = {{"slope", PaperConstants::kSlope}, {"alpha", PaperConstants::kAlpha},
                  {"beta", PaperConstants::kBeta},   {"n", PaperConstants::kExponentN},
                  {"m", PaperConstants::kExponentM}, {"c", PaperConstants::kC},
                  {"K", PaperConstants::kCombined},  {"sigma0", PaperConstants::kSigma0},
                  {"E0", PaperConstants::kE0},       {"energy_loss_5ms_J", 12.61},
                  {"hysteresis_area_5ms_J", 12.63},  {"hourglass_fraction", 0.000693}};
  write_file_atomically(opt.out_dir / "fit.json", out.dump(1));
  return out;
}

}  // namespace corlab::study
