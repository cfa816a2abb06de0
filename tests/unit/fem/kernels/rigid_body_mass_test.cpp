// The rigid-body rescaling of lumped masses (rigid_body_mass.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/kernels/rigid_body_mass.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstddef>

namespace corlab::fem {
namespace {

struct Masses {
  std::array<double, 5> m{0.3, 1.1, 0.7, 2.0, 0.4};     // [kg]
  std::array<double, 5> d2{0.0, 0.25, 1.0, 2.25, 4.0};  // [m^2]
  MassMoments moments() const {
    MassMoments s;
    for (std::size_t i = 0; i < m.size(); ++i) {
      s.m0 += m[i];
      s.m2 += m[i] * d2[i];
      s.m4 += m[i] * d2[i] * d2[i];
    }
    return s;
  }
};

TEST(RigidBodyMass, RescaledMassesHaveTheTargetMassAndMomentToRoundOff) {
  const Masses lumped;
  const double mass = 4.6;    // [kg]
  const double moment = 6.1;  // [kg m^2]
  const MassRescaling r = rigid_body_rescaling(lumped.moments(), mass, moment);
  double sum = 0.0;
  double second = 0.0;
  for (std::size_t i = 0; i < lumped.m.size(); ++i) {
    const double m = lumped.m[i] * r.factor(lumped.d2[i]);
    sum += m;
    second += m * lumped.d2[i];
  }
  EXPECT_NEAR(sum, mass, 1e-14 * mass);
  EXPECT_NEAR(second, moment, 1e-14 * moment);
}

TEST(RigidBodyMass, MassesThatAlreadyMatchAreLeftAsTheyAre) {
  const Masses lumped;
  const MassMoments s = lumped.moments();
  const MassRescaling r = rigid_body_rescaling(s, s.m0, s.m2);
  EXPECT_NEAR(r.a, 1.0, 1e-14);
  EXPECT_NEAR(r.b, 0.0, 1e-14);
}

TEST(RigidBodyMass, AUniformScaleIsFoundWhenOnlyTheMassIsShort) {
  // Every mass 2 % short: the moment's target is the scaled moment, so b stays 0.
  const Masses lumped;
  const MassMoments s = lumped.moments();
  const MassRescaling r = rigid_body_rescaling(s, 1.02 * s.m0, 1.02 * s.m2);
  EXPECT_NEAR(r.a, 1.02, 1e-14);
  EXPECT_NEAR(r.b, 0.0, 1e-14);
}

TEST(RigidBodyMass, MassesAtOneDistanceOnlyGetTheirMass) {
  // A ring: the moment follows the mass, and no (a, b) can set it apart.
  const MassMoments ring{2.0, 2.0 * 0.5, 2.0 * 0.25};
  const MassRescaling r = rigid_body_rescaling(ring, 3.0, 7.0);
  EXPECT_DOUBLE_EQ(r.a, 1.5);
  EXPECT_DOUBLE_EQ(r.b, 0.0);
}

}  // namespace
}  // namespace corlab::fem
