// The one table of config keys (config_keys.hpp): it drives --help, and every key takes the text
// of its default.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/config/config_keys.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "corlab/core/units.hpp"
#include "corlab/fem/config/impact_config.hpp"

namespace corlab::fem {
namespace {

TEST(ConfigKeys, TableDrivesHelpAndCoversEveryKey) {
  const std::string help = config_keys_help();
  for (const auto& key : config_keys()) {
    EXPECT_NE(help.find(std::string(key.key)), std::string::npos) << key.key;
    EXPECT_FALSE(key.doc.empty()) << key.key;
    // Every key can be set from the text of its default.
    ImpactConfig c;
    if (key.kind == KeyKind::material || key.kind == KeyKind::path) continue;
    EXPECT_NO_THROW(set_config_key(c, key.key, config_value_text(ImpactConfig{}, key.key)))
        << key.key;
    EXPECT_NO_THROW(validate(c)) << key.key;
  }
  EXPECT_NE(help.find("solver.max_steps"), std::string::npos);
  // The defaults lie inside every range.
  EXPECT_NO_THROW(validate_key_ranges(ImpactConfig{}));
}

// impact.angle is kept in radians and written in degrees: each value reads back as it was typed
// (30, not the 30.000000000000004 that 30 x pi/180 x 180/pi gives), in the text and the echo.
TEST(ConfigKeys, AngleIsStoredInRadiansAndWrittenInDegrees) {
  for (const char* text : {"30", "7.5", "60", "62.5", "9.5", "1e-10", "89.999"}) {
    ImpactConfig c;
    set_config_key(c, "impact.angle", text);
    EXPECT_EQ(c.impact.angle.radians, std::stod(text) * units::kDegree) << text;
    EXPECT_EQ(config_value_text(c, "impact.angle"), text) << text;
    EXPECT_EQ(config_value_json(c, "impact.angle").get<double>(), std::stod(text)) << text;
  }
}

}  // namespace
}  // namespace corlab::fem
