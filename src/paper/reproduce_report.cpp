// `corlab reproduce`, the numbers of the report: every number report.html prints or a figure draws
// that is not a fit itself (the Hertz reference of the verification runs, the mesh table, the
// errors of eq. 19 per case and overall, corlab2026 against eq. 19 on Table 2, our coefficients
// against the paper's, the runs and solver time on disk, the model lines of Figs. 3 and 6-10). The
// Python report (corlab.report) only reads, formats and plots them: no formula or published
// constant lives on both sides.
// SPDX-License-Identifier: BSD-3-Clause
#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <utility>

#include "corlab/fem/mesh/contact_estimate.hpp"
#include "corlab/fit/relative_error.hpp"
#include "corlab/materials/material.hpp"
#include "corlab/paper/fit_paper.hpp"
#include "corlab/study/results_table.hpp"
#include "reproduce_internal.hpp"

namespace corlab::study::reproduce_detail {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// Points of the Hertz F(delta) line of Fig. 3 (0 to the largest FE indentation) and of the
/// power-law lines of Figs. 9-10.
constexpr int kHertzCurveSteps = 100;
constexpr int kPowerLawSteps = 50;

double number(const json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_number() ? it->get<double>() : kNaN;
}

std::optional<json> read_json(const fs::path& file) {
  if (!fs::exists(file)) return std::nullopt;
  std::ifstream in(file);
  return json::parse(in);
}

/// (case, summary.json, run folder) of every finished run of a history study, in spec order.
struct HistoryRun {
  SweepCase c;
  json summary;
  fs::path dir;
};

std::vector<HistoryRun> history_runs(const fs::path& out_dir,
                                     const fs::path& studies_dir,
                                     const std::string& preset,
                                     const std::string& study) {
  std::vector<HistoryRun> runs;
  const fs::path file = spec_file(studies_dir, preset, study);
  if (!fs::exists(file) || !fs::exists(out_dir / study)) return runs;
  for (const auto& c : load_sweep_spec(file).expand()) {
    const fs::path dir = out_dir / study / "runs" / c.id;
    if (auto s = read_json(dir / "summary.json")) runs.push_back({c, std::move(*s), dir});
  }
  return runs;
}

/// The largest indentation of a run's history.csv [m] (NaN without one).
double largest_indentation(const fs::path& run_dir) {
  const fs::path file = run_dir / "history.csv";
  if (!fs::exists(file)) return kNaN;
  const auto d = read_results(file).numbers("indentation_m");
  return d.empty() ? kNaN : *std::max_element(d.begin(), d.end());
}

/// One verification_hertz run against the Hertz reference (elastic substrate) or against the
/// paper's energies (elastic-plastic substrate).
json hertz_run(const HistoryRun& run, const json& paper) {
  const fem::ImpactConfig& cfg = run.c.config;
  const json& s = run.summary;
  const fem::HertzReference h = fem::hertz_reference(cfg);
  const double v = cfg.impact.velocity;
  const double radius = cfg.sphere.radius;
  const double d_fe = largest_indentation(run.dir);
  json r = {{"case_id", run.c.id},
            {"elastic", !cfg.substrate.material.yield_stress.has_value()},
            {"velocity", v},
            {"e", number(s, "e")},
            {"largest_indentation_fe", d_fe},
            {"contact_radius_fe", fem::hertz_contact_radius(d_fe, radius)},
            {"hertz",
             {{"effective_modulus", h.effective_modulus},
              {"mass", h.mass},
              {"max_overlap", h.max_overlap},
              {"max_force", h.max_force},
              {"contact_radius", h.contact_radius},
              {"contact_time", h.contact_time},
              {"contact_time_factor", hertz_contact_time_factor()}}}};
  if (r["elastic"].get<bool>()) {
    r["F_max"] = number(s, "F_max");
    r["delta_max"] = number(s, "delta_max");
    r["t_contact"] = number(s, "t_contact");
    r["F_max_vs_hertz"] = number(s, "F_max") / h.max_force - 1.0;
    r["delta_max_vs_hertz"] = number(s, "delta_max") / h.max_overlap - 1.0;
    r["t_contact_vs_hertz"] = number(s, "t_contact") / h.contact_time - 1.0;
    std::vector<double> delta;
    std::vector<double> force;
    for (int k = 0; k <= kHertzCurveSteps; ++k) {
      delta.push_back(d_fe * k / kHertzCurveSteps);
      force.push_back(fem::hertz_force(delta.back(), radius, h.effective_modulus));
    }
    r["hertz_curve"] = {{"delta", delta}, {"force", force}};
    return r;
  }
  const double loss = number(s, "energy_sphere_loss");
  r["e_from_paper_energy_loss"] =
      std::sqrt(1.0 - number(paper, "energy_loss_5ms_J") / (0.5 * h.mass * v * v));
  r["energy_sphere_loss"] = loss;
  r["hysteresis_area"] = number(s, "hysteresis_area");
  r["hysteresis_vs_energy_loss"] = number(s, "hysteresis_area") / loss - 1.0;
  r["hourglass_fraction"] = number(s, "energy_hourglass") / number(s, "energy_initial");
  r["energy_balance_error"] = number(s, "energy_balance_error");
  return r;
}

/// The mesh study, coarsest first, with each e against the finest mesh's.
json mesh_runs(const std::vector<HistoryRun>& runs) {
  std::vector<const HistoryRun*> sorted;
  sorted.reserve(runs.size());
  for (const auto& r : runs) sorted.push_back(&r);
  std::stable_sort(sorted.begin(), sorted.end(), [](const HistoryRun* a, const HistoryRun* b) {
    return a->c.config.mesh.h_min > b->c.config.mesh.h_min;
  });
  json out = json::array();
  if (sorted.empty()) return out;
  const double finest = number(sorted.back()->summary, "e");
  for (const HistoryRun* r : sorted) {
    const json& s = r->summary;
    out.push_back({{"case_id", r->c.id},
                   {"h_min", r->c.config.mesh.h_min},
                   {"elements", s.value("elements", json())},
                   {"steps", s.value("steps", json())},
                   {"e", number(s, "e")},
                   {"e_minus_finest", number(s, "e") - finest},
                   {"F_max", number(s, "F_max")},
                   {"wall_s", number(s, "wall_s")}});
  }
  return out;
}

/// Relative errors (e_model - e_FE)/e_FE of one model over the compared runs
/// (relative_error_stats): per (study, group) (mean, RMS, largest with its velocity) and over all
/// runs (RMS, largest magnitude).
json model_error(const json& comparison, const char* model) {
  struct Group {
    int runs = 0;
    std::vector<double> e_model;
    std::vector<double> e_fe;
    std::vector<double> velocity;
  };
  std::map<std::pair<std::string, std::string>, Group> groups;
  std::vector<const Group*> first_seen;  // the overall numbers take the groups in this order
  for (const auto& c : comparison) {
    const double e_fe = number(c, "e_fe");
    const double e_m = number(c, model);
    if (!std::isfinite(e_fe) || !std::isfinite(e_m)) continue;
    auto [it, added] = groups.try_emplace(
        std::make_pair(c["study"].get<std::string>(), c["group"].get<std::string>()));
    if (added) first_seen.push_back(&it->second);
    Group& g = it->second;
    ++g.runs;
    g.e_model.push_back(e_m);
    g.e_fe.push_back(e_fe);
    g.velocity.push_back(number(c, "velocity"));
  }
  json per_group = json::array();
  for (const auto& [key, g] : groups) {
    const RelativeErrorStats s = relative_error_stats(g.e_model, g.e_fe);
    if (s.n == 0) continue;
    per_group.push_back({{"study", key.first},
                         {"group", key.second},
                         {"runs", g.runs},
                         {"mean_relative_error", s.bias},
                         {"rms_relative_error", s.rms},
                         {"largest_relative_error", s.worst},
                         {"largest_at_velocity", g.velocity[s.worst_index]}});
  }
  std::vector<double> e_model;
  std::vector<double> e_fe;
  for (const Group* g : first_seen) {
    e_model.insert(e_model.end(), g->e_model.begin(), g->e_model.end());
    e_fe.insert(e_fe.end(), g->e_fe.begin(), g->e_fe.end());
  }
  const RelativeErrorStats all = relative_error_stats(e_model, e_fe);
  json overall = {{"runs", all.n},
                  {"rms_relative_error", all.rms},
                  {"largest_relative_error", std::abs(all.worst)}};
  return {{"groups", per_group}, {"overall", overall}};
}

json stats_json(const RelativeErrorStats& s) {
  return {{"n", s.n}, {"rms", s.rms}, {"worst", s.worst}, {"bias", s.bias}};
}

/// corlab2026 against eq. 19 with the paper's constants (ma2023) on the Table 2 runs, both for each
/// run's own materials: their relative errors over the runs where both are defined, and in how
/// many of those corlab2026 is at least as close to the FE e.
json corlab2026_versus_eq19(const json& comparison) {
  std::vector<double> e_fe;
  std::vector<double> e_ours;
  std::vector<double> e_paper;
  for (const auto& c : comparison) {
    if (c["study"] != "table2") continue;
    e_fe.push_back(number(c, "e_fe"));
    e_ours.push_back(number(c, "e_corlab2026"));
    e_paper.push_back(number(c, "e_paper"));
  }
  const std::vector<double> all_ours = relative_errors(e_ours, e_fe);
  const std::vector<double> all_paper = relative_errors(e_paper, e_fe);
  std::vector<double> ours;
  std::vector<double> paper;
  int closer = 0;
  for (std::size_t i = 0; i < all_ours.size(); ++i) {
    if (!std::isfinite(all_ours[i]) || !std::isfinite(all_paper[i])) continue;
    ours.push_back(all_ours[i]);
    paper.push_back(all_paper[i]);
    if (std::abs(all_ours[i]) <= std::abs(all_paper[i])) ++closer;
  }
  return {{"study", "table2"},
          {"cases", ours.size()},
          {"corlab2026_at_least_as_close", closer},
          {"corlab2026", stats_json(relative_error_stats(ours))},
          {"ma2023", stats_json(relative_error_stats(paper))}};
}

/// A fitted coefficient next to a published value: relative difference and whether the
/// published value lies in our 95 % interval.
json versus(const json& coefficient, double paper) {
  const double v = number(coefficient, "value");
  const double lo = number(coefficient, "ci_lower");
  const double hi = number(coefficient, "ci_upper");
  return {{"value", v},
          {"ci_lower", lo},
          {"ci_upper", hi},
          {"paper", paper},
          {"relative_difference", v / paper - 1.0},
          {"paper_in_ci", lo <= paper && paper <= hi}};
}

/// Our coefficients against the paper's (the sentences of the report's summary).
json versus_paper(const json& fits) {
  json out = json::object();
  const json law = fits.value("restitution_law", json::object());
  if (!law.contains("error") && law.contains("slope")) {
    out["slope"] = versus(law["slope"], PaperConstants::kSlope);
    out["alpha"] = versus(law["alpha"], PaperConstants::kAlpha);
    out["beta"] = versus(law["beta"], PaperConstants::kBeta);
  }
  const json y = fits.value("yield_velocity_fe", json::object());
  if (!y.contains("error") && y.contains("n")) {
    out["n"] = versus(y["n"], PaperConstants::kExponentN);
    out["m"] = versus(y["m"], PaperConstants::kExponentM);
    out["K_fixed_exponents"] = versus(y["K_fixed_exponents"], PaperConstants::kCombined);
    // K of the free one-step fit carries the unit Pa^(1-n-m): comparable only for n + m ~ 1.
    const double unit = 1.0 - number(y["n_one_step"], "value") - number(y["m_one_step"], "value");
    out["K_unit_exponent"] = unit;
    out["K_comparable"] = std::abs(unit) < 0.01;
    // v_y ~ sqrt(K) at fixed exponents: our crossing velocities relative to the paper's eq. 18.
    out["crossing_velocity_ratio"] =
        std::sqrt(number(y["K_fixed_exponents"], "value") / PaperConstants::kCombined);
  }
  return out;
}

/// n + 1 points from a to b, evenly spaced.
std::vector<double> span(double a, double b, int n) {
  std::vector<double> out;
  for (int k = 0; k <= n; ++k) out.push_back(a + (b - a) * k / n);
  return out;
}

/// Figs. 6-7: the lines e = a_i + s ln k1 over each Table 2 case's ln k1 range (clamped at 1), and
/// each plastic point's eq. 9 value next to its FE value.
json restitution_lines(const json& law, const json& comparison) {
  std::map<std::string, double> intercept;
  for (const auto& c : law["cases"]) {
    intercept[c["case"].get<std::string>()] = number(c["a"], "value");
  }
  const double s = number(law["slope"], "value");
  std::map<std::string, std::pair<double, double>> range;  // ln k1 of each group's points
  json fe = json::array();
  json eq9 = json::array();
  for (const auto& c : comparison) {
    if (c["study"] != "table2") continue;
    const double x =
        std::log(k1(number(c, "E_star"), number(c, "sphere_rho"), number(c, "velocity")));
    const auto group = c["group"].get<std::string>();
    auto [it, added] = range.try_emplace(group, x, x);
    it->second = {std::min(it->second.first, x), std::max(it->second.second, x)};
    const auto a = intercept.find(group);
    // The plastic points, as form (i) uses them (PaperFitOptions::plastic_tolerance).
    if (a != intercept.end() && number(c, "e_fe") < 1.0 - PaperFitOptions{}.plastic_tolerance) {
      fe.push_back(number(c, "e_fe"));
      eq9.push_back(a->second + s * x);
    }
  }
  json lines = json::object();
  for (const auto& [group, r] : range) {
    const auto a = intercept.find(group);
    if (a == intercept.end()) continue;
    lines[group] = {
        {"ln_k1", {r.first, r.second}},
        {"e", {std::min(1.0, a->second + s * r.first), std::min(1.0, a->second + s * r.second)}}};
  }
  json ln_k2 = json::array();
  for (const auto& c : law["cases"]) ln_k2.push_back(std::log(number(c, "k2")));
  json fig8 = json::object();
  if (!ln_k2.empty()) {
    const auto [lo, hi] = std::minmax_element(ln_k2.begin(), ln_k2.end());
    const std::vector<double> x = {lo->get<double>() - 0.1, hi->get<double>() + 0.1};
    const double alpha = number(law["alpha"], "value");
    const double beta = number(law["beta"], "value");
    fig8 = {{"ln_k2", x},
            {"ours", {alpha + beta * x[0], alpha + beta * x[1]}},
            {"paper",
             {PaperConstants::kAlpha + PaperConstants::kBeta * x[0],
              PaperConstants::kAlpha + PaperConstants::kBeta * x[1]}}};
  }
  return {{"fig6", lines}, {"fig7", {{"e_fe", fe}, {"e_eq9", eq9}}}, {"fig8", fig8}};
}

/// b = c (E*/E0)^m (form (iv)) [Pa].
double b_of(double c, double m, double E_star) {
  return c * std::pow(E_star / PaperConstants::kE0, m);
}

/// Figs. 9-10: rho v_y^2 = b (sigma_y/sigma0)^n per E* group over its sigma_y range, ours and the
/// paper's, and b(E*) over the groups' E* range.
json yield_lines(const json& y) {
  const double n = number(y["n"], "value");
  const double c = number(y["c"], "value");
  const double m = number(y["m"], "value");
  const double n_p = PaperConstants::kExponentN;
  json fig9 = json::array();
  std::vector<double> e_stars;
  for (const auto& g : y["groups"]) {
    const double es = number(g, "E_star");
    e_stars.push_back(es);
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (const auto& s : y["samples"]) {
      if (number(s, "E_star") != es) continue;
      lo = std::min(lo, number(s, "sigma_y"));
      hi = std::max(hi, number(s, "sigma_y"));
    }
    if (lo > hi) continue;
    const std::vector<double> sigma = span(lo, hi, kPowerLawSteps);
    std::vector<double> ours;
    std::vector<double> paper;
    for (const double sy : sigma) {
      const double bar = sy / PaperConstants::kSigma0;
      ours.push_back(number(g["b"], "value") * std::pow(bar, n));
      paper.push_back(b_of(PaperConstants::kC, PaperConstants::kExponentM, es) *
                      std::pow(bar, n_p));
    }
    fig9.push_back({{"E_star", es}, {"sigma_y", sigma}, {"ours", ours}, {"paper", paper}});
  }
  json fig10 = json::object();
  if (!e_stars.empty()) {
    const auto [lo, hi] = std::minmax_element(e_stars.begin(), e_stars.end());
    const std::vector<double> grid = span(*lo, *hi, kPowerLawSteps);
    std::vector<double> ours;
    std::vector<double> paper;
    for (const double es : grid) {
      ours.push_back(b_of(c, m, es));
      paper.push_back(b_of(PaperConstants::kC, PaperConstants::kExponentM, es));
    }
    fig10 = {{"E_star", grid}, {"ours", ours}, {"paper", paper}};
  }
  return {{"fig9", fig9}, {"fig10", fig10}};
}

}  // namespace

