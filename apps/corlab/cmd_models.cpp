// `corlab models`: list the analytic CoR models with citation, equation, validity and status.
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/core.h>

#include <nlohmann/json.hpp>

#include "command.hpp"
#include "corlab/core/error.hpp"
#include "corlab/restitution/registry.hpp"

namespace corlab::cli {
namespace {

int run_models(const std::string& format) {
  const auto& catalog = restitution::model_catalog();
  if (format == "json") {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& info : catalog) out.push_back(restitution::model_info_json(info));
    fmt::print("{}\n", out.dump(2));
    return 0;
  }
  fmt::print("{:<18} {:<24} {}\n", "name", "status", "title");
  for (const auto& info : catalog) {
    fmt::print("{:<18} {:<24} {}\n", info.name, restitution::to_string(info.status), info.title);
    fmt::print("{:<18} citation: {}\n", "", info.citation);
    fmt::print("{:<18} equation: {}\n", "", info.equation);
    fmt::print("{:<18} validity: {}\n", "", info.validity);
    fmt::print("{:<18} status:   {}\n", "", info.status_note);
  }
  return 0;
}

const CommandRegistration kRegistration{Command{
    "models", "List the analytic CoR models (citation, equation, validity, verification status)",
    [](CLI::App& sub) -> std::function<int()> {
      auto format = std::make_shared<std::string>("table");
      sub.add_option("--format", *format, "output format: table|json")
          ->check(CLI::IsMember({"table", "json"}));
      return [format] { return run_models(*format); };
    },
    20}};

}  // namespace
}  // namespace corlab::cli
