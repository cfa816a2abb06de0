// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file command.hpp
/// Subcommand registry of the corlab CLI. Each subcommand lives in its own cmd_<name>.cpp and
/// registers itself with a static CommandRegistration; main.cpp knows none of them by name.

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace corlab::cli {

/// Adds the subcommand's options to `sub` and returns the action to run once parsing succeeded.
/// The action returns the process exit code; it may throw corlab::InputError for bad input.
using CommandSetup = std::function<std::function<int()>(CLI::App& sub)>;

struct Command {
  std::string name;
  std::string description;
  CommandSetup setup;
  int order = 100;  ///< position in `corlab --help`
};

std::vector<Command>& command_registry();

struct CommandRegistration {
  explicit CommandRegistration(Command command) {
    command_registry().push_back(std::move(command));
  }
};

}  // namespace corlab::cli
