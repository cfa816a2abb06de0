// `corlab reproduce`, the fits of fit.json: the paper's forms refitted to our runs, the
// back-calculated yield velocities, every FE run against eq. 19 (the paper's and ours) with its
// error bar, the analytic model curves of Figs. 11-13 and the yield onset measured by the solver.
// Everything is recomputed from what is on disk (no solver runs).
// SPDX-License-Identifier: BSD-3-Clause
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include "corlab/core/error.hpp"
#include "corlab/materials/material.hpp"
#include "corlab/paper/fit_io.hpp"
#include "corlab/paper/fit_paper.hpp"
#include "corlab/restitution/registry.hpp"
#include "corlab/study/results_table.hpp"
#include "reproduce_internal.hpp"

namespace corlab::study {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using reproduce_detail::kElasticKind;
using reproduce_detail::kOnsetStudy;
using reproduce_detail::kPlasticKind;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Analytic models drawn next to the FE results (Ma et al. 2023, Figs. 11-13).
const std::vector<std::string> kCurveModels = {"ma2023", "thornton1997", "wu2003", "jg1", "jg2"};
/// The sweeps whose runs are compared with eq. 19; the last two also get model curves.
const std::vector<std::string> kComparedStudies = {"table2", "yield_velocity", "alumina", "table4"};

/// The results and specs of an output directory.
struct StudyFiles {
  const fs::path& out_dir;
  const fs::path& studies_dir;
  const std::string& preset;

  ResultsTable table(const std::string& study) const {
    const fs::path csv = out_dir / study / "results.csv";
    if (!fs::exists(csv)) return {};
    return read_results(csv);
  }
  std::optional<SweepSpec> spec(const std::string& study) const {
    const fs::path file = reproduce_detail::spec_file(studies_dir, preset, study);
    if (!fs::exists(file)) return std::nullopt;
    return load_sweep_spec(file);
  }
};

/// (rho [kg/m^3], E* [Pa], sigma_y [Pa]) of a config; sigma_y NaN for an elastic substrate.
struct PaperInputs {
  double rho = kNaN;
  double E_star = kNaN;
  double sigma_y = kNaN;

  explicit PaperInputs(const fem::ImpactConfig& c)
      : rho(c.sphere.material.density),
        E_star(effective_modulus(c.sphere.material, c.substrate.material)),
        sigma_y(c.substrate.material.yield_stress.value_or(kNaN)) {}
  std::string group() const { return group_label(rho, E_star, sigma_y); }
};

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
                  {"max_case",
                   {{"study", (*run)["study"]},
                    {"case_id", (*run)["case_id"]},
                    {"group", (*run)["group"]},
                    {"velocity", (*run)["velocity"]},
                    {"e", (*run)["e_fe"]}}}};
  }
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

/// Our refit of the paper's forms, used for "ours" in the comparisons.
struct OurFits {
  RestitutionLawFit law;
  bool have_law = false;
  YieldVelocityFit yield_velocity;  ///< v_y from each yield-velocity case's own FE line
  bool have_yield_velocity = false;

  /// Our eq. 19: the fitted log law above our fitted power-law v_y, 1 below; NaN without a law.
  double e(const PaperInputs& p, double v) const {
    if (!have_law) return kNaN;
    // the log law, 1 below its own e = 1 crossing (for a positive slope: the clamp of the line)
    const double e_log = log_law_restitution(law.alpha.value, law.beta.value, law.slope.value,
                                             p.rho, p.E_star, p.sigma_y, v);
    if (!have_yield_velocity || !std::isfinite(yield_velocity.combined.value)) return e_log;
    return v < v_y(p) ? 1.0 : e_log;
  }
  /// Our power-law v_y [m/s]; NaN without the fit.
  double v_y(const PaperInputs& p) const {
    if (!have_yield_velocity || !std::isfinite(yield_velocity.combined.value)) return kNaN;
    return power_law_yield_velocity(yield_velocity.combined.value, yield_velocity.n_joint.value,
                                    yield_velocity.m_joint.value, p.rho, p.E_star, p.sigma_y);
  }
};

/// Forms (i)-(ii) on Table 2, and (iii)-(iv) with v_y from each yield-velocity case's own FE line
/// (common slope in-study); writes their fit.json entries.
OurFits fit_paper_forms(const StudyFiles& files, json& fits) {
  OurFits ours;
  fits["restitution_law"] =
      restitution_fit_or_error(restitution_samples(files.table("table2")), &ours.law);
  ours.have_law = !fits["restitution_law"].contains("error") && std::isfinite(ours.law.alpha.value);

  RestitutionLawFit per_case;
  fits["yield_velocity_cases"] =
      restitution_fit_or_error(restitution_samples(files.table("yield_velocity")), &per_case);
  if (!fits["yield_velocity_cases"].contains("error")) {
    std::vector<YieldVelocitySample> samples;
    for (const auto& c : per_case.cases) {
      samples.push_back({c.case_id, c.sphere_rho, c.E_star, c.sigma_y, c.v_cross});
    }
    fits["yield_velocity_fe"] = yield_fit_or_error(samples, &ours.yield_velocity);
    ours.have_yield_velocity = !fits["yield_velocity_fe"].contains("error");
  }
  return ours;
}

