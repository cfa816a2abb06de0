// `corlab reproduce --preset paper|coarse --out DIR [--jobs N]`: the studies of Ma et al. (2023),
// the fits of their model forms and the HTML report, end to end. Resumable: rerunning the same
// command continues where it stopped (finished runs are kept in DIR).
//
// Sample runs:
//   corlab reproduce --out out/report                 # the paper's mesh and grids (make run)
//   corlab reproduce --preset coarse --out out/demo   # a coarse demo, not the reproduction
//   corlab reproduce --out out/r --only table2 --no-report
// Exit status: 0 done, 1 some runs failed or the report failed, 2 bad input, 128 + signal when
// interrupted (130 Ctrl-C, 143 SIGTERM, 129 SIGHUP).
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/core.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "command.hpp"
#include "corlab/core/error.hpp"
#include "corlab/core/interrupt.hpp"
#include "corlab/core/process.hpp"
#include "corlab/fem/solver/simd_level.hpp"
#include "corlab/paper/reproduce.hpp"

namespace corlab::cli {
namespace {

namespace fs = std::filesystem;

struct ReproduceArgs {
  std::string preset = "paper";
  std::string out;
  int jobs = 0;
  std::vector<std::string> only;
  std::string studies;
  bool no_report = false;
  bool quiet = false;
  bool error_estimate = true;
};

/// `s` quoted for a POSIX shell, for showing command lines (nothing runs through a shell).
std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (const char c : s) {
    if (c == '\'') {
      out += "'\\''";
    } else {
      out += c;
    }
  }
  return out + "'";
}

/// The command line of this process as typed (from /proc/self/cmdline), for the report.
std::string own_command_line() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string out;
  std::string arg;
  for (const char c : all) {
    if (c == '\0') {
      out += (out.empty() ? "" : " ") +
             (arg.find_first_of(" '\"$") == std::string::npos ? arg : shell_quote(arg));
      arg.clear();
    } else {
      arg += c;
    }
  }
  return out;
}

/// The directory holding the Python package `corlab`: $CORLAB_PYTHONPATH if set; else
/// <build>/python next to <build>/bin/corlab; else, for an installed corlab, the package directory
/// next to <prefix>/bin (CORLAB_INSTALL_PYTHON_FROM_BIN, the ':'-separated candidates of the
/// install layouts in cmake/CorlabInstall.cmake: `make install` and the .deb).
fs::path python_package_dir() {
  if (const char* env = std::getenv("CORLAB_PYTHONPATH"); env != nullptr && *env != '\0') {
    return env;
  }
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  fs::path build = exe.parent_path().parent_path() / "python";
#ifdef CORLAB_INSTALL_PYTHON_FROM_BIN
  if (!fs::exists(build / "corlab" / "report.py", ec)) {
    std::string_view candidates = CORLAB_INSTALL_PYTHON_FROM_BIN;
    while (!candidates.empty()) {  // the first layout that holds the package
      const auto colon = candidates.find(':');
      fs::path installed = (exe.parent_path() / candidates.substr(0, colon)).lexically_normal();
      candidates = colon == std::string_view::npos ? "" : candidates.substr(colon + 1);
      if (fs::exists(installed / "corlab" / "report.py", ec)) return installed;
    }
  }
#endif
  return build;
}

