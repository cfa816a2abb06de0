// `corlab dataset design`: write the FE restitution dataset's design as a `corlab sweep` spec
// (docs/theory/dataset.md). Run it with `corlab sweep SPEC --out DIR --error-estimate`.
//
// Sample runs:
//   corlab dataset design --out studies/dataset/fe_restitution.toml
//   corlab dataset design --points 64            # the spec on stdout
#include <fmt/core.h>

#include <filesystem>
#include <fstream>
#include <memory>

#include "command.hpp"
#include "corlab/core/error.hpp"
#include "corlab/dataset/dataset_spec.hpp"

namespace corlab::cli {
namespace {

struct DesignArgs {
  std::size_t points = 2048;
  std::string out;
};

int run_design(const DesignArgs& args) {
  if (args.points < 1) throw_invalid("--points", static_cast<double>(args.points), ">= 1");
  dataset::DatasetDesign design;
  design.points = args.points;
  std::string command = "corlab dataset design";
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

const CommandRegistration kRegistration{Command{
    "dataset", "The FE restitution dataset: write its design as a sweep spec",
    [](CLI::App& sub) -> std::function<int()> {
      sub.require_subcommand(1);
      auto* design = sub.add_subcommand(
          "design", "Write the Sobol design of the dimensionless box as a `corlab sweep` spec");
      auto a = std::make_shared<DesignArgs>();
      design->add_option("--points", a->points, "Sobol points 0 .. N-1 (2^m: stratified)")
          ->capture_default_str();
      design->add_option("--out", a->out, "spec file to write (default: stdout)");
      return [a]() { return run_design(*a); };
    },
    75}};

}  // namespace
}  // namespace corlab::cli