/// The paper's literal back-calculation: v_y from eq. 12 (the paper's constants, and ours) over
/// the full (rho, E*, sigma_y) grid of the yield-velocity spec.
void fit_back_calculated_yield_velocity(const StudyFiles& files, const OurFits& ours, json& fits) {
  std::set<std::tuple<double, double, double>> grid;
  if (auto spec = files.spec("yield_velocity")) {
    for (const auto& c : spec->expand()) {
      const PaperInputs p(c.config);
      grid.insert({p.rho, p.E_star, p.sigma_y});
    }
  }
  auto back_calc = [&](double alpha, double beta, double s) {
    std::vector<YieldVelocitySample> samples;
    for (const auto& [rho, es, sy] : grid) {
      if (!std::isfinite(sy)) continue;
      samples.push_back({group_label(rho, es, sy), rho, es, sy,
                         crossing_yield_velocity(alpha, beta, s, rho, es, sy)});
    }
    return samples;
  };
  YieldVelocityFit unused;
  fits["yield_velocity_paper_eq12"] = yield_fit_or_error(
      back_calc(PaperConstants::kAlpha, PaperConstants::kBeta, PaperConstants::kSlope), &unused);
  if (ours.have_law) {
    fits["yield_velocity_eq12"] = yield_fit_or_error(
        back_calc(ours.law.alpha.value, ours.law.beta.value, ours.law.slope.value), &unused);
  }
}

/// e of a registered model (the paper's eq. 19 with its published constants: "ma2023"; corlab's
/// own: "corlab2026") for a run's own sphere and substrate, as its config has them; NaN where the
/// model refuses the case.
double registered_model_e(const std::string& model, const fem::ImpactConfig& c, double v) {
  try {
    return restitution::make_model(model, c.sphere.material, c.substrate.material).cor(v);
  } catch (const std::exception&) {
    return kNaN;
  }
}

/// One entry of "comparison" per clean run of `study` (FE e with its error bar, eq. 19 with the
/// paper's and with our constants, corlab2026); `groups` gets the config of every (rho, E*,
/// sigma_y) group.
void compare_study_runs(const std::string& study,
                        const SweepSpec& spec,
                        const ResultsTable& ok,
                        const OurFits& ours,
                        json& comparison,
                        std::map<std::string, fem::ImpactConfig>& groups) {
  std::map<std::string, fem::ImpactConfig> configs;
  for (const auto& c : spec.expand()) configs[c.id] = c.config;
  const auto& ids = ok.text("case_id");
  const auto e = ok.numbers("e");
  const auto v = ok.numbers("velocity");
  const auto e_error =
      ok.has_column("e_error") ? ok.numbers("e_error") : std::vector<double>(ok.size(), kNaN);
  for (std::size_t i = 0; i < ok.size(); ++i) {
    const auto it = configs.find(ids[i]);
    if (it == configs.end()) continue;  // a row of an older spec
    const fem::ImpactConfig& c = it->second;
    if (!c.substrate.material.yield_stress) continue;
    const PaperInputs p(c);
    groups[p.group()] = c;
    comparison.push_back({{"study", study},
                          {"case_id", ids[i]},
                          {"group", p.group()},
                          {"sphere", c.sphere.material.name},
                          {"substrate", c.substrate.material.name},
                          {"sphere_rho", p.rho},
                          {"E_star", p.E_star},
                          {"sigma_y", p.sigma_y},
                          {"velocity", v[i]},
                          {"k1", k1(p.E_star, p.rho, v[i])},
                          {"e_fe", e[i]},
                          {"e_error", e_error[i]},
                          {"e_paper", registered_model_e("ma2023", c, v[i])},
                          {"e_ours", ours.e(p, v[i])},
                          {"e_corlab2026", registered_model_e("corlab2026", c, v[i])}});
  }
}

/// The analytic models' e(v) over 0.02-100 m/s for every group (Figs. 11-13), ours included.
json model_curves(const std::map<std::string, fem::ImpactConfig>& groups, const OurFits& ours) {
  std::vector<double> velocity;
  for (int k = 0; k <= 120; ++k) velocity.push_back(0.02 * std::pow(10.0, k * 3.7 / 120.0));
  json by_group = json::object();
  for (const auto& [group, c] : groups) {
    json models = json::object();
    for (const auto& name : kCurveModels) {
      try {
        models[name] =
            restitution::make_model(name, c.sphere.material, c.substrate.material).cor(velocity);
      } catch (const std::exception& err) {
        models[name] = {{"error", err.what()}};
      }
    }
    if (ours.have_law) {
      const PaperInputs p(c);
      std::vector<double> e(velocity.size());
      std::transform(velocity.begin(), velocity.end(), e.begin(),
                     [&](double x) { return ours.e(p, x); });
      models["ours"] = e;
    }
    by_group[group] = {{"sphere", c.sphere.material.name},
                       {"substrate", c.substrate.material.name},
                       {"velocity", velocity},
                       {"models", models}};
  }
  return by_group;
}

