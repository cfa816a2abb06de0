// corlab: coefficient of restitution of elastic-plastic impacts.
// Thin CLI: parse -> options -> validate -> run -> write. No physics here.
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/core.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "command.hpp"
#include "corlab/core/error.hpp"
#include "corlab/core/text.hpp"
#include "corlab/version.hpp"

namespace corlab::cli {
std::vector<Command>& command_registry() {
  static std::vector<Command> registry;
  return registry;
}

namespace {

// Parses the command line and runs the chosen subcommand; its exit code. Bad input (ours or the
// parser's) is one line on stderr and exit 2; any other std::exception escapes to main.
int run(int argc, char** argv) {
  CLI::App app{"corlab: coefficient of restitution of elastic-plastic impacts (SI units)"};
  app.set_version_flag("--version", std::string(corlab::kVersion));
  app.require_subcommand(1);

  auto commands = command_registry();
  std::sort(commands.begin(), commands.end(),
            [](const Command& a, const Command& b) { return a.order < b.order; });
  std::function<int()> action;
  for (const auto& command : commands) {
    CLI::App* sub = app.add_subcommand(command.name, command.description);
    auto run = std::make_shared<std::function<int()>>(command.setup(*sub));
    sub->callback([run, &action] { action = *run; });
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& err) {
    return app.exit(err);
  } catch (const CLI::CallForAllHelp& err) {
    return app.exit(err);
  } catch (const CLI::CallForVersion& err) {
    return app.exit(err);
  } catch (const CLI::ParseError& err) {
    // The parser's own errors follow the same rule as ours: one line on stderr, exit 2.
    std::fprintf(stderr, "corlab: error: %s (see corlab --help)\n",
                 corlab::one_line(err.what()).c_str());
    return 2;
  } catch (const corlab::InputError& err) {
    std::fprintf(stderr, "corlab: error: %s\n", err.what());
    return 2;
  }
  try {
    return action ? action() : 0;
  } catch (const corlab::InputError& err) {
    std::fprintf(stderr, "corlab: error: %s\n", err.what());
    return 2;
  }
}

}  // namespace
}  // namespace corlab::cli

// Anything that is not bad input is an internal error: one line, exit 3 (never an abort).
int main(int argc, char** argv) {
  try {
    return corlab::cli::run(argc, argv);
  } catch (const std::exception& err) {
    std::fprintf(stderr, "corlab: internal error: %s\n", err.what());
  } catch (...) {
    std::fprintf(stderr, "corlab: internal error: unknown exception\n");
  }
  return 3;
}
