#pragma once
/// @file kharaz2001_mbf.hpp
/// Kharaz, Gorham & Salman (2001)'s case as an input of the MBF theory (mbf_oblique.hpp), shared
/// by its tests: an alumina sphere (E 380 GPa, nu 0.23, rho 4000 kg/m^3, R 2.5 mm) on soda-lime
/// glass (E 70 GPa, nu 0.25) at 3.9 m/s with mu = 0.092 (data/kharaz2001/README.md).

#include "corlab/restitution/mbf_oblique.hpp"

namespace corlab::test {

/// The case at `angle_deg` [deg from the normal].
inline restitution::MbfImpact kharaz2001_mbf_impact(double angle_deg) {
  return {.radius = 2.5e-3,
          .density = 4000.0,
          .sphere_modulus = 380e9,
          .sphere_poisson = 0.23,
          .flat_modulus = 70e9,
          .flat_poisson = 0.25,
          .velocity = 3.9,
          .angle = angle_deg,
          .friction = 0.092};
}

}  // namespace corlab::test
