// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file law_info.hpp
/// Citation and verification status of the contact laws and the published chi(e) formulas
/// (same Status scale as the CoR models, restitution/model_info.hpp).

#include <string>
#include <vector>

#include "corlab/restitution/model_info.hpp"

namespace corlab::dem {

/// Metadata of one contact law or one published damping formula.
struct LawInfo {
  std::string name;                                               ///< key, e.g. "hunt_crossley"
  std::string citation;                                           ///< author, year, journal
  std::string equation;                                           ///< the formula in plain text
  restitution::Status status = restitution::Status::kUnverified;  ///< verification status
  std::string status_note;                                        ///< which sources were compared
};

/// Every contact law and every published chi(e) formula, in a fixed order.
const std::vector<LawInfo>& law_catalog();

}  // namespace corlab::dem