json verification_numbers(const fs::path& out_dir,
                          const fs::path& studies_dir,
                          const std::string& preset,
                          const json& paper) {
  json hertz = json::array();
  for (const auto& run : history_runs(out_dir, studies_dir, preset, "verification_hertz")) {
    hertz.push_back(hertz_run(run, paper));
  }
  return {{"hertz", hertz},
          {"mesh", mesh_runs(history_runs(out_dir, studies_dir, preset, "verification_mesh"))}};
}

void add_comparison_numbers(json& fits) {
  const json comparison = fits.value("comparison", json::array());
  fits["model_error"] = {{"e_paper", model_error(comparison, "e_paper")},
                         {"e_ours", model_error(comparison, "e_ours")}};
  fits["corlab2026_versus_eq19"] = corlab2026_versus_eq19(comparison);
  fits["versus_paper"] = versus_paper(fits);
}

json figure_lines(const json& fits) {
  json out = json::object();
  const json law = fits.value("restitution_law", json::object());
  if (!law.contains("error") && law.contains("slope")) {
    out.update(restitution_lines(law, fits.value("comparison", json::array())));
  }
  const json y = fits.value("yield_velocity_fe", json::object());
  if (!y.contains("error") && y.contains("groups")) out.update(yield_lines(y));
  return out;
}

