// Tests of time_step.cpp: the Hertz contact time and the measured steps-per-contact rules.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dem/time_step.hpp"

#include <gtest/gtest.h>

#include "corlab/core/error.hpp"
#include "corlab/dem/contact_laws.hpp"
#include "corlab/dem/contact_ode.hpp"

namespace corlab::dem {
namespace {

TEST(DemTimeStep, HertzContactTimeMatchesTheOde) {
  // Glass on copper, R = 2 mm, 4 m/s: the closed form against the integrated elastic impact
  // (2.9432 is the rounded 2.94328...: 3e-5 relative).
  const double k = hertz_stiffness(4.4494e10, 0.002);
  const double m = 8.3776e-5;
  const HertzLaw law{k};
  const ForceLaw f = [&law](double d, double, const ContactHistory&) { return law.force(d); };
  const double ode = simulate_impact(f, m, 4.0).contact_time;
  EXPECT_NEAR(hertz_contact_time(k, m, 4.0) / ode, 1.0, 1e-4);
  // t_c ~ v^(-1/5)
  EXPECT_NEAR(hertz_contact_time(k, m, 0.125) / hertz_contact_time(k, m, 4.0), 2.0, 1e-12);
  EXPECT_THROW(hertz_contact_time(k, m, 0.0), InputError);
}

TEST(DemTimeStep, EveryLawHasOneMeasuredRule) {
  for (const auto law :
       {CodeLaw::lammps_tsuji, CodeLaw::lammps_hook, CodeLaw::lammps_viscoelastic,
        CodeLaw::liggghts_hertz, CodeLaw::liggghts_thornton_ning, CodeLaw::yade_mindlin}) {
    const StepRule& r = step_rule(law);
    EXPECT_GE(r.steps_per_contact, 25);
    EXPECT_LE(r.measured_error, kTimeStepError) << r.name;
    // issue 41: twice the stated step holds the promise too (a margin for where contacts start)
    EXPECT_LE(r.twice_step_error, kTimeStepError) << r.name;
    EXPECT_LE(r.measured_error, r.twice_step_error) << r.name;
  }
  EXPECT_EQ(step_rules().size(), 6u);
}

}  // namespace
}  // namespace corlab::dem