/// Writes the report with Python; 0 when written, 1 when it failed, 128 + signal when a signal
/// stopped it (passed on to Python, which ends without a traceback; the studies are kept).
int make_report(const fs::path& out_dir, const InterruptScope& interrupt) {
  const fs::path pydir = python_package_dir();
  if (pydir.empty() || !fs::exists(pydir / "corlab" / "report.py")) {
    std::fprintf(stderr,
                 "corlab: cannot find the Python package (looked in '%s'; set "
                 "CORLAB_PYTHONPATH): no report\n",
                 pydir.string().c_str());
    return 1;
  }
  std::string pythonpath = pydir.string();
  if (const char* old = std::getenv("PYTHONPATH"); old != nullptr && *old != '\0') {
    pythonpath += ":" + std::string(old);
  }
  ::setenv("PYTHONPATH", pythonpath.c_str(), 1);
  ::setenv("MPLBACKEND", "Agg", 1);
  const std::vector<std::string> argv = {"/usr/bin/python3", "-m", "corlab.report",
                                         out_dir.string()};
  std::fprintf(stderr, "corlab: report: PYTHONPATH=%s %s -m corlab.report %s\n",
               pydir.string().c_str(), argv[0].c_str(), shell_quote(argv[3]).c_str());
  int status = 0;
  try {
    status = run_process(argv, interrupt);  // no shell: the directory name reaches Python as it is
  } catch (const std::exception& err) {
    std::fprintf(stderr, "corlab: the report failed: %s\n", err.what());
    return 1;
  }
  if (interrupt.requested()) {
    std::fprintf(stderr,
                 "corlab: interrupted (%s) while writing the report; the studies are kept, rerun "
                 "the same command to write it\n",
                 interrupt.signal_name());
    return interrupt.exit_code();
  }
  if (status != 0) {
    std::fprintf(stderr, "corlab: the report failed (%s exited with status %d)\n", argv[0].c_str(),
                 status);
    return 1;
  }
  std::fprintf(stderr, "corlab: report written to %s\n",
               (out_dir / "report.html").string().c_str());
  return 0;
}

int run(const ReproduceArgs& args) {
  if (args.jobs < 0) throw_invalid("--jobs", args.jobs, ">= 0 (0 = all cores)");
  fem::simd_level();  // a bad $CORLAB_SIMD is refused before any output
  study::ReproduceOptions options;
  options.preset = args.preset;
  options.error_estimate = args.error_estimate;
  options.out_dir = args.out;
  options.jobs = args.jobs;
  options.only = args.only;
  options.studies_dir = args.studies;
  options.progress = !args.quiet;
  const InterruptScope interrupt;  // Ctrl-C, SIGTERM, SIGHUP: stop after the running cases
  options.cancel = interrupt.flag();
  options.command_line = own_command_line();
  const nlohmann::json result = study::reproduce(options);
  if (interrupt.requested()) {
    std::fprintf(stderr, "corlab: interrupted (%s); rerun the same command to continue\n",
                 interrupt.signal_name());
    return interrupt.exit_code();
  }
  int failed = 0;
  for (const auto& [name, s] : result["studies"].items()) failed += s.value("failed", 0);
  std::fprintf(stderr,
               "corlab: studies done in %.1f s (%d runs this time, %d failed); fit.json "
               "written\n",
               result.value("run_wall_s", 0.0), result.value("runs_this_invocation", 0), failed);
  int status = failed > 0 ? 1 : 0;
  if (!args.no_report) {
    const int report = make_report(args.out, interrupt);
    if (interrupt.requested()) return report;
    if (report != 0) status = 1;
  }
  return status;
}

const CommandRegistration kRegistration{Command{
    "reproduce",
    "Reproduce Ma et al. (2023): run the studies, fit the model forms, write the HTML report",
    [](CLI::App& sub) -> std::function<int()> {
      auto args = std::make_shared<ReproduceArgs>();
      sub.add_option("--preset", args->preset,
                     "paper (default: the reproduction, the paper's mesh and grids) or coarse (a "
                     "demo and test fixture, not the reproduction)")
          ->check(CLI::IsMember({"paper", "coarse"}));
      sub.add_flag("!--no-error-estimate", args->error_estimate,
                   "skip the companion runs on coarser meshes that give each e its error bar");
      sub.add_option("--out", args->out, "output directory (resumable)")->required();
      sub.add_option("--jobs", args->jobs, "runs at the same time (0 = all cores)");
      sub.add_option("--only", args->only,
                     "run only these studies (names as in studies/<preset>/)");
      sub.add_option("--studies", args->studies,
                     "folder holding <preset>/<study>.toml (default: the installed or source "
                     "tree's studies/)");
      sub.add_flag("--no-report", args->no_report, "skip the Python report");
      sub.add_flag("--quiet", args->quiet, "no progress on stderr");
      return [args] { return run(*args); };
    },
    60}};

}  // namespace
}  // namespace corlab::cli