json disk_runs(const fs::path& out_dir, const std::string& study) {
  const fs::path dir = out_dir / study;
  std::size_t runs = 0;
  double seconds = 0.0;
  if (study == kOnsetStudy) {
    if (fs::exists(dir / "probes.csv")) {
      const ResultsTable t = read_results(dir / "probes.csv");
      runs = t.size();
      if (runs > 0) {
        for (const double s : t.numbers("wall_s")) seconds += s;
      }
    }
  } else if (fs::exists(dir / "cases.csv")) {
    const ResultsTable cases = read_results(dir / "cases.csv");
    for (const auto& id : cases.size() > 0 ? cases.text("case_id") : std::vector<std::string>{}) {
      if (auto s = read_json(dir / "runs" / id / "summary.json")) {
        ++runs;
        seconds += s->value("wall_s", 0.0);
      }
    }
  }
  if (runs == 0 && study != kOnsetStudy && fs::exists(dir / "results.csv")) {
    const ResultsTable t = read_results(dir / "results.csv");
    const auto wall = t.size() > 0 ? t.numbers("wall_s") : std::vector<double>{};
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (t.cell(i, "status") == "failed") continue;
      ++runs;
      seconds += wall[i];
    }
  }
  return {{"runs_on_disk", runs}, {"solver_s_on_disk", seconds}};
}

}  // namespace corlab::study::reproduce_detail
