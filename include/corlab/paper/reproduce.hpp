// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file reproduce.hpp
/// The pipeline of Ma et al. (2023) end to end: run the studies of a preset (studies/<preset>/
/// *.toml), fit the paper's model forms (fit_paper.hpp), measure the yield-onset velocity with
/// the solver (yield_velocity.hpp), evaluate the analytic models, and write <out>/fit.json for
/// the report (python -m corlab.report <out>). Every stage is resumable: finished runs are kept
/// on disk and rerunning continues where it stopped.
///
/// Layout of <out>:
///   verification_mesh/, verification_hertz/   runs/<case_id>/{history.csv,summary.json}, cases.csv
///   table2/, yield_velocity/, alumina/, table4/   results.csv + spec.toml (run_sweep)
///   yield_onset/probes.csv                        every onset probe (elastic reference, bracket)
///   models/<study>.csv                            analytic model curves per case
///   fit.json                                      everything the report needs

#include <atomic>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace corlab::study {

/// Options of reproduce().
struct ReproduceOptions {
  /// "paper" (the reproduction: the paper's mesh and grids) or "coarse" (a demo and test
  /// fixture, not the reproduction); the subfolder of studies_dir
  std::string preset = "paper";
  /// Every sweep run also runs on meshes sqrt 2, 2 and 2 sqrt 2 times as coarse for its error bar
  /// (e_error, discretisation_error.hpp; +11-12 % CPU time per run).
  bool error_estimate = true;
  std::filesystem::path out_dir;              ///< output directory (created)
  std::filesystem::path studies_dir;          ///< empty = studies_directory()
  int jobs = 0;                               ///< runs at the same time; 0 = all cores
  bool progress = true;                       ///< progress on stderr
  std::string command_line;                   ///< echoed into fit.json (the report shows it)
  std::vector<std::string> only;              ///< run only these studies (empty = all)
  const std::atomic<bool>* cancel = nullptr;  ///< stop early (finished runs are kept)
};

/// Names of the studies of a preset, in run order.
const std::vector<std::string>& reproduce_study_names();

/// Runs the studies and the fits and writes <out>/fit.json, which it also returns. Throws
/// InputError for an unknown preset, a missing or bad spec, or an unusable out_dir.
nlohmann::json reproduce(const ReproduceOptions& options);

/// Recomputes the fits and model comparisons from what is in <out> (no solver runs) and
/// returns the "fits" object of fit.json (used by reproduce() and `corlab fit --paper`).
nlohmann::json fit_outputs(const std::filesystem::path& out_dir,
                           const std::filesystem::path& studies_dir,
                           const std::string& preset);

}  // namespace corlab::study
