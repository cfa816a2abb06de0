// `corlab dataset`: the FE restitution dataset (docs/theory/dataset.md). `design` writes its
// Sobol design as a `corlab sweep` spec; `export` turns the sweep's results into data/.
//
// Sample runs:
//   corlab dataset design --out studies/dataset/fe_restitution.toml
//   corlab dataset design --points 64            # the spec on stdout
//   corlab dataset design --box pairs --out studies/dataset/fe_restitution_pairs.toml
//   corlab sweep studies/dataset/fe_restitution.toml --out out/dataset --error-estimate
//   corlab dataset export out/dataset --out data/fe_restitution
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/core.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "command.hpp"
#include "corlab/core/error.hpp"
#include "corlab/dataset/dataset_export.hpp"
#include "corlab/dataset/dataset_spec.hpp"

namespace corlab::cli {
namespace {

struct DesignArgs {
  std::size_t points = 2048;
  std::string box = "flat";
  std::string out;
};

int run_design(const DesignArgs& args) {
  dataset::validate_design_points(args.points, "--points");
  if (args.box != "flat" && args.box != "pairs") throw_invalid("--box", args.box, "flat | pairs");
  dataset::DatasetDesign design =
      args.box == "pairs" ? dataset::pair_design() : dataset::DatasetDesign{};
  design.points = args.points;
  std::string command = "corlab dataset design";
  if (args.box != "flat") command += fmt::format(" --box {}", args.box);
  if (args.points != dataset::DatasetDesign{}.points) {
    command += fmt::format(" --points {}", args.points);
  }
  if (!args.out.empty()) command += " --out " + args.out;
  const std::string text = dataset::dataset_spec_toml(design, command);
  if (args.out.empty()) {
    fmt::print("{}", text);
    return 0;
  }
  std::ofstream out(args.out, std::ios::binary);
  if (!out) throw_invalid("--out", args.out, "a writable file");
  out << text;
  fmt::print(stderr, "corlab: wrote {} design points to {}\n", args.points, args.out);
  return 0;
}

struct ExportArgs {
  std::string sweep_dir;
  std::string out = "data/fe_restitution";
};

int run_export(const ExportArgs& args) {
  const dataset::ExportSummary s = dataset::export_dataset(args.sweep_dir, args.out);
  fmt::print("corlab: dataset {}: {} of {} design points run, {} in the fitting set", args.out,
             s.rows, s.design_points, s.included);
  for (const auto& [reason, count] : s.excluded) fmt::print(", {} excluded ({})", count, reason);
  // no e_error in any row (a sweep without --error-estimate): said so, not "median nan"
  fmt::print(
      "; {:.0f} CPU-s; {}\n", s.cpu_s,
      std::isfinite(s.e_error_median)
          ? fmt::format("e_error/e median {:.2g}, max {:.2g}", s.e_error_median, s.e_error_max)
          : std::string("no e_error (the sweep ran without --error-estimate)"));
  return 0;
}

const CommandRegistration kRegistration{Command{
    "dataset", "The FE restitution dataset: its design (a sweep spec) and its export to data/",
    [](CLI::App& sub) -> std::function<int()> {
      sub.require_subcommand(1);
      auto* design = sub.add_subcommand(
          "design", "Write the Sobol design of the dimensionless box as a `corlab sweep` spec");
      auto a = std::make_shared<DesignArgs>();
      design->add_option("--points", a->points, "Sobol points 0 .. N-1 (2^m: stratified)")
          ->capture_default_str();
      design
          ->add_option("--box", a->box,
                       "flat: sphere on a flat, equal densities (fe_restitution); pairs: "
                       "particle-particle and particle-wall, E ratio 0.05-20, density ratio "
                       "0.1-10, R1/R2 0-1 (fe_restitution_pairs)")
          ->capture_default_str();
      design->add_option("--out", a->out, "spec file to write (default: stdout)");
      auto* exporter = sub.add_subcommand(
          "export",
          "Write data/ (dataset.csv, columns.json, configs.jsonl, summary.json) from a "
          "dataset sweep's results");
      auto x = std::make_shared<ExportArgs>();
      exporter->add_option("SWEEP_DIR", x->sweep_dir, "the sweep's --out (results.csv, spec.toml)")
          ->required();
      exporter->add_option("--out", x->out, "dataset directory")->capture_default_str();
      return [a, x, design]() { return design->parsed() ? run_design(*a) : run_export(*x); };
    },
    75}};

}  // namespace
}  // namespace corlab::cli
