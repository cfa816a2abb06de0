// `corlab sweep SPEC --out DIR`: run a parametric study (one impact simulation per case), in
// parallel over all cores, or over MPI ranks when started with `mpirun -n N`.
//
// Sample runs:
//   corlab sweep studies/table2.toml --out out/table2           # all cores, progress bar
//   corlab sweep studies/table2.toml --out out/table2 --dry-run # list the cases
//   mpirun -n 8 corlab sweep studies/table2.toml --out out/table2
// Exit status: 0 all cases finished without failure, 1 some failed, 2 bad input, 128 + signal when
// interrupted (130 Ctrl-C, 143 SIGTERM, 129 SIGHUP).
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/core.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "command.hpp"
#include "corlab/core/error.hpp"
#include "corlab/core/interrupt.hpp"
#include "corlab/fem/solver/discretisation_error.hpp"
#include "corlab/fem/solver/run_cost.hpp"
#include "corlab/fem/solver/simd_level.hpp"
#include "corlab/study/progress.hpp"
#include "corlab/study/sweep.hpp"
#include "corlab/study/sweep_spec.hpp"

namespace corlab::cli {
namespace {

struct SweepArgs {
  std::string spec;
  std::string out;
  int jobs = 0;
  bool quiet = false;
  bool dry_run = false;
  bool error_estimate = false;
  bool in_order = false;
  std::string only;
  bool estimate = false;
};

// The dry run's list: case id, swept values and, with `estimate`, the estimated cost.
int list_cases(const study::SweepSpec& spec, const std::vector<std::size_t>& only, bool estimate) {
  std::vector<study::SweepCase> cases = spec.expand();
  if (!only.empty()) {
    std::vector<study::SweepCase> selected;
    selected.reserve(only.size());
    for (const std::size_t i : only) selected.push_back(cases[i]);
    cases = std::move(selected);
  }
  const auto keys = spec.swept_keys();
  fmt::print("case_id");
  if (estimate) fmt::print("  element_steps");
  for (const auto& key : keys) fmt::print("  {}", key);
  fmt::print("\n");
  double total = 0.0;
  for (const auto& run : cases) {
    fmt::print("{}", run.id);
    if (estimate) {
      const double cost = fem::estimate_run_cost(run.config).element_steps();
      total += cost;
      fmt::print("  {:.4g}", cost);
    }
    for (const auto& key : keys) {
      std::string value;
      for (const auto& [k, v] : run.settings) {
        if (k == key) value = v;
      }
      fmt::print("  {}", value);
    }
    fmt::print("\n");
  }
  std::fprintf(stderr, "corlab: sweep %s: %zu cases (dry run, nothing was run)\n",
               spec.name.c_str(), cases.size());
  if (estimate) std::fprintf(stderr, "corlab: estimated cost %.4g element-steps\n", total);
  return 0;
}

study::SweepSpec load_spec(const std::string& file) {
  try {
    return study::load_sweep_spec(file);
  } catch (const InputError&) {
    // Under mpirun every rank finds the same problem: let rank 0 alone print it.
    if (study::launched_world_rank() != 0) std::exit(2);
    throw;
  }
}

int run(const SweepArgs& args) {
  fem::simd_level();  // a bad $CORLAB_SIMD is refused before any output
  const study::SweepSpec spec = load_spec(args.spec);
  const std::vector<std::size_t> only =
      args.only.empty() ? std::vector<std::size_t>{}
                        : study::parse_case_selection(args.only, spec.run_count(), "--only");
  if (args.dry_run) return list_cases(spec, only, args.estimate);
  if (args.out.empty()) {
    throw_invalid("--out", args.out, "given (the directory for results.csv)");
  }
  if (args.jobs < 0) throw_invalid("--jobs", args.jobs, ">= 0 (0 = all cores)");
  study::SweepOptions options;
  options.jobs = args.jobs;
  options.progress = !args.quiet;
  options.spec_order = args.in_order;
  options.only = only;
  // Ctrl-C, SIGTERM or SIGHUP: stop after the running cases (their rows are written); a second
  // signal stops at once (finished rows are on disk).
  const InterruptScope interrupt;
  options.cancel = interrupt.flag();
  if (args.error_estimate) {
    options.runner = [](const fem::ImpactConfig& config, const fem::SimulationControl& control) {
      return fem::simulate_with_error_estimate(config, control);
    };
  }
  const study::SweepSummary summary = study::run_sweep(spec, args.out, options);
  const int interrupted_status = interrupt.requested() ? interrupt.exit_code() : 130;
  if (summary.rank != 0)
    return summary.interrupted ? interrupted_status : summary.failed > 0 ? 1 : 0;

  const std::string csv = (std::filesystem::path(args.out) / "results.csv").string();
  std::string where =
      summary.ranks > 1 ? fmt::format("{} MPI ranks, {} at a time", summary.ranks, summary.workers)
                        : fmt::format("{} at a time", summary.workers);
  std::fprintf(stderr,
               "corlab: sweep %s: %d ran (%d failed, %d not separated), %d already done, %d "
               "total, %s, in %s -> %s\n",
               spec.name.c_str(), summary.ran, summary.failed, summary.not_separated,
               summary.already_done, summary.total, where.c_str(),
               study::format_duration(summary.wall_s).c_str(), csv.c_str());
  if (summary.interrupted) {
    std::fprintf(stderr,
                 "corlab: interrupted: %d of %d cases remain; run the same command again to "
                 "resume (finished rows are kept in %s)\n",
                 summary.remaining(), summary.total, csv.c_str());
    return interrupted_status;
  }
  if (summary.failed > 0) {
    std::fprintf(stderr,
                 "corlab: %d cases failed (status failed, message in column error); a "
                 "rerun retries them\n",
                 summary.failed);
    return 1;
  }
  return 0;
}

const CommandRegistration kRegistration{Command{
    "sweep",
    "Run a parametric study (TOML spec) into DIR/results.csv; parallel, resumable, MPI-aware",
    [](CLI::App& sub) -> std::function<int()> {
      auto args = std::make_shared<SweepArgs>();
      sub.add_option("spec", args->spec, "study spec (TOML: [study], [base], [grid], [[cases]])")
          ->required();
      sub.add_option("--out,-o", args->out,
                     "output directory: results.csv, spec.toml (a rerun resumes)");
      sub.add_option("--jobs,-j", args->jobs,
                     "cases at a time per process (0 = all cores; under mpirun 1 per rank)");
      sub.add_flag("--quiet,-q", args->quiet, "no progress bar");
      sub.add_flag("--dry-run", args->dry_run, "list the expanded cases and exit");
      sub.add_flag("--in-order", args->in_order,
                   "run the cases in the spec's order (default: longest first); for designs "
                   "whose every prefix is balanced");
      sub.add_option("--only", args->only,
                     "only these cases: indices in the spec's order and ranges, e.g. 0-99,512");
      sub.add_flag("--estimate", args->estimate,
                   "with --dry-run: each case's estimated cost (elements x expected steps, "
                   "before subcycling and mass scaling)");
      sub.add_flag(
          "--error-estimate", args->error_estimate,
          "also run each case on coarser meshes for its error bar (e_error, e_coarse columns)");
      return [args] { return run(*args); };
    },
    40}};

}  // namespace
}  // namespace corlab::cli
