// `corlab simulate`: one explicit FE impact; writes summary.json, history.csv, fields_<t>.vtu.
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/core.h>
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "command.hpp"
#include "corlab/core/error.hpp"
#include "corlab/core/interrupt.hpp"
#include "corlab/fem/config/config_keys.hpp"
#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/output/impact_output.hpp"
#include "corlab/fem/output/vtu_writer.hpp"
#include "corlab/fem/solver/discretisation_error.hpp"
#include "corlab/fem/solver/simd_level.hpp"
#include "corlab/fem/solver/simulate.hpp"
#include "corlab/study/progress.hpp"

namespace corlab::cli {
namespace {

struct SimulateOptions {
  std::string config_file;
  std::vector<std::string> settings;
  std::string out_dir;
  bool quiet = false;
  bool error_estimate = false;
};

// The 3-D model's line: e_n, e_t and omega with "+/- U" where the error estimate gave U; a normal
// impact has no e_t (no tangential velocity to restitute), said in words rather than "nan".
void print_oblique_result(const fem::ImpactResult& result) {
  auto bar = [](double u) { return std::isfinite(u) ? fmt::format(" +/- {:.2g}", u) : ""; };
  const std::string e_t = std::isfinite(result.e_t)
                              ? fmt::format("{:.4f}{}", result.e_t, bar(result.e_t_error))
                              : std::string("none (normal impact)");
  fmt::print(
      "3-D model: e_n = {:.4f}  e_t = {}  omega = {:.5g}{} rad/s  rebound_angle = {:.3f} "
      "deg  energy_friction = {:.4g} J\n",
      result.e_n, e_t, result.omega, bar(result.omega_error), result.rebound_angle,
      result.energy_friction);
}

int run_simulate(const SimulateOptions& opt) {
  fem::ImpactConfig config;
  if (!opt.config_file.empty()) config = fem::load_impact_config(opt.config_file);
  fem::apply_settings(config, opt.settings, "--set");
  fem::validate(config);
  fem::simd_level();  // a bad $CORLAB_SIMD is refused before any output
  const std::filesystem::path out(opt.out_dir);
  std::error_code ec;
  std::filesystem::create_directories(out, ec);
  if (ec) throw_invalid("--out", opt.out_dir, "a writable directory");

  fem::SimulationControl control;
  control.config_validated = true;  // above, before the output directory is made
  const InterruptScope interrupt;   // Ctrl-C, SIGTERM, SIGHUP: the solver polls the flag
  control.cancel = interrupt.flag();
  if (!opt.quiet) {
    // Silent once interrupted: the solver's last call (fraction 1) would print "100.0 %" before
    // "interrupted".
    control.progress = [print = study::fraction_progress(stderr, "corlab simulate"),
                        &interrupt](double fraction) {
      if (!interrupt.requested()) print(fraction);
    };
  }
  std::vector<std::string> written;
  const auto write_fields = [&out, &written](double time, const auto& snapshot) {
    const auto file = out / fmt::format("fields_{:.6e}.vtu", time);
    fem::write_vtu(file, snapshot);
    written.push_back(file.string());
  };
  control.on_fields = write_fields;
  control.on_hex_fields = write_fields;
  const fem::ImpactResult result = opt.error_estimate
                                       ? fem::simulate_with_error_estimate(config, control)
                                       : fem::simulate(config, control);
  if (result.status == fem::RunStatus::kCancelled) {
    fmt::print(stderr, "\ncorlab simulate: interrupted ({}), nothing written\n",
               interrupt.signal_name());
    return interrupt.exit_code();
  }
  fem::write_summary_json(result, config, out / "summary.json");
  fem::write_history_csv(result.history, out / "history.csv");
  const bool clean = result.status == fem::RunStatus::kSeparated;
  if (clean && std::isfinite(result.e_error)) {
    // e at 2h only when that companion ran (the bar may come from the others alone)
    fmt::print("e = {:.4f} +/- {:.4f} (discretisation error{})\n", result.e, result.e_error,
               std::isfinite(result.e_coarse) ? fmt::format("; e at 2h = {:.4f}", result.e_coarse)
                                              : std::string());
  }
  if (result.e_impacts.size() > 1) {
    fmt::print("e of each impact (impact.repeats): {:.4f}\n", fmt::join(result.e_impacts, ", "));
  }
  if (clean) {
    fmt::print(
        "e = {:.4f}  e_energy = {:.4f}  F_max = {:.5g} N  delta_max = {:.5g} m  t_contact = {:.5g} "
        "s  energy_balance_error = {:.2e}  elements = {}  steps = {}  wall = {:.2f} s\n",
        result.e, result.e_energy, result.F_max, result.delta_max, result.t_contact,
        result.energy_balance_error, result.elements, result.steps, result.wall_s);
  } else {
    fmt::print(
        "status = {}  ({})  no restitution coefficient: the run did not end in a clean "
        "rebound\n",
        fem::to_string(result.status), result.status_detail);
  }
  if (clean && fem::uses_3d_model(config)) print_oblique_result(result);
  if (!result.suspect.empty()) {
    fmt::print(stderr, "corlab simulate: warning: suspect run: {}\n", result.suspect);
  }
  if (!result.e_error_reason.empty()) {
    fmt::print(stderr, "corlab simulate: warning: no error bar: {}\n", result.e_error_reason);
  }
  if (const std::string late = fem::unreached_output_times(config, result); !late.empty()) {
    fmt::print(stderr, "corlab simulate: warning: {}\n", late);
  }
  if (!opt.quiet) {
    fmt::print(stderr, "corlab simulate: wrote {}/summary.json, history.csv and {} field file(s)\n",
               out.string(), written.size());
  }
  // Exit 4: the run ended without a clean rebound (status in summary.json; README "Errors").
  return clean ? 0 : 4;
}

const CommandRegistration kRegistration{Command{
    "simulate", "Run one explicit FE impact (elastic sphere on elastic-plastic substrate)",
    [](CLI::App& sub) -> std::function<int()> {
      auto opt = std::make_shared<SimulateOptions>();
      sub.add_option("--config", opt->config_file,
                     "TOML case file (keys: impact_config.hpp; a pipe such as <(...) too)");
      sub.add_option("--set", opt->settings, "override one key, e.g. --set impact.velocity=2")
          ->take_all();
      sub.add_option("--out", opt->out_dir, "output directory")->required();
      sub.add_flag("--quiet", opt->quiet, "no progress on stderr");
      sub.add_flag("--error-estimate", opt->error_estimate,
                   "also run on coarser meshes (sqrt 2, 2, 2 sqrt 2 h) for the error bar of e "
                   "(e_error in summary.json)");
      sub.footer(fem::config_keys_help());
      return [opt] { return run_simulate(*opt); };
    },
    30}};

}  // namespace
}  // namespace corlab::cli
