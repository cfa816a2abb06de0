// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/restitution/model_info.hpp"

#include <nlohmann/json.hpp>

namespace corlab::restitution {

std::string_view to_string(Status status) {
  switch (status) {
    case Status::kVerifiedPaper:
      return "verified-paper";
    case Status::kVerifiedSecondSource:
      return "verified-second-source";
    case Status::kVerifiedDataset:
      return "verified-dataset";
    case Status::kUnverified:
      return "unverified";
  }
  return "unverified";
}

nlohmann::json model_info_json(const ModelInfo& info) {
  nlohmann::json box = nullptr;
  if (info.calibrated) {
    box = {{"k1_min", info.calibrated->k1_min},
           {"k1_max", info.calibrated->k1_max},
           {"k2_min", info.calibrated->k2_min},
           {"k2_max", info.calibrated->k2_max}};
  }
  return {{"name", info.name},
          {"title", info.title},
          {"citation", info.citation},
          {"equation", info.equation},
          {"validity", info.validity},
          {"status", std::string(to_string(info.status))},
          {"status_note", info.status_note},
          {"clamped_by_default", info.clamped_by_default},
          {"calibrated", box},
          {"accurate_damage_number", info.accurate_damage_number
                                         ? nlohmann::json(*info.accurate_damage_number)
                                         : nlohmann::json(nullptr)}};
}

}  // namespace corlab::restitution
