// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file time_step.hpp
/// The time step each DEM export recommends: the shortest Hertz contact time of its pairs (at
/// v_max) over the steps per contact at which that code's law delivered e within
/// kTimeStepError of the law's exact e in drop tests (measured once per code and law:
/// scripts/dem_time_step.py; table in time_step.cpp).
#include <string_view>
#include <vector>

namespace corlab::dem {

/// A normal contact law as one DEM code runs it.
enum class CodeLaw {
  lammps_tsuji,            ///< LAMMPS pair granular hertz + damping tsuji (constant e)
  lammps_hook,             ///< LAMMPS hertz + corlab's e(v) hook (fix python/invoke or corlab/ev)
  lammps_viscoelastic,     ///< LAMMPS hertz + damping viscoelastic (no-Python e(v) fallback)
  liggghts_hertz,          ///< LIGGGHTS model hertz with coefficientRestitution
  liggghts_thornton_ning,  ///< LIGGGHTS model thornton_ning (yield ratio)
  yade_mindlin,            ///< YADE Ip2_FrictMat_FrictMat_MindlinPhys(en) (constant or hook)
};

/// |e_code - e_law| promised at the recommended step (the time-step part of the error) [-].
inline constexpr double kTimeStepError = 1e-3;

/// One measured rule: at contact_time / steps_per_contact, and at twice that step, the code's e
/// was within kTimeStepError of the law's (worst measured errors stated).
struct StepRule {
  CodeLaw law;
  std::string_view name;    ///< e.g. "LAMMPS hertz + damping tsuji"
  int steps_per_contact;    ///< contact time / recommended step [-]
  double measured_error;    ///< worst |e_code - e_law| of the drop tests at that step [-]
  double twice_step_error;  ///< the same at twice the step (steps_per_contact / 2) [-]
};

/// Every rule, one per CodeLaw.
const std::vector<StepRule>& step_rules();
/// The rule of one law.
const StepRule& step_rule(CodeLaw law);

/// Hertz contact time 2.9432 delta_max / v [s], delta_max = (5 m* v^2/(4 K))^(2/5) [m].
/// @param stiffness K [N/m^1.5]  @param effective_mass m* [kg]  @param velocity v [m/s]
double hertz_contact_time(double stiffness, double effective_mass, double velocity);

}  // namespace corlab::dem
