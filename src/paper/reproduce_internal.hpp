// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What reproduce.cpp (the pipeline), reproduce_studies.cpp (running the studies) and
// reproduce_fits.cpp (the fits and comparisons of fit.json) share; not a public header.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "corlab/paper/reproduce.hpp"
#include "corlab/paper/yield_velocity.hpp"
#include "corlab/study/progress.hpp"
#include "corlab/study/sweep_spec.hpp"

namespace corlab::study::reproduce_detail {

inline const std::string kOnsetStudy = "yield_onset";
/// The `kind` column of yield_onset/probes.csv.
inline const std::string kElasticKind = "elastic_reference";
inline const std::string kPlasticKind = "probe";

/// The studies that keep every run's time history (run_history_study).
bool is_history_study(const std::string& name);

/// Seconds on the steady clock [s].
double now_s();

/// <studies_dir, or the source tree's studies/ when empty>/<preset>/<study>.toml
std::filesystem::path spec_file(const std::filesystem::path& studies_dir,
                                const std::string& preset,
                                const std::string& study);

/// The scaled onset search's options for a preset, and their echo in fit.json.
ScaledOnsetOptions onset_options(const std::string& preset);
nlohmann::json onset_options_json(const ScaledOnsetOptions& options);

/// (case id, probe) of every row of a probes.csv (empty when the file does not exist).
std::vector<std::pair<std::string, OnsetProbe>> read_onset_probes(
    const std::filesystem::path& file);

/// Runs of the onset search per case (an elastic reference and a two-run bracket) and the part
/// of a full run's steps each takes (they stop at maximum compression) [-]: its cost estimate.
inline constexpr double kOnsetRunsPerCase = 3.0;
inline constexpr double kLoadingHalfFraction = 0.5;

/// The companions' cost over the run's own, sum of r^-3 over fem::kErrorBarRatios (a mesh r
/// times coarser has r^-2 the elements and takes r^-1 the steps) [-]: 0.52.
double companion_cost_factor();
/// A-priori cost of one run [element-steps] (fem::estimate_run_cost), its error-bar companions
/// (companion_cost_factor()) included when `error_estimate`; 0 for an invalid config.
double case_cost(const fem::ImpactConfig& config, bool error_estimate);
/// A-priori cost of one case of the onset search [element-steps]: kOnsetRunsPerCase runs of
/// kLoadingHalfFraction of a full run at the Hertz onset velocity.
double onset_case_cost(const fem::ImpactConfig& config);
/// The values of the swept `keys` in `config`, as one text: tells a sweep's cases apart.
std::string swept_key(const fem::ImpactConfig& config, const std::vector<std::string>& keys);

/// A study's cases (spec.expand()) with their a-priori costs [element-steps] and whether each
/// is finished on disk already (history and sweep studies; an onset case is never skipped).
struct StudyCost {
  std::vector<SweepCase> cases;
  std::vector<double> cost;
  std::vector<bool> done;
  double total() const;    ///< every case [element-steps]
  double skipped() const;  ///< the cases finished on disk [element-steps]
};
StudyCost study_cost(const std::string& name,
                     const SweepSpec& spec,
                     const std::filesystem::path& dir,
                     const ReproduceOptions& options);

/// Runs what is not yet on disk of one study into `dir` and returns its entry of fit.json's
/// "studies": a history study (runs/<case>/history.csv + summary.json), a sweep (results.csv,
/// run_sweep) or the yield-onset study (probes.csv). `cost`: study_cost() of the study;
/// `progress` (null: none) gets every finished case and the per-run lines.
nlohmann::json run_history_study(const SweepSpec& spec,
                                 const std::filesystem::path& dir,
                                 const ReproduceOptions& options,
                                 const StudyCost& cost,
                                 WorkProgress* progress);
nlohmann::json run_sweep_study(const SweepSpec& spec,
                               const std::filesystem::path& dir,
                               const ReproduceOptions& options,
                               const StudyCost& cost,
                               WorkProgress* progress);
nlohmann::json run_onset_study(const SweepSpec& spec,
                               const std::filesystem::path& dir,
                               const ReproduceOptions& options,
                               const StudyCost& cost,
                               WorkProgress* progress);

/// The numbers of the report beside the fits (reproduce_report.cpp); the Python report only
/// reads, formats and plots them.
/// fit.json's "verification": the verification_hertz runs against the Hertz reference (elastic
/// substrate) or the paper's energies (`paper`: fit.json's "paper"), and the mesh study.
nlohmann::json verification_numbers(const std::filesystem::path& out_dir,
                                    const std::filesystem::path& studies_dir,
                                    const std::string& preset,
                                    const nlohmann::json& paper);
/// Adds "model_error" (eq. 19 against the FE runs, per case and overall),
/// "corlab2026_versus_eq19" (corlab2026 against eq. 19 on the Table 2 runs) and "versus_paper" (our
/// coefficients against the published ones) to fit.json's "fits".
void add_comparison_numbers(nlohmann::json& fits);
/// fit.json's "figure_lines": the model lines of Figs. 6-10 sampled from `fits`.
nlohmann::json figure_lines(const nlohmann::json& fits);
/// Finished runs of a study on disk and their summed solver time: {"runs_on_disk",
/// "solver_s_on_disk"}.
nlohmann::json disk_runs(const std::filesystem::path& out_dir, const std::string& study);

}  // namespace corlab::study::reproduce_detail
