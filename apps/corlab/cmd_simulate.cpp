// `corlab simulate`: one explicit FE impact; writes summary.json, history.csv, fields_<t>.vtu.
#include <fmt/core.h>

#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "command.hpp"
#include "corlab/core/error.hpp"
#include "corlab/core/interrupt.hpp"
#include "corlab/fem/impact_config.hpp"
#include "corlab/fem/impact_output.hpp"
#include "corlab/fem/simulate.hpp"
#include "corlab/fem/vtu_writer.hpp"

namespace corlab::cli {
namespace {

struct SimulateOptions {
  std::string config_file;
  std::vector<std::string> settings;
  std::string out_dir;
  bool quiet = false;
};

int run_simulate(const SimulateOptions& opt) {
  fem::ImpactConfig config;
  if (!opt.config_file.empty()) config = fem::load_impact_config(opt.config_file);
  for (const auto& s : opt.settings) {
    const auto eq = s.find('=');
    if (eq == std::string::npos) throw_invalid("--set", s, "key=value");
    fem::apply_setting(config, s.substr(0, eq), s.substr(eq + 1));
  }
  fem::validate(config);
  const std::filesystem::path out(opt.out_dir);
  std::error_code ec;
  std::filesystem::create_directories(out, ec);
  if (ec) throw_invalid("--out", opt.out_dir, "a writable directory");

  fem::SimulationControl control;
  const InterruptScope interrupt;  // Ctrl-C, SIGTERM, SIGHUP: the solver polls the flag
  control.cancel = interrupt.flag();
  auto last = std::chrono::steady_clock::now();
  if (!opt.quiet) {
    control.progress = [&last](double fraction) {
      const auto now = std::chrono::steady_clock::now();
      if (fraction < 1.0 && now - last < std::chrono::milliseconds(500)) return;
      last = now;
      fmt::print(stderr, "\rcorlab simulate: {:5.1f} %", 100.0 * fraction);
      if (fraction >= 1.0) fmt::print(stderr, "\n");
    };
  }
  std::vector<std::string> written;
  control.on_fields = [&out, &written](double time, const fem::FieldSnapshot& snapshot) {
    const auto file = out / fmt::format("fields_{:.6e}.vtu", time);
    fem::write_vtu(file, snapshot);
    written.push_back(file.string());
  };
  fem::ImpactResult result;
  try {
    result = fem::simulate(config, control);
  } catch (const std::runtime_error& err) {
    if (interrupt.requested()) {
      fmt::print(stderr, "\ncorlab simulate: interrupted ({}), nothing written\n",
                 interrupt.signal_name());
      return interrupt.exit_code();
    }
    throw;
  }
  fem::write_summary_json(result, config, out / "summary.json");
  fem::write_history_csv(result.history, out / "history.csv");
  if (!result.separated) {
    fmt::print(stderr,
               "corlab simulate: warning: the sphere did not separate before t_max = {} s\n",
               result.end_time);
  }
  fmt::print(
      "e = {:.4f}  e_energy = {:.4f}  F_max = {:.5g} N  delta_max = {:.5g} m  t_contact = {:.5g} s "
      " "
      "energy_balance_error = {:.2e}  elements = {}  steps = {}  wall = {:.2f} s\n",
      result.e, result.e_energy, result.force_max, result.indentation_max, result.contact_time,
      result.energy_balance_error, result.elements, result.steps, result.wall_s);
  if (!opt.quiet) {
    fmt::print(stderr, "corlab simulate: wrote {}/summary.json, history.csv and {} field file(s)\n",
               out.string(), written.size());
  }
  return 0;
}

const CommandRegistration kRegistration{Command{
    "simulate", "Run one explicit FE impact (elastic sphere on elastic-plastic substrate)",
    [](CLI::App& sub) -> std::function<int()> {
      auto opt = std::make_shared<SimulateOptions>();
      sub.add_option("--config", opt->config_file, "TOML case file (keys: impact_config.hpp)")
          ->check(CLI::ExistingFile);
      sub.add_option("--set", opt->settings, "override one key, e.g. --set impact.velocity=2")
          ->take_all();
      sub.add_option("--out", opt->out_dir, "output directory")->required();
      sub.add_flag("--quiet", opt->quiet, "no progress on stderr");
      return [opt] { return run_simulate(*opt); };
    },
    30}};

}  // namespace
}  // namespace corlab::cli
