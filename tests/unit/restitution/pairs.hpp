// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Material pairs of the seed paper (Ma et al. 2023, Table 3) for the restitution tests.
#include "corlab/materials/material_database.hpp"
#include "corlab/restitution/impact_pair.hpp"

namespace corlab::restitution::testing {

inline const Material& alumina() { return MaterialDatabase::builtin().get("alumina_ma2023"); }
inline const Material& aluminium() { return MaterialDatabase::builtin().get("aluminium_ma2023"); }
inline const Material& steel() { return MaterialDatabase::builtin().get("steel_jackson2010"); }

/// alumina sphere on aluminium alloy
inline ImpactPair alumina_on_al() { return make_impact_pair(alumina(), aluminium(), "test"); }
/// alumina sphere on steel
inline ImpactPair alumina_on_steel() { return make_impact_pair(alumina(), steel(), "test"); }

}  // namespace corlab::restitution::testing
