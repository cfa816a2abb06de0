// Fuzz target: the impact-config readers, a TOML file (load_impact_config + validate) and the same
// text as `--set key=value` lines (apply_settings + validate); once, the special and oversized
// files the file reader refuses.
#include <sstream>
#include <vector>

#include "corlab/core/text_file.hpp"
#include "corlab/fem/config/impact_config.hpp"
#include "fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace corlab;
  static const bool special_files = [] {
    fuzz::expect_special_files_refused("config_toml", kMaxConfigFileBytes, [](const auto& path) {
      (void)fem::load_impact_config(path);
    });
    return true;
  }();
  (void)special_files;
  const auto file = fuzz::scratch_file(".toml", data, size);
  fuzz::expect_clean("config_toml", [&] { fem::validate(fem::load_impact_config(file)); });
  std::vector<std::string> items;
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  for (std::string line; std::getline(lines, line);) items.push_back(line);
  fuzz::expect_clean("config_set", [&] {
    fem::ImpactConfig config;
    fem::apply_settings(config, items, "--set");
    fem::validate(config);
  });
  return 0;
}