/// Title, citation and verification status of each curve model.
json curve_model_info() {
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
  return titles;
}

/// "comparison", "curves", "model_info" and "discretisation_error" of fit.json.
void compare_runs_with_models(const StudyFiles& files, const OurFits& ours, json& fits) {
  json comparison = json::array();
  json curves = json::object();
  for (const std::string& study : kComparedStudies) {
    const auto spec = files.spec(study);
    const ResultsTable table = files.table(study);
    if (!spec || table.size() == 0) continue;
    const ResultsTable ok = table.where("status", "ok");
    if (ok.size() == 0) continue;
    std::map<std::string, fem::ImpactConfig> groups;
    compare_study_runs(study, *spec, ok, ours, comparison, groups);
    if (study == "alumina" || study == "table4") curves[study] = model_curves(groups, ours);
  }
  fits["comparison"] = comparison;
  fits["curves"] = curves;
  fits["model_info"] = curve_model_info();
  fits["discretisation_error"] = discretisation_error_summary(comparison);
}

/// The onset of one case from its probes: the highest elastic and lowest plastic probe, the
/// velocity scaled from the last elastic reference, and the published and fitted v_y.
json onset_case(const SweepCase& c,
                const std::vector<std::pair<std::string, OnsetProbe>>& all_probes,
                const ScaledOnsetOptions& options,
                const OurFits& ours) {
  const PaperInputs p(c.config);
  double v_scaled = kNaN;  // from the last elastic reference
  double v_el = 0.0;
  double v_pl = std::numeric_limits<double>::infinity();
  json probes = json::array();
  for (const auto& [id, probe] : all_probes) {
    if (id != c.id) continue;
    const bool plastic = !probe.elastic_reference && probe.plastic_strain_max > options.threshold;
    if (probe.elastic_reference) {
      v_scaled = probe.velocity * std::pow(p.sigma_y / probe.von_mises_max, 2.5);
    } else if (plastic) {
      v_pl = std::min(v_pl, probe.velocity);
    } else {
      v_el = std::max(v_el, probe.velocity);
    }
    probes.push_back({{"kind", probe.elastic_reference ? kElasticKind : kPlasticKind},
                      {"velocity", probe.velocity},
                      {"plastic_strain_max", probe.plastic_strain_max},
                      {"von_mises_max", probe.von_mises_max}});
  }
  const bool bracketed = v_el > 0 && std::isfinite(v_pl) && v_el < v_pl;
  const double v_y_paper =
      power_law_yield_velocity(PaperConstants::kCombined, PaperConstants::kExponentN,
                               PaperConstants::kExponentM, p.rho, p.E_star, p.sigma_y);
  return {{"case_id", c.id},
          {"group", p.group()},
          {"sphere_rho", p.rho},
          {"E_star", p.E_star},
          {"sigma_y", p.sigma_y},
          {"v_elastic", v_el},
          {"v_plastic", std::isfinite(v_pl) ? v_pl : kNaN},
          {"v_onset", bracketed ? std::sqrt(v_el * v_pl) : kNaN},
          {"v_scaled", v_scaled},
          {"bracketed", bracketed},
          {"v_hertz_onset", hertz_yield_onset_velocity(p.rho, p.E_star, p.sigma_y)},
          {"v_y_paper_eq18", v_y_paper},
          {"v_y_ours", ours.v_y(p)},
          {"v_y_paper_over_onset", v_y_paper / (bracketed ? std::sqrt(v_el * v_pl) : kNaN)},
          {"probes", probes}};
}

/// "yield_onset" (and "onset_options") of fit.json from yield_onset/probes.csv.
void yield_onset_results(const StudyFiles& files, const OurFits& ours, json& fits) {
  json onset = json::array();
  const auto spec = files.spec(kOnsetStudy);
  const fs::path probes_file = files.out_dir / kOnsetStudy / "probes.csv";
  if (spec && fs::exists(probes_file)) {
    const auto all_probes = reproduce_detail::read_onset_probes(probes_file);
    const ScaledOnsetOptions options = reproduce_detail::onset_options(files.preset);
    for (const auto& c : spec->expand()) onset.push_back(onset_case(c, all_probes, options, ours));
    fits["onset_options"] = reproduce_detail::onset_options_json(options);
  }
  fits["yield_onset"] = onset;
}

}  // namespace

json fit_outputs(const fs::path& out_dir, const fs::path& studies_dir, const std::string& preset) {
  const StudyFiles files{out_dir, studies_dir, preset};
  json fits = json::object();
  const OurFits ours = fit_paper_forms(files, fits);
  fit_back_calculated_yield_velocity(files, ours, fits);
  compare_runs_with_models(files, ours, fits);
  yield_onset_results(files, ours, fits);
  return fits;
}

}  // namespace corlab::study
