// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file sweep_spec.hpp
/// A parametric study ("sweep") read from TOML: the impact-config keys that every run shares,
/// an optional list of case tables and a cartesian grid. Runs = cases x grid.
///
///   [study]
///   name = "table2"                      # required, [A-Za-z0-9_-]
///   description = "..."
///   max_runs = 20000                     # optional; more runs than this (default 10,000, at
///                                        # most 1,000,000) is refused before anything is read
///   [base]                               # impact-config keys over the defaults
///   "mesh.h_min" = 0.5e-3
///   [grid]                               # cartesian product; each value a non-empty array
///   "sphere.rho" = [3925.0, 7850.0]
///   "impact.velocity" = [1.0, 5.0, 20.0]
///   [[cases]]                            # optional list of case tables
///   "sphere.material" = "alumina_ma2023"
///
/// Keys are the text keys of fem::ImpactConfig (see impact_config.hpp); dotted keys may be written
/// quoted ("impact.velocity") or as TOML dotted keys / sub-tables. Values are numbers, strings or
/// booleans and are handed as text to fem::apply_setting.
///
/// Precedence and order: the settings of one run are base, then its case table, then its grid
/// point (a later one replaces an earlier one with the same key). They are applied to the default
/// config with the `*.material` keys first, then the others in that order, so an explicit property
/// (e.g. "sphere.rho") always overrides the material preset it modifies.

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "corlab/fem/config/impact_config.hpp"

namespace corlab::study {

/// One key/value setting, value as text (what fem::apply_setting receives).
using Setting = std::pair<std::string, std::string>;
/// An ordered list of settings.
using Settings = std::vector<Setting>;

/// One run of a sweep.
struct SweepCase {
  /// Stable key of the run: "c" + 10 hex digits of a hash of its settings (sorted by key), so the
  /// same settings give the same id across runs, ranks and edits of the spec that add cases.
  std::string id;
  Settings settings;         ///< merged settings in the order they are applied
  fem::ImpactConfig config;  ///< defaults + settings
};

/// Largest number of runs a spec may expand to unless its [study] max_runs says more.
inline constexpr std::size_t kDefaultMaxRuns = 10'000;
/// Largest [study] max_runs: expanding and checking a million runs takes about 1 GB and a few
/// seconds (docs/user/errors.md); a larger study is split into several specs.
inline constexpr std::size_t kMaxRunsLimit = 1'000'000;

/// A parsed and validated sweep specification.
struct SweepSpec {
  std::string name;                        ///< [study] name, [A-Za-z0-9_-]+
  std::string description;                 ///< [study] description (may be empty)
  std::size_t max_runs = kDefaultMaxRuns;  ///< [study] max_runs
  Settings base;                           ///< [base]
  std::vector<Settings> cases;             ///< [[cases]]; empty = one case with no extra settings
  std::vector<std::pair<std::string, std::vector<std::string>>> grid;  ///< [grid], document order
  std::string origin;     ///< where it came from (file name), used in messages
  std::string toml_text;  ///< the source text (copied to <out>/spec.toml); empty = regenerate

  /// Every run, in order: for each case, every grid point (the last grid key varies fastest).
  /// Throws InputError if a setting is rejected by fem::apply_setting / fem::validate, or if two
  /// runs have identical settings.
  std::vector<SweepCase> expand() const;
  /// Keys that vary between runs: the keys of the case tables (first appearance) then the grid
  /// keys. These become columns of results.csv.
  std::vector<std::string> swept_keys() const;
  /// Number of runs (cases x grid points) without building the configs.
  std::size_t run_count() const;
  /// The spec as TOML (toml_text when set, else generated from the fields).
  std::string to_toml() const;
};

/// Parses and validates a spec. Every error is an InputError with one line naming the origin, the
/// key, the value and the violated constraint, e.g.
///   invalid spec table2.toml grid."impact.velocity"[2] = -1: must be > 0 [m/s]
/// Validation applies every run's settings to a config and calls fem::validate, so a bad spec
/// fails before anything runs.
SweepSpec parse_sweep_spec(std::string_view toml_text, std::string_view origin);

/// Reads and parses a spec file (origin = the path as given).
SweepSpec load_sweep_spec(const std::filesystem::path& file);

/// Applies settings in the documented order to `config`; throws InputError (from apply_setting).
void apply_settings(fem::ImpactConfig& config, const Settings& settings);

/// The case id of a list of settings (order-independent).
std::string case_id(const Settings& settings);

}  // namespace corlab::study
