// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dem/time_step.hpp"

#include <cmath>
#include <stdexcept>

#include "corlab/core/error.hpp"
#include "corlab/materials/material.hpp"

namespace corlab::dem {

// Measured with `python3 scripts/dem_time_step.py --corlab build/bin/corlab` (the drop tests of
// tests/verification/dem, every code, at contact time at v_max / N; Debian 12's LAMMPS 7Jan2022,
// LIGGGHTS 3.8.0, YADE 2023.02a): the smallest N of 100, 200, 400, 800, 1600 whose worst
// |e_code - e_law| is within kTimeStepError, and that error. thornton_ning switches branch at
// whole steps, so its error falls only as 1/N (8.96e-3 at 100, 1.08e-3 at 800). YADE's stays
// about 2e-4 at any N (its en mapping, measured at 0.85 and above, and the hook's table).
const std::vector<StepRule>& step_rules() {
  static const std::vector<StepRule> rules{
      {CodeLaw::lammps_tsuji, "LAMMPS hertz + damping tsuji", 100, 4.35e-4},
      {CodeLaw::lammps_hook, "LAMMPS hertz + corlab python/invoke hook", 100, 1.86e-5},
      {CodeLaw::lammps_viscoelastic, "LAMMPS hertz + damping viscoelastic", 100, 4.85e-4},
      {CodeLaw::liggghts_hertz, "LIGGGHTS model hertz", 100, 6.93e-4},
      {CodeLaw::liggghts_thornton_ning, "LIGGGHTS model thornton_ning", 1600, 5.36e-4},
      {CodeLaw::yade_mindlin, "YADE Hertz-Mindlin (en)", 100, 4.05e-4},
  };
  return rules;
}

const StepRule& step_rule(CodeLaw law) {
  for (const auto& r : step_rules()) {
    if (r.law == law) return r;
  }
  throw std::logic_error("step_rule: a CodeLaw without a measured rule");
}

double hertz_contact_time(double stiffness, double effective_mass, double velocity) {
  require_positive("stiffness", stiffness, "[N/m^1.5]");
  require_positive("effective_mass", effective_mass, "[kg]");
  require_positive("velocity", velocity, "[m/s]");
  const double delta_max =
      std::pow(5.0 * effective_mass * velocity * velocity / (4.0 * stiffness), 0.4);
  return hertz_contact_time_factor() * delta_max / velocity;
}

}  // namespace corlab::dem
